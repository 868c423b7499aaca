// The wiring table: each core declares its ports once (sdlqr/messages/ports.hpp) and the drivers
// route by them. The flight's cores feed each other completely; the in-process routing follows
// the declarations in the order the cores are given; a core that publishes a type it did not
// declare is refused; a port that exists only while its core says so.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sdlqr/closedloop/closed_loop.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"

namespace sdlqr {
namespace {

template <class Msg, class... Cores>
constexpr bool publishedByOneOf() {
  return (Cores::Outputs::template kHas<Msg> || ...);
}

// Every input of every flight core is some flight core's output: nothing waits on a channel
// nobody in the stack publishes.
template <class... Cores>
std::vector<std::string> inputsWithoutPublisher() {
  std::vector<std::string> missing;
  const auto check = [&](auto* core) {
    using Core = std::remove_pointer_t<decltype(core)>;
    ports::forEachInput<Core>([&](const auto& port) {
      using Msg = typename std::decay_t<decltype(port)>::Msg;
      if (!publishedByOneOf<Msg, Cores...>()) missing.emplace_back(channelOf<Msg>());
    });
  };
  (check(static_cast<Cores*>(nullptr)), ...);
  return missing;
}

TEST(Wiring, EveryInputOfTheFlightCoresHasAPublisherAmongThem) {
  const std::vector<std::string> missing =
      inputsWithoutPublisher<sim::SimCore, estimator::EstimatorCore, gains::GainsCore, controller::ControllerCore,
                             lowlevel::LowlevelCore, mission::MissionCore>();
  EXPECT_TRUE(missing.empty()) << (missing.empty() ? "" : missing.front());
  // Without the mission nobody publishes COMMAND: the check can fail.
  const std::vector<std::string> without_mission =
      inputsWithoutPublisher<sim::SimCore, estimator::EstimatorCore, gains::GainsCore, controller::ControllerCore,
                             lowlevel::LowlevelCore>();
  EXPECT_NE(std::find(without_mission.begin(), without_mission.end(), "COMMAND"), without_mission.end());
}

// Two cores that take COMMAND and say who got it; the first answers with a REFERENCE.
struct Journal {
  std::vector<std::string> lines;
};
struct Answering {
  Journal* journal;
  RejectReason onCommand(const Command& m, Outbox& out) {
    journal->lines.push_back("answering COMMAND " + std::to_string(m.seq));
    Reference r;
    r.seq = m.seq;
    out.publish(r);
    return RejectReason::kNone;
  }
  static constexpr auto inputs() { return std::tuple{ports::Input{&Answering::onCommand, 16}}; }
  using Outputs = ports::Publishes<Reference>;
};
struct Listening {
  Journal* journal;
  bool listening = true;
  RejectReason onCommand(const Command& m) {
    journal->lines.push_back("listening COMMAND " + std::to_string(m.seq));
    return RejectReason::kNone;
  }
  RejectReason onReference(const Reference& m) {
    journal->lines.push_back("listening REFERENCE " + std::to_string(m.seq));
    return RejectReason::kNone;
  }
  bool isListening() const { return listening; }
  static constexpr auto inputs() {
    return std::tuple{ports::Input{&Listening::onCommand},
                      ports::Input{&Listening::onReference}.onlyWhen(&Listening::isListening)};
  }
  using Outputs = ports::Publishes<>;
};
struct Misbehaving {
  RejectReason onCommand(const Command&, Outbox& out) {
    out.publish(GainSet{});  // not among its Outputs
    return RejectReason::kNone;
  }
  static constexpr auto inputs() { return std::tuple{ports::Input{&Misbehaving::onCommand}}; }
  using Outputs = ports::Publishes<Reference>;
};

TEST(Wiring, AMessageReachesEveryCoreWhosePortsTakeItInTheOrderTheCoresAreGiven) {
  Journal journal;
  Answering answering{&journal};
  Listening listening{&journal};
  std::vector<std::string> seen;
  auto observer = [&](const auto& m) { seen.emplace_back(channelOf<std::decay_t<decltype(m)>>()); };
  InProcessWiring<decltype(observer), Answering, Listening> wiring(observer, answering, listening);
  Command command;
  command.seq = 7;
  wiring.publish(command);
  // The answer is routed within the call that published it, before the next core's turn.
  EXPECT_EQ(journal.lines, (std::vector<std::string>{"answering COMMAND 7", "listening REFERENCE 7", "listening COMMAND 7"}));
  EXPECT_EQ(seen, (std::vector<std::string>{"COMMAND", "REFERENCE"}));
  // A port that exists only while its core says so.
  listening.listening = false;
  journal.lines.clear();
  wiring.publish(command);
  EXPECT_EQ(journal.lines, (std::vector<std::string>{"answering COMMAND 7", "listening COMMAND 7"}));
  EXPECT_TRUE(ports::takesStream<Listening>(Stream::kReference));
  EXPECT_FALSE(ports::takesStream<Answering>(Stream::kReference));
}

TEST(Wiring, ACoreThatPublishesWhatItDidNotDeclareIsRefused) {
  Misbehaving core;
  NoObserver none;
  InProcessWiring<NoObserver, Misbehaving> wiring(none, core);
  try {
    wiring.publish(Command{});
    ADD_FAILURE() << "an undeclared GAINS passed";
  } catch (const ports::UndeclaredOutput& e) {
    EXPECT_NE(std::string(e.what()).find("publishes GAINS without declaring it"), std::string::npos) << e.what();
  }
}

TEST(Wiring, TheMissionTakesEstimatesOnlyInThrowMode) {
  const std::string dir = std::string(SDLQR_SOURCE_DIR) + "/config/scenarios/";
  const auto estimatePortActive = [&](const std::string& scenario_file) {
    const mission::Scenario scenario = mission::Scenario::load(dir + scenario_file);
    const mission::MissionCore core(scenario, trajectory::TrajectoryParams{}, mission::PathLimits{}, {});
    bool active = false;
    ports::forEachInput<mission::MissionCore>([&](const auto& port) {
      if constexpr (std::is_same_v<typename std::decay_t<decltype(port)>::Msg, StateEstimate>) active = port.active(core);
    });
    return active;
  };
  EXPECT_TRUE(estimatePortActive("throw.yaml"));
  EXPECT_FALSE(estimatePortActive("hover_jumps.yaml"));
}

}  // namespace
}  // namespace sdlqr
