// The flight report's lost messages per subscriber and channel count exactly the gaps injected
// into a synthetic log: each process's HEARTBEAT counters (summed over a restart) and the log's
// own seq gaps; a flight without gaps reports none.

#include <gtest/gtest.h>

#include <sstream>

#include "sdlqr/analysis/flight_report.hpp"

namespace sdlqr {
namespace {

logger::HeartbeatRecord heartbeat(const char* process, int32_t pid, int64_t lost, int64_t queue) {
  logger::HeartbeatRecord hb;
  hb.process = process;
  hb.pid = pid;
  hb.counters = {{"lost.STATE_EST", lost}, {"queue_drop.STATE_EST", queue}, {"bus.datagrams", 999}};
  return hb;
}

logger::FlightLog lossyLog(std::vector<int64_t> imu_seq) {
  logger::FlightLog log;
  // Counters only grow: the last heartbeat of each pid counts, a restarted process adds its own.
  for (const auto& hb : {heartbeat("sdlqr-controller", 10, 2, 0), heartbeat("sdlqr-controller", 10, 5, 1),
                         heartbeat("sdlqr-controller", 11, 2, 2)}) {
    log.heartbeat.messages.push_back(hb);
    log.heartbeat.receive_utime.push_back(0);
  }
  logger::ChannelTimeline imu;
  imu.channel = "IMU";
  imu.lcm_type = "imu_t";
  imu.seq = std::move(imu_seq);
  imu.utime.assign(imu.seq.size(), 0);
  log.channels.push_back(imu);
  return log;
}

const analysis::ChannelLoss* find(const analysis::FlightReport& r, const std::string& process,
                                  const std::string& channel) {
  for (const auto& l : r.message_loss) {
    if (l.process == process && l.channel == channel) return &l;
  }
  return nullptr;
}

TEST(MessageLoss, CountsEveryInjectedGapPerSubscriberAndChannel) {
  const analysis::FlightReport r =
      analysis::analyzeFlight(lossyLog({0, 1, 4, 5, 9, 10}), mission::Scenario{});  // 2 + 3 lost
  const analysis::ChannelLoss* controller = find(r, "sdlqr-controller", "STATE_EST");
  ASSERT_NE(controller, nullptr);
  EXPECT_EQ(controller->lost, 7);
  EXPECT_EQ(controller->queue_dropped, 3);
  const analysis::ChannelLoss* recorder = find(r, "log", "IMU");
  ASSERT_NE(recorder, nullptr);
  EXPECT_EQ(recorder->lost, 5);
  EXPECT_EQ(find(r, "sdlqr-controller", "datagrams"), nullptr);
  std::ostringstream summary;
  analysis::writeSummary(r, summary);
  EXPECT_NE(summary.str().find("sdlqr-controller STATE_EST 7 (queue 3), log IMU 5"), std::string::npos) << summary.str();
}

TEST(MessageLoss, AFlightWithoutGapsReportsNone) {
  logger::FlightLog log = lossyLog({0, 1, 2, 3});
  log.heartbeat.messages.clear();
  log.heartbeat.receive_utime.clear();
  const analysis::FlightReport r = analysis::analyzeFlight(log, mission::Scenario{});
  ASSERT_NE(find(r, "log", "IMU"), nullptr);
  EXPECT_EQ(find(r, "log", "IMU")->lost, 0);
  std::ostringstream summary;
  analysis::writeSummary(r, summary);
  EXPECT_NE(summary.str().find("messages lost (subscriber channel count): none"), std::string::npos) << summary.str();
}

}  // namespace
}  // namespace sdlqr
