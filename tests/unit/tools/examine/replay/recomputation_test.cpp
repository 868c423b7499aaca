// The replay's recomputation: the estimator reproduces a closed-loop flight, a replay of a
// replay is identical bit for bit, and the pairing named in the recording decides which K a
// controller tick uses and which reference input a solve uses, whatever the arrival order.

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <stdexcept>

#include "flight_fixture.hpp"
#include "sdlqr/replay/output_comparison.hpp"

namespace sdlqr::replay {
namespace {

using test::ClosedLoopFlight;

const ClosedLoopFlight& closedLoopFlight() {
  static const ClosedLoopFlight flight = test::flyClosedLoop();
  return flight;
}

// Replay #1 of the closed-loop flight, taken as a recording of its own.
const RecordedFlight& replayedFlight() {
  static const RecordedFlight flight = [] {
    const ClosedLoopFlight& c = closedLoopFlight();
    Recomputation first(test::paramsOf(c.config), c.flight);
    first.runToEnd();
    return test::withOutputs(c.flight, first.outputs());
  }();
  return flight;
}

const ChannelComparison& channel(const Comparison& c, const std::string& name) {
  for (const ChannelComparison& ch : c.channels) {
    if (ch.channel == name) return ch;
  }
  throw std::runtime_error("no channel " + name);
}

TEST(Recomputation, EstimatorReproducesTheClosedLoopFlightBitForBit) {
  const ClosedLoopFlight& c = closedLoopFlight();
  ASSERT_GT(c.flight.imu.size(), 10000u);
  Recomputation replay(test::paramsOf(c.config), c.flight);
  replay.runToEnd();
  const Comparison comparison = compareOutputs(c.flight, replay.outputs(), 0.0);
  std::cout << formatComparison(comparison);
  const ChannelComparison& state = channel(comparison, "STATE_EST");
  EXPECT_TRUE(state.bitForBit()) << state.first_difference;
  EXPECT_EQ(state.compared, static_cast<int64_t>(c.flight.state_estimate.size()));
  // The controller flew: ticks at 100 Hz from take-off to touch-down, solves at 10 Hz.
  EXPECT_GT(replay.outputs().rate_command.size(), 900u);
  EXPECT_GT(replay.outputs().gains.size(), 100u);
}

TEST(Recomputation, ReplayOfAReplayIsIdenticalBitForBit) {
  const ClosedLoopFlight& c = closedLoopFlight();
  const RecordedFlight& recorded = replayedFlight();
  ASSERT_EQ(recorded.state_estimate.size(), c.flight.state_estimate.size());
  Recomputation second(test::paramsOf(c.config), recorded);
  second.runToEnd();
  const Comparison comparison = compareOutputs(recorded, second.outputs(), 0.0);
  std::cout << formatComparison(comparison);
  EXPECT_TRUE(comparison.bitForBit());
  for (const ChannelComparison& ch : comparison.channels) {
    EXPECT_GT(ch.compared, 0) << ch.channel;
    EXPECT_EQ(ch.identical, ch.compared) << ch.first_difference;
  }
  const PairingStats& pairing = second.pairing();
  std::cout << "[ figures  ] GAINS fed by name " << pairing.gains_from_replay << ", REFERENCE fed by name "
            << pairing.references_from_replay << ", unpaired solves " << pairing.solves_unpaired << "\n";
  EXPECT_GT(pairing.gains_from_replay, 100);
  EXPECT_EQ(pairing.gains_from_record, 0);
  EXPECT_EQ(pairing.solves_unpaired, 0);
}

// A recording whose tick k names the previous solve (the GAINS arrived just after the tick on
// the bus): the replay gives tick k that older K, not the newest one it has computed.
TEST(Recomputation, TheRecordedPairingDecidesWhichGainsATickUses) {
  const ClosedLoopFlight& c = closedLoopFlight();
  RecordedFlight recorded = replayedFlight();
  // The first tick that uses a new solve g (not the first solve).
  size_t k = 0;
  for (size_t i = 1; i < recorded.rate_command.size(); ++i) {
    const RateCommand& r = recorded.rate_command[i];
    if (r.gains_seq > 5 && r.gains_seq != recorded.rate_command[i - 1].gains_seq) {
      k = i;
      break;
    }
  }
  ASSERT_GT(k, 0u);
  const int64_t newest = recorded.rate_command[k].gains_seq;
  recorded.rate_command[k].gains_seq = newest - 1;  // the race lost: K of the solve before

  Recomputation replay(test::paramsOf(c.config), recorded);
  replay.runToEnd();
  const RateCommand& tick = replay.outputs().rate_command[k];
  ASSERT_EQ(tick.seq, recorded.rate_command[k].seq);
  EXPECT_EQ(tick.gains_seq, newest - 1);
  EXPECT_NE(tick.body_rate, recorded.rate_command[k].body_rate) << "an older K gives another command";
  // The next tick names `newest` again and gets it.
  EXPECT_EQ(replay.outputs().rate_command[k + 1].gains_seq, newest);
  const Comparison comparison = compareOutputs(recorded, replay.outputs(), 0.0);
  const ChannelComparison& rate = channel(comparison, "RATE_CMD");
  std::cout << "[ figures  ] tick " << k << " with K " << newest - 1 << " instead of " << newest << ": "
            << rate.first_difference << "\n";
  EXPECT_FALSE(rate.bitForBit());
}

TEST(Recomputation, TheRecordedPairingDecidesTheReferenceOfASolve) {
  const ClosedLoopFlight& c = closedLoopFlight();
  RecordedFlight recorded = replayedFlight();
  // A solve during the climb, where the reference input changes from tick to tick.
  size_t s = 0;
  for (size_t i = 0; i < recorded.gains.size(); ++i) {
    if (recorded.gains[i].reference_seq > 50) {
      s = i;
      break;
    }
  }
  ASSERT_GT(s, 0u);
  const int64_t named = recorded.gains[s].reference_seq;
  recorded.gains[s].reference_seq = named - 3;
  Recomputation replay(test::paramsOf(c.config), recorded);
  replay.runToEnd();
  ASSERT_GT(replay.outputs().gains.size(), s);
  EXPECT_EQ(replay.outputs().gains[s].reference_seq, named - 3);
  EXPECT_EQ(replay.outputs().gains[s].u_lin, recorded.reference[static_cast<size_t>(named - 3)].u);
}

// COMMAND races STATE_EST on the bus too: the recorder may hear the take-off after the estimate
// from which the controller already computed its first tick. The REFERENCE of that tick names
// the command (command_seq), so the replay applies it before the tick all the same.
TEST(Recomputation, ACommandTheRecorderHeardLateIsAppliedBeforeTheTickThatNamesIt) {
  const ClosedLoopFlight& c = closedLoopFlight();
  RecordedFlight recorded = replayedFlight();
  int moved = 0;
  for (size_t i = 0; i < recorded.order.size(); ++i) {
    if (recorded.order[i].kind != InputKind::kCommand) continue;
    // Three estimates later in the log than where it was heard.
    size_t j = i;
    for (int estimates = 0; j + 1 < recorded.order.size() && estimates < 3; ++j) {
      std::swap(recorded.order[j], recorded.order[j + 1]);
      if (recorded.order[j].kind == InputKind::kStateEstimate) ++estimates;
    }
    ++moved;
    i = j;
  }
  ASSERT_GE(moved, 2);
  Recomputation replay(test::paramsOf(c.config), recorded);
  replay.runToEnd();
  const Comparison comparison = compareOutputs(recorded, replay.outputs(), 0.0);
  std::cout << formatComparison(comparison);
  EXPECT_TRUE(comparison.bitForBit());
}

// Where `kind` entry `index` sits in the recorder's order.
size_t positionOf(const RecordedFlight& f, InputKind kind, size_t index) {
  for (size_t i = 0; i < f.order.size(); ++i) {
    if (f.order[i].kind == kind && static_cast<size_t>(f.order[i].index) == index) return i;
  }
  throw std::runtime_error("not in the order");
}

// The recorder heard input `index` of `kind` `estimates` recorded STATE_EST earlier than it did.
void moveBeforeEstimates(RecordedFlight& f, InputKind kind, size_t index, int estimates) {
  size_t at = positionOf(f, kind, index);
  for (int passed = 0; at > 0 && passed < estimates; --at) {
    std::swap(f.order[at], f.order[at - 1]);
    if (f.order[at].kind == InputKind::kStateEstimate) ++passed;
  }
}

void expectBitForBit(const RecordedFlight& recorded, const Recomputation& replay) {
  const Comparison comparison = compareOutputs(recorded, replay.outputs(), 0.0);
  std::cout << formatComparison(comparison);
  EXPECT_TRUE(comparison.bitForBit());
}

// The other way round: the controller heard the take-off after estimates the recorder heard it
// before. No tick names those estimates in the recording, so the replay must not tick on them
// either: the COMMAND reaches the controller's core later (seen on a busy 2-core machine: the
// first recorded tick one grid point later than the replay's). The flight: the take-off 25 ms
// later; the recording: its COMMAND heard 6 estimates (24 ms) earlier.
TEST(Recomputation, ACommandTheControllerHeardLateDoesNotMakeTheReplayTickEarlier) {
  const ClosedLoopFlight c = test::flyClosedLoop([](mission::Scenario& s) {
    for (mission::ScenarioEvent& e : s.events) {
      if (e.at == 1.0) e.at = 1.025;
    }
  });
  RecordedFlight recorded = c.flight;
  const Command& takeoff = recorded.command.at(1);
  ASSERT_GT(takeoff.utime, 1'020'000);
  moveBeforeEstimates(recorded, InputKind::kCommand, 1, 6);
  Recomputation replay(test::paramsOf(c.config), recorded);
  replay.runToEnd();
  expectBitForBit(recorded, replay);
  ASSERT_FALSE(replay.outputs().rate_command.empty());
  EXPECT_EQ(replay.outputs().rate_command.front().utime, recorded.rate_command.front().utime);
}

// TRAJECTORY races STATE_EST as COMMAND does: the recorder heard the upload 6 estimates before the
// controller did. The ticks in between track no trajectory in the recording, so the replay holds
// the upload until the tick whose REFERENCE first tracks it; delivered where the recorder heard
// it, those ticks track it early (measured with the hold taken out: 3 of 1,300 RATE_CMD and
// REFERENCE differ, and this test fails).
TEST(Recomputation, ATrajectoryTheControllerHeardLateIsHeldUntilTheTickThatTracksIt) {
  const ClosedLoopFlight c = test::flyClosedLoop([](mission::Scenario& s) {
    mission::ScenarioEvent circle;
    circle.at = 7.025;
    circle.kind = mission::ScenarioEvent::Kind::kTrajectory;
    circle.trajectory.generator = "circle";
    circle.trajectory.speed = 0.5;
    circle.trajectory.size = 0.3;
    circle.trajectory.center = Vec3(0.5, 0.0, 1.0);
    s.events.push_back(circle);
    std::stable_sort(s.events.begin(), s.events.end(),
                     [](const mission::ScenarioEvent& a, const mission::ScenarioEvent& b) { return a.at < b.at; });
  });
  ASSERT_EQ(c.flight.trajectory.size(), 1u);
  RecordedFlight recorded = c.flight;
  moveBeforeEstimates(recorded, InputKind::kTrajectory, 0, 6);
  Recomputation replay(test::paramsOf(c.config), recorded);
  replay.runToEnd();
  expectBitForBit(recorded, replay);
  const auto tracking = std::count_if(replay.outputs().reference.begin(), replay.outputs().reference.end(),
                                      [](const Reference& r) { return r.trajectory_seq >= 0; });
  EXPECT_GT(tracking, 100) << "the circle was flown";
}

// Where the recorded STATE_EST of `seq` sits in the recorder's order.
size_t estimatePositionOf(const RecordedFlight& f, int64_t seq) {
  const auto estimate = std::find_if(f.state_estimate.begin(), f.state_estimate.end(),
                                     [&](const StateEstimate& e) { return e.seq == seq; });
  if (estimate == f.state_estimate.end()) throw std::runtime_error("no estimate of that seq");
  return positionOf(f, InputKind::kStateEstimate, static_cast<size_t>(estimate - f.state_estimate.begin()));
}

void expectNoForeignGainsAndBitForBit(const ClosedLoopFlight& c, const RecordedFlight& recorded) {
  Recomputation replay(test::paramsOf(c.config), recorded);
  replay.runToEnd();
  const Comparison comparison = compareOutputs(recorded, replay.outputs(), 0.0);
  std::cout << formatComparison(comparison);
  EXPECT_EQ(replay.pairing().foreign_gains, 0);
  EXPECT_TRUE(comparison.bitForBit());
}

// The recorder reads GAINS and STATE_EST on sockets of their own: on a busy machine it logs a
// solve before the estimate it was solved at, even before that estimate's IMU sample. Such a
// GAINS is the replay's own solve, not a foreign one fed to the controller early.
TEST(Recomputation, AGainsLoggedBeforeItsEstimateIsNotForeign) {
  const ClosedLoopFlight& c = closedLoopFlight();
  RecordedFlight recorded = replayedFlight();
  for (size_t g = 0; g < recorded.gains.size(); ++g) {
    size_t at = estimatePositionOf(recorded, recorded.gains[g].state_seq);
    while (at > 0 && recorded.order[at - 1].kind != InputKind::kImu) --at;
    if (at > 0) --at;  // before the IMU sample that completes the estimate
    recorded.order.insert(recorded.order.begin() + static_cast<std::ptrdiff_t>(at),
                          LogPosition{InputKind::kGains, static_cast<int32_t>(g)});
  }
  expectNoForeignGainsAndBitForBit(c, recorded);
}

// The estimate too heard before its IMU sample, and the solve at it between the two.
TEST(Recomputation, AGainsLoggedBetweenAnEarlyEstimateAndItsImuIsNotForeign) {
  const ClosedLoopFlight& c = closedLoopFlight();
  RecordedFlight recorded = replayedFlight();
  for (size_t g = 0; g < recorded.gains.size(); ++g) {
    const size_t at = estimatePositionOf(recorded, recorded.gains[g].state_seq);
    ASSERT_EQ(recorded.order[at - 1].kind, InputKind::kImu);
    std::swap(recorded.order[at - 1], recorded.order[at]);  // STATE_EST, then its IMU
    recorded.order.insert(recorded.order.begin() + static_cast<std::ptrdiff_t>(at),
                          LogPosition{InputKind::kGains, static_cast<int32_t>(g)});
  }
  expectNoForeignGainsAndBitForBit(c, recorded);
}

// A GAINS no solve of the replay matches, logged as early, is still foreign: judged by the
// controller's core once its estimate is handed over.
TEST(Recomputation, AForgedGainsLoggedBeforeItsEstimateIsStillForeign) {
  const ClosedLoopFlight& c = closedLoopFlight();
  RecordedFlight recorded = replayedFlight();
  GainSet forged = recorded.gains[40];
  forged.seq = 100000;
  forged.K = -forged.K;  // destabilizing: the controller's closed-loop check refuses it
  recorded.gains.push_back(forged);
  const size_t at = estimatePositionOf(recorded, forged.state_seq);
  recorded.order.insert(recorded.order.begin() + static_cast<std::ptrdiff_t>(at),
                        LogPosition{InputKind::kGains, static_cast<int32_t>(recorded.gains.size() - 1)});
  Recomputation replay(test::paramsOf(c.config), recorded);
  replay.runToEnd();
  EXPECT_EQ(replay.pairing().foreign_gains, 1);
  EXPECT_EQ(replay.controller().health().rejected(), 1);
}

}  // namespace
}  // namespace sdlqr::replay
