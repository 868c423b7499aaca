// BusMonitor: rates over the report period, ages, sizes, heartbeat liveness.

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "sdlqr/inspect/bus_monitor.hpp"

namespace sdlqr::inspect {
namespace {

constexpr int64_t kT0 = 1'700'000'000'000'000;  // [us] wall clock

logger::HeartbeatRecord heartbeat(const std::string& process, int8_t state) {
  logger::HeartbeatRecord h;
  h.process = process;
  h.state = state;
  h.cpu_percent = 3.5;
  h.dropped = 7;
  return h;
}

TEST(BusMonitor, RatesAgesAndSizesPerChannel) {
  BusMonitor monitor;
  // 1000 IMU messages of 89 B and 100 RATE_CMD of 120 B within one second.
  for (int i = 0; i < 1000; ++i) {
    monitor.onMessage("IMU", 89, kT0 + i * 1000);
    if (i % 10 == 0) monitor.onMessage("RATE_CMD", 120, kT0 + i * 1000);
  }
  const BusReport first = monitor.report(kT0 + 1'000'000);
  ASSERT_EQ(first.channels.size(), 2u);
  EXPECT_EQ(first.channels[0].channel, "IMU");
  EXPECT_DOUBLE_EQ(first.period_s, 1.0);
  EXPECT_DOUBLE_EQ(first.channels[0].rate_hz, 1000.0);
  EXPECT_DOUBLE_EQ(first.channels[0].age_ms, 1.0);
  EXPECT_EQ(first.channels[0].last_size, 89);
  EXPECT_DOUBLE_EQ(first.channels[0].bytes_per_s, 89000.0);
  EXPECT_DOUBLE_EQ(first.channels[1].rate_hz, 100.0);
  EXPECT_DOUBLE_EQ(first.channels[1].age_ms, 10.0);

  // The next report counts only what came since: IMU half as fast, RATE_CMD silent.
  for (int i = 0; i < 250; ++i) monitor.onMessage("IMU", 90, kT0 + 1'000'000 + i * 2000);
  const BusReport second = monitor.report(kT0 + 1'500'000);
  EXPECT_DOUBLE_EQ(second.period_s, 0.5);
  EXPECT_DOUBLE_EQ(second.channels[0].rate_hz, 500.0);
  EXPECT_EQ(second.channels[0].last_size, 90);
  EXPECT_EQ(second.channels[0].messages, 1250);
  EXPECT_DOUBLE_EQ(second.channels[1].rate_hz, 0.0);
  EXPECT_DOUBLE_EQ(second.channels[1].age_ms, 510.0);
}

TEST(BusMonitor, ProcessIsAliveUntilSilentOrStopping) {
  BusMonitor monitor(2.5);
  monitor.onHeartbeat("HEARTBEAT", heartbeat("sdlqr-sim", 1), kT0);
  monitor.onHeartbeat("HEARTBEAT", heartbeat("sdlqr-gains", 1), kT0);
  monitor.onHeartbeat("QUAD1/HEARTBEAT", heartbeat("sdlqr-gains", 2), kT0);
  BusReport report = monitor.report(kT0 + 2'000'000);
  ASSERT_EQ(report.processes.size(), 3u);
  for (const ProcessRow& p : report.processes) EXPECT_TRUE(p.alive) << p.channel << " " << p.heartbeat.process;

  monitor.onHeartbeat("HEARTBEAT", heartbeat("sdlqr-sim", 4), kT0 + 2'500'000);  // STOPPING
  monitor.onHeartbeat("QUAD1/HEARTBEAT", heartbeat("sdlqr-gains", 1), kT0 + 2'500'000);
  report = monitor.report(kT0 + 3'000'000);
  std::map<std::string, bool> alive;
  for (const ProcessRow& p : report.processes) alive[p.channel + " " + p.heartbeat.process] = p.alive;
  EXPECT_FALSE(alive["HEARTBEAT sdlqr-sim"]) << "stopping";
  EXPECT_FALSE(alive["HEARTBEAT sdlqr-gains"]) << "silent for 3 s";
  EXPECT_TRUE(alive["QUAD1/HEARTBEAT sdlqr-gains"]);

  const std::string text = formatReport(report);
  std::cout << text;
  EXPECT_NE(text.find("QUAD1/sdlqr-gains"), std::string::npos);
  EXPECT_NE(text.find("stopped"), std::string::npos);
  EXPECT_NE(text.find("SILENT"), std::string::npos);
}

// A name longer than the default column (a vehicle prefix) widens the column for every row, so
// each row's HEALTH stays under the header's.
TEST(BusMonitor, LongProcessNamesKeepTheColumnsInLine) {
  BusMonitor monitor;
  monitor.onHeartbeat("QUAD1/HEARTBEAT", heartbeat("sdlqr-controller", 1), kT0);
  monitor.onHeartbeat("HEARTBEAT", heartbeat("sdlqr-sim", 1), kT0);
  const std::string text = formatReport(monitor.report(kT0 + 100'000));
  std::istringstream lines(text.substr(text.find("PROCESS")));
  std::string line;
  std::getline(lines, line);
  const size_t health_column = line.find("HEALTH");
  int rows = 0;
  while (std::getline(lines, line)) {
    EXPECT_EQ(line.find("alive"), health_column) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 2);
}

}  // namespace
}  // namespace sdlqr::inspect
