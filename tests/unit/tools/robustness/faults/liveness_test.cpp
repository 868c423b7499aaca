// sdlqr-faultcheck's liveness verdict on synthetic heartbeat logs: a process that beats to the end
// passes; one that hangs for good after its last heartbeat fails; forged and replayed heartbeats
// under its name (the fuzz flight's hostile peer) do not keep a hung process alive.

#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/faults/liveness.hpp"

namespace sdlqr::faults {
namespace {

// Simulation time t [s] is received at wall time kLivenessWall0 + t.
constexpr int64_t kLivenessWall0 = 1'700'000'000'000'000;
int64_t livenessWall(double t) { return kLivenessWall0 + static_cast<int64_t>(std::llround(t * 1e6)); }

void beat(logger::FlightLog& log, const std::string& process, int32_t pid, int64_t seq, double t,
          int8_t state = 1) {
  logger::HeartbeatRecord hb;
  hb.process = process;
  hb.pid = pid;
  hb.seq = seq;
  hb.state = state;
  log.heartbeat.messages.push_back(hb);
  log.heartbeat.receive_utime.push_back(livenessWall(t));
}

// `process` beats once a second from 0 s until `last_beat`; the recorder hears the simulator
// until `end` (the log's end).
logger::FlightLog flight(double last_beat, double end) {
  logger::FlightLog log;
  for (int i = 0; i <= static_cast<int>(end); ++i) beat(log, "sdlqr-sim", 100, i, i);
  for (int i = 0; i <= static_cast<int>(last_beat); ++i) beat(log, "sdlqr-controller", 200, i, i + 0.5);
  log.sim_truth.messages.push_back(SimTruth{});
  log.sim_truth.receive_utime.push_back(livenessWall(end));
  return log;
}

const Finding* findingAbout(const std::vector<Finding>& findings, const std::string& text) {
  for (const Finding& f : findings) {
    if (f.text.find(text) != std::string::npos) return &f;
  }
  return nullptr;
}

TEST(Liveness, AProcessThatBeatsToTheEndPasses) {
  const Liveness l = measureLiveness(flight(29.0, 30.0));
  EXPECT_EQ(l.log_end_utime, livenessWall(30.0));
  ASSERT_EQ(l.processes.size(), 2u);
  EXPECT_EQ(l.processes[0].process, "sdlqr-controller");
  EXPECT_EQ(l.processes[0].beats, 30);
  EXPECT_NEAR(l.processes[0].silent_at_end_s, 0.5, 1e-9);
  EXPECT_NEAR(l.processes[0].longest_gap_s, 1.0, 1e-9);
  EXPECT_TRUE(allOk(judgeLiveness(l, LivenessRules{})));
}

TEST(Liveness, AProcessThatHangsForGoodAfterItsLastHeartbeatFails) {
  // No gap between its heartbeats is long: only the silence at the end shows the hang.
  const Liveness l = measureLiveness(flight(12.0, 30.0));
  EXPECT_NEAR(l.processes[0].longest_gap_s, 1.0, 1e-9);
  EXPECT_NEAR(l.processes[0].silent_at_end_s, 17.5, 1e-9);
  const std::vector<Finding> findings = judgeLiveness(l, LivenessRules{});
  EXPECT_FALSE(allOk(findings));
  const Finding* end = findingAbout(findings, "sdlqr-controller: last heartbeat 17.50 s before the end");
  ASSERT_NE(end, nullptr);
  EXPECT_FALSE(end->ok);
  // Killed on purpose excuses the gap, never the end: a restart must beat to the end too.
  LivenessRules killed;
  killed.killed = {"sdlqr-controller"};
  EXPECT_FALSE(allOk(judgeLiveness(l, killed)));
}

TEST(Liveness, OnlyAProcessAllowedToStopMayEndEarlyAndOnlyWithAStoppingHeartbeat) {
  logger::FlightLog log = flight(30.0, 30.0);
  for (int i = 0; i <= 10; ++i) beat(log, "sdlqr-fuzz-publisher", 300, i, 5.0 + i, i == 10 ? 4 : 1);
  LivenessRules rules;
  rules.may_stop = {"sdlqr-fuzz-publisher"};
  EXPECT_TRUE(allOk(judgeLiveness(measureLiveness(log), rules)));
  EXPECT_FALSE(allOk(judgeLiveness(measureLiveness(log), LivenessRules{})));
  // Ended without saying so: hung, even if it may stop.
  logger::FlightLog hung = flight(30.0, 30.0);
  for (int i = 0; i <= 10; ++i) beat(hung, "sdlqr-fuzz-publisher", 300, i, 5.0 + i);
  EXPECT_FALSE(allOk(judgeLiveness(measureLiveness(hung), rules)));
}

// A loss flight's launch took over a second to hear every process: the launcher's waiter beat
// twice, then ended with its STOPPING heartbeat long before the log did.
TEST(Liveness, TheLaunchersWaiterMayStopByDefaultButNotHangThere) {
  LivenessRules rules;
  rules.may_stop = kProcessesThatMayStop;
  logger::FlightLog log = flight(30.0, 30.0);
  for (int i = 0; i <= 2; ++i) beat(log, "sdlqr-top", 400, i, 0.5 * i, i == 2 ? 4 : 0);
  EXPECT_TRUE(allOk(judgeLiveness(measureLiveness(log), rules)));
  logger::FlightLog hung = flight(30.0, 30.0);
  for (int i = 0; i <= 2; ++i) beat(hung, "sdlqr-top", 400, i, 0.5 * i);
  EXPECT_FALSE(allOk(judgeLiveness(measureLiveness(hung), rules)));
}

TEST(Liveness, ReplayedAndForgedHeartbeatsDoNotKeepAHungProcessAlive) {
  logger::FlightLog log = flight(12.0, 30.0);
  // A hostile peer resends the controller's last heartbeat (same seq), a copy with its seq
  // mutated far ahead, and copies under pids that never beat twice, until the end.
  for (double t = 13.0; t <= 30.0; t += 0.25) {
    beat(log, "sdlqr-controller", 200, 12, t);
    beat(log, "sdlqr-controller", 200, 1'000'000'000 + static_cast<int64_t>(t * 4), t);
    beat(log, "sdlqr-controller", static_cast<int32_t>(1000 + t * 4), 13, t);
  }
  const Liveness l = measureLiveness(log);
  EXPECT_EQ(l.processes[0].beats, 13);
  EXPECT_GT(l.processes[0].ignored, 200);
  EXPECT_EQ(l.processes[0].senders, 1);
  EXPECT_NEAR(l.processes[0].silent_at_end_s, 17.5, 1e-9);
  EXPECT_FALSE(allOk(judgeLiveness(l, LivenessRules{})));
}

TEST(Liveness, ARestartedProcessCountsAsOneThatBeatsAgain) {
  logger::FlightLog log = flight(10.0, 30.0);
  for (int i = 0; i <= 15; ++i) beat(log, "sdlqr-controller", 201, i, 15.0 + i);  // new pid, seq from 0
  const Liveness l = measureLiveness(log);
  EXPECT_EQ(l.processes[0].senders, 2);
  EXPECT_NEAR(l.processes[0].longest_gap_s, 4.5, 1e-9);
  LivenessRules rules;
  EXPECT_FALSE(allOk(judgeLiveness(l, rules)));  // a 4.5 s gap nobody asked for
  rules.killed = {"sdlqr-controller"};
  EXPECT_TRUE(allOk(judgeLiveness(l, rules)));
}

// The simulator beats at whole seconds and the controller half a second later, from 0 to 30 s; the
// simulator is silent strictly inside (sim_from, sim_to), the controller inside (from, to). With
// both silent together nothing at all reaches the recorder: the machine stalled.
logger::FlightLog silences(double sim_from, double sim_to, double from, double to) {
  logger::FlightLog log;
  int64_t sim_seq = 0, controller_seq = 0;
  for (int i = 0; i <= 30; ++i) {
    if (i <= sim_from || i >= sim_to) beat(log, "sdlqr-sim", 100, sim_seq++, i);
  }
  for (int i = 0; i <= 29; ++i) {
    if (i + 0.5 <= from || i + 0.5 >= to) beat(log, "sdlqr-controller", 200, controller_seq++, i + 0.5);
  }
  log.sim_truth.messages.push_back(SimTruth{});
  log.sim_truth.receive_utime.push_back(livenessWall(30.0));
  return log;
}

TEST(Liveness, AStallOfTheWholeMachineIsNotAProcessHang) {
  // 10 .. 14 s: nothing at all on the bus (seen in the suite: every heartbeat 2.8 s apart at once);
  // each process's gap besides it is what it alone left silent.
  const Liveness l = measureLiveness(silences(10.2, 13.8, 10.2, 13.8));
  EXPECT_NEAR(l.longest_machine_stall_s, 4.0, 1e-9);
  EXPECT_NEAR(l.processes[0].longest_gap_s, 1.0, 1e-9);  // 9.5 -> 14.5, 4 s of it the machine's
  EXPECT_NEAR(l.processes[0].stall_not_counted_s, 4.0, 1e-9);
  const std::vector<Finding> findings = judgeLiveness(l, LivenessRules{});
  EXPECT_TRUE(allOk(findings));
  const Finding* controller = findingAbout(findings, "sdlqr-controller: longest heartbeat gap");
  ASSERT_NE(controller, nullptr);
  EXPECT_NE(controller->text.find("not counting a 4.00 s stall of the whole bus"), std::string::npos)
      << controller->text;
}

TEST(Liveness, AProcessSilentWhileTheOthersGoOnFailsWhateverTheStalls) {
  // The controller silent 9.5 -> 14.5 s while the simulator beats on: it hung, no stall to discount.
  const Liveness alone = measureLiveness(silences(-1.0, -1.0, 10.2, 13.8));
  EXPECT_EQ(alone.longest_machine_stall_s, 0.0);  // the simulator beat on every second: no stall
  EXPECT_NEAR(alone.processes[0].longest_gap_s, 5.0, 1e-9);
  EXPECT_FALSE(allOk(judgeLiveness(alone, LivenessRules{})));
  // Silent 9.5 -> 20.5 s across a 4 s stall of the machine (10 -> 14 s): 7 s are its own.
  const Liveness longer = measureLiveness(silences(10.2, 13.8, 10.2, 19.8));
  EXPECT_NEAR(longer.processes[0].longest_gap_s, 7.0, 1e-9);
  EXPECT_FALSE(allOk(judgeLiveness(longer, LivenessRules{})));
  // Hung for good after 9.5 s across the same stall: its silence at the end counts all but it.
  const Liveness hung = measureLiveness(silences(10.2, 13.8, 10.2, 99.0));
  EXPECT_NEAR(hung.processes[0].silent_at_end_s, 30.0 - 9.5 - 4.0, 1e-9);
  EXPECT_FALSE(allOk(judgeLiveness(hung, LivenessRules{})));
}

TEST(Liveness, AnExpectedProcessThatNeverBeatFails) {
  LivenessRules rules;
  rules.expected = {"sdlqr-sim", "sdlqr-estimator"};
  const std::vector<Finding> findings = judgeLiveness(measureLiveness(flight(30.0, 30.0)), rules);
  const Finding* missing = findingAbout(findings, "sdlqr-estimator: never sent a heartbeat");
  ASSERT_NE(missing, nullptr);
  EXPECT_FALSE(missing->ok);
  EXPECT_EQ(findingAbout(findings, "sdlqr-sim: never"), nullptr);
}

}  // namespace
}  // namespace sdlqr::faults
