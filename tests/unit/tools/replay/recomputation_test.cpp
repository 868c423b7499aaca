// The replay's recomputation: the estimator reproduces a closed-loop flight, a replay of a
// replay is identical bit for bit, and the pairing named in the recording decides which K a
// controller tick uses and which reference input a solve uses, whatever the arrival order.

#include <gtest/gtest.h>

#include <iostream>

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

}  // namespace
}  // namespace sdlqr::replay
