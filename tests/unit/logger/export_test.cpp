// Logs written with LCM's event-log API (no bus), read back through FlightLog and the CSV
// export, compared value for value.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "sdlqr/messages/channels.hpp"
#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/logger/csv.hpp"
#include "sdlqr/logger/decode.hpp"
#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/lcmtypes/generated/wire_fits.hpp"
#include "sdlqr/logger/csv_row.hpp"
#include "sdlqr/logger/log_export.hpp"
#include "sdlqr/logger/log_reader.hpp"
#include "sdlqr/bus/convert.hpp"
#include "test_support.hpp"

namespace sdlqr::logger {
namespace {

namespace fs = std::filesystem;
using test::encode;
using test::RawEvent;
using test::ScratchDir;
using test::writeLog;

constexpr int64_t kStart = 1'700'000'000'000'000;  // [us] a wall-clock receive time

std::vector<std::vector<std::string>> readCsv(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> cells;
  std::string error;
  while (readCsvRecord(in, &cells, &error)) rows.push_back(cells);
  EXPECT_TRUE(error.empty()) << error;
  return rows;
}

const ExportedChannel* findExported(const ExportResult& result, const std::string& channel) {
  for (const ExportedChannel& c : result.channels) {
    if (c.channel == channel) return &c;
  }
  return nullptr;
}

TEST(Export, EveryTypeRoundTripsExactly) {
  ScratchDir dir("roundtrip");
  test::RandomCells random(42);
  std::vector<RawEvent> events;
  std::map<std::string, std::vector<std::vector<uint8_t>>> expected;  // channel -> encoded messages
  int64_t receive = kStart;
  for (int round = 0; round < 40; ++round) {
    for (const ChannelType& c : channelTypes()) {
      const bool known = lcmtypes::visitLcmType(c.lcm_type, [&](auto tag) {
        using LcmType = typename decltype(tag)::type;
        const lcmtypes::TypeDescriptor& descriptor = lcmtypes::LcmFields<LcmType>::type;
        LcmType message;
        std::string error;
        ASSERT_TRUE(readCsvRow(random.make(descriptor), message, &error)) << c.lcm_type << ": " << error;
        const std::string channel = channel::name(round % 4 == 0 ? "" : "QUAD1", c.base);
        events.push_back({channel, encode(message), receive += 137});
        expected[channel].push_back(events.back().bytes);
      });
      ASSERT_TRUE(known) << c.lcm_type;
    }
  }
  writeLog(dir / "all.lcmlog", events);

  ExportOptions options;
  options.log_path = (dir / "all.lcmlog").string();
  options.out_dir = (dir / "out").string();
  std::vector<int> progress;
  options.progress = [&](int percent, int64_t) { progress.push_back(percent); };
  const ExportResult result = exportLog(options);
  EXPECT_EQ(progress, (std::vector<int>{10, 20, 30, 40, 50, 60, 70, 80, 90, 100}));
  EXPECT_TRUE(result.log.complete());
  EXPECT_EQ(result.log.events, static_cast<int64_t>(events.size()));
  ASSERT_EQ(result.channels.size(), expected.size());

  size_t values_compared = 0;
  for (const auto& entry : expected) {
    // Named references, not a structured binding: the lambda below captures them (C++17 does not
    // let a lambda capture a structured binding; clang, which builds the sanitizer pass, refuses).
    const std::string& channel = entry.first;
    const auto& messages = entry.second;
    const ExportedChannel* exported = findExported(result, channel);
    ASSERT_NE(exported, nullptr) << channel;
    EXPECT_EQ(exported->rows, static_cast<int64_t>(messages.size())) << channel;
    EXPECT_EQ(exported->decode_failures, 0);
    const std::vector<std::vector<std::string>> rows = readCsv(exported->csv_path);
    ASSERT_EQ(rows.size(), messages.size() + 1) << channel << ": header plus one row per message";
    lcmtypes::visitLcmType(exported->lcm_type, [&](auto tag) {
      using LcmType = typename decltype(tag)::type;
      const lcmtypes::TypeDescriptor& descriptor = lcmtypes::LcmFields<LcmType>::type;
      EXPECT_EQ(rows[0], std::vector<std::string>(descriptor.columns, descriptor.columns + descriptor.num_columns));
      for (size_t i = 0; i < messages.size(); ++i) {
        LcmType back;
        std::string error;
        ASSERT_TRUE(readCsvRow(rows[i + 1], back, &error)) << channel << " row " << i << ": " << error;
        // Same encoding = every field, every array element, every string byte identical.
        ASSERT_EQ(encode(back), messages[i]) << channel << " row " << i;
        values_compared += rows[i + 1].size();
      }
    });
  }
  std::cout << "[ figures  ] " << events.size() << " messages of " << channelTypes().size() << " types on "
            << expected.size() << " channels, " << values_compared << " cells compared exactly\n";
  EXPECT_TRUE(fs::exists(result.metrics_path));
}

TEST(Export, ColumnsHoldTheFieldsTheyName) {
  ScratchDir dir("columns");
  imu_t imu{};
  imu.utime = 1234;
  imu.seq = 7;
  imu.gyro[1] = -0.2;
  imu.accel[2] = 9.81;
  gains_t gains{};
  for (int k = 0; k < 40; ++k) gains.K[k] = 0.5 * k;
  gains.x_lin[3] = 1.0;
  gains.u_lin[3] = 9.81;
  gains.solve_us = 12.5;
  gains.iterations = 13;
  heartbeat_t heartbeat{};
  heartbeat.process = "sdlqr-gains";
  heartbeat.num_counters = 2;
  heartbeat.counter_names = {"reject.nan", "gains.fallback"};
  heartbeat.counter_values = {3, -4};
  heartbeat.last_error = "solver: \"not converged\", retry";
  trajectory_t trajectory{};
  trajectory.num_samples = 2;
  trajectory.t = {0.0, 0.1};
  trajectory.x = {std::vector<double>(10), std::vector<double>(10)};
  trajectory.u = {std::vector<double>(4), std::vector<double>(4)};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 10; ++j) trajectory.x[static_cast<size_t>(i)][static_cast<size_t>(j)] = 10 * i + j;
  }
  writeLog(dir / "a.lcmlog", {{"IMU", encode(imu), kStart},
                              {"GAINS", encode(gains), kStart + 1},
                              {"HEARTBEAT", encode(heartbeat), kStart + 2},
                              {"TRAJECTORY", encode(trajectory), kStart + 3}});
  ExportOptions options;
  options.log_path = (dir / "a.lcmlog").string();
  options.out_dir = (dir / "out").string();
  exportLog(options);

  auto cell = [&](const std::string& csv, const std::string& column) {
    const auto rows = readCsv(dir / "out" / csv);
    EXPECT_EQ(rows.size(), 2u);
    for (size_t c = 0; c < rows[0].size(); ++c) {
      if (columnName(rows[0][c]) == column) return rows[1][c];
    }
    ADD_FAILURE() << csv << " has no column " << column;
    return std::string();
  };
  auto number = [&](const std::string& csv, const std::string& column) { return std::stod(cell(csv, column)); };
  EXPECT_EQ(cell("IMU.csv", "utime"), "1234");
  EXPECT_EQ(cell("IMU.csv", "seq"), "7");
  EXPECT_EQ(number("IMU.csv", "gyro[1]"), -0.2);
  EXPECT_EQ(number("IMU.csv", "accel[2]"), 9.81);
  EXPECT_EQ(number("GAINS.csv", "K[39]"), 19.5);
  EXPECT_EQ(number("GAINS.csv", "K[5]"), 2.5);
  EXPECT_EQ(number("GAINS.csv", "x_lin[3]"), 1.0);
  EXPECT_EQ(number("GAINS.csv", "u_lin[3]"), 9.81);
  EXPECT_EQ(number("GAINS.csv", "solve_us"), 12.5);
  EXPECT_EQ(cell("GAINS.csv", "iterations"), "13");
  EXPECT_EQ(cell("HEARTBEAT.csv", "process"), "sdlqr-gains");
  EXPECT_EQ(cell("HEARTBEAT.csv", "last_error"), heartbeat.last_error);
  JsonDocument names;
  JsonDocument values;
  std::string error;
  ASSERT_TRUE(parseJson(cell("HEARTBEAT.csv", "counter_names[num_counters]"), &names, &error)) << error;
  ASSERT_TRUE(parseJson(cell("HEARTBEAT.csv", "counter_values[num_counters]"), &values, &error)) << error;
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[1].get<std::string>(), "gains.fallback");
  EXPECT_EQ(values[1].get<double>(), -4.0);
  JsonDocument x;
  ASSERT_TRUE(parseJson(cell("TRAJECTORY.csv", "x[num_samples][10]"), &x, &error)) << error;
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[1][7].get<double>(), 17.0);
  EXPECT_EQ(number("TRAJECTORY.csv", "num_samples"), 2.0);
}

// A small flight of two vehicles, with one undecodable message and one foreign channel.
struct Flight {
  std::vector<RawEvent> events;
  int imu = 0;
  int gains = 0;
};

Flight makeFlight() {
  Flight f;
  int64_t receive = kStart;
  for (int i = 0; i < 200; ++i) {
    ImuSample s;
    s.utime = 1000 * i;
    s.seq = i;
    s.gyro = Vec3(0.01 * i, -0.5, 1.5);
    f.events.push_back({"QUAD1/IMU", encode(bus::toLcm(s)), receive += 1000});
    ++f.imu;
    if (i % 4 == 0) {
      StateEstimate e;
      e.utime = s.utime;
      e.seq = i / 4;
      e.position = Vec3(1.0, 2.0, 0.001 * i);
      f.events.push_back({"QUAD1/STATE_EST", encode(bus::toLcm(e)), receive + 300});
      f.events.push_back({"QUAD2/STATE_EST", encode(bus::toLcm(e)), receive + 400});
    }
    if (i % 100 == 0) {
      GainSet g;
      g.utime = s.utime;
      g.seq = f.gains++;
      g.solve_us = 11.0 + i;
      f.events.push_back({"QUAD1/GAINS", encode(bus::toLcm(g)), receive + 500});
    }
  }
  heartbeat_t hb{};
  hb.process = "sdlqr-controller";
  hb.state = 2;
  f.events.push_back({"QUAD1/HEARTBEAT", encode(hb), receive + 1});
  f.events.push_back({"QUAD1/IMU", std::vector<uint8_t>(30, 0xAB), receive + 2});  // not an imu_t
  f.events.push_back({"FOREIGN_CHANNEL", {1, 2, 3}, receive + 3});
  return f;
}

TEST(FlightLog, DecodesOneVehicleIntoPlainStructs) {
  ScratchDir dir("flight");
  const Flight flight = makeFlight();
  writeLog(dir / "f.lcmlog", flight.events);
  const FlightLog log = FlightLog::load((dir / "f.lcmlog").string(), "QUAD1");
  EXPECT_TRUE(log.file.complete());
  EXPECT_EQ(log.file.events, static_cast<int64_t>(flight.events.size()));
  ASSERT_EQ(log.imu.size(), 200u);
  EXPECT_EQ(log.imu.decode_failures, 1);
  EXPECT_EQ(log.imu[37].gyro, Vec3(0.01 * 37, -0.5, 1.5));
  EXPECT_EQ(log.imu.receive_utime[1] - log.imu.receive_utime[0], 1000);
  EXPECT_EQ(log.state_estimate.size(), 50u);
  EXPECT_EQ(log.state_estimate[10].position.z(), 0.001 * 40);
  EXPECT_EQ(log.gains.size(), 2u);
  EXPECT_EQ(log.gains[1].solve_us, 111.0);
  ASSERT_EQ(log.heartbeat.size(), 1u);
  EXPECT_EQ(log.heartbeat[0].process, "sdlqr-controller");
  EXPECT_TRUE(log.sim_truth.empty());
  // Truth-at-time lookups.
  EXPECT_EQ(log.state_estimate.indexAtOrBefore(9999), 2);
  EXPECT_EQ(log.state_estimate.indexAtOrBefore(-1), -1);
  EXPECT_EQ(log.state_estimate.indexAtOrBefore(1'000'000), 49);
  // The other vehicle and the foreign channel are counted, not decoded.
  const ChannelTimeline* other = log.channel("QUAD2/STATE_EST");
  ASSERT_NE(other, nullptr);
  EXPECT_EQ(other->events, 50);
  EXPECT_TRUE(other->utime.empty());
  ASSERT_NE(log.channel("FOREIGN_CHANNEL"), nullptr);
  EXPECT_TRUE(log.channel("FOREIGN_CHANNEL")->lcm_type.empty());

  const LogMetrics metrics = computeLogMetrics(log.metricsInput(), MetricsOptions{});
  ASSERT_EQ(metrics.gains.count("QUAD1/GAINS"), 1u);
  EXPECT_DOUBLE_EQ(metrics.gains.at("QUAD1/GAINS").solve_us.mean, 61.0);
  EXPECT_EQ(metrics.clock_channel, "QUAD1/IMU");
  EXPECT_DOUBLE_EQ(metrics.real_time_factor, 1.0);
}

TEST(LogReader, StreamsEventsDecodedOneByOne) {
  ScratchDir dir("stream");
  writeLog(dir / "f.lcmlog", makeFlight().events);
  LogReader reader((dir / "f.lcmlog").string());
  LogEvent event;
  int imu = 0;
  int failures = 0;
  while (reader.next(&event)) {
    if (event.channel != "QUAD1/IMU") continue;
    ImuSample sample;
    GainSet wrong;
    if (decodeMessage(event, &sample)) {
      EXPECT_EQ(sample.seq, imu);
      EXPECT_FALSE(decodeMessage(event, &wrong)) << "an imu_t must not decode as gains_t";
      ++imu;
    } else {
      ++failures;
    }
  }
  EXPECT_EQ(imu, 200);
  EXPECT_EQ(failures, 1);
}

TEST(FlightLog, UnprefixedVehicleIsTheDefault) {
  ScratchDir dir("unprefixed");
  ImuSample s;
  s.seq = 5;
  writeLog(dir / "u.lcmlog", {{"IMU", encode(bus::toLcm(s)), kStart}, {"QUAD1/IMU", encode(bus::toLcm(s)), kStart}});
  const FlightLog log = FlightLog::load((dir / "u.lcmlog").string());
  ASSERT_EQ(log.imu.size(), 1u);
  EXPECT_EQ(log.imu[0].seq, 5);
}

TEST(Export, DecodeFailuresAndForeignChannelsAreCountedNotExported) {
  ScratchDir dir("failures");
  const Flight flight = makeFlight();
  writeLog(dir / "f.lcmlog", flight.events);
  ExportOptions options;
  options.log_path = (dir / "f.lcmlog").string();
  options.out_dir = (dir / "out").string();
  const ExportResult result = exportLog(options);
  const ExportedChannel* imu = findExported(result, "QUAD1/IMU");
  ASSERT_NE(imu, nullptr);
  EXPECT_EQ(imu->events, 201);
  EXPECT_EQ(imu->rows, 200);
  EXPECT_EQ(imu->decode_failures, 1);
  EXPECT_EQ(readCsv(imu->csv_path).size(), 201u);
  const ExportedChannel* foreign = findExported(result, "FOREIGN_CHANNEL");
  ASSERT_NE(foreign, nullptr);
  EXPECT_TRUE(foreign->csv_path.empty());
  EXPECT_TRUE(fs::exists(dir / "out" / "QUAD2" / "STATE_EST.csv"));

  JsonDocument json;
  std::string error;
  ASSERT_TRUE(parseJson(test::readText(result.metrics_path), &json, &error)) << error;
  ASSERT_TRUE(json["channels"].contains("QUAD1/IMU"));
  const JsonDocument& imu_metrics = json["channels"]["QUAD1/IMU"];
  EXPECT_EQ(imu_metrics["decode_failures"].get<double>(), 1.0);
  EXPECT_EQ(imu_metrics["seq"]["lost"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(imu_metrics["sim"]["rate_hz"].get<double>(), 1000.0);
  EXPECT_EQ(json["gains"]["QUAD1/GAINS"]["count"].get<double>(), 2.0);
  EXPECT_EQ(json["heartbeat"]["QUAD1/HEARTBEAT"]["sdlqr-controller"]["last"]["state"].get<std::string>(), "DEGRADED");
}

int64_t eventBytes(const RawEvent& e) { return 28 + static_cast<int64_t>(e.channel.size() + e.bytes.size()); }

TEST(LogReader, TruncatedLastEventIsToleratedAndReported) {
  ScratchDir dir("truncated");
  const Flight flight = makeFlight();
  std::vector<RawEvent> events(flight.events.begin(), flight.events.begin() + 100);
  writeLog(dir / "t.lcmlog", events);
  const int64_t full = static_cast<int64_t>(fs::file_size(dir / "t.lcmlog"));
  const int64_t cut = eventBytes(events.back()) / 2;
  fs::resize_file(dir / "t.lcmlog", static_cast<uintmax_t>(full - cut));

  LogReader reader((dir / "t.lcmlog").string());
  LogEvent event;
  int64_t read = 0;
  while (reader.next(&event)) ++read;
  EXPECT_EQ(read, 99);
  EXPECT_EQ(reader.status().truncated_tail_bytes, eventBytes(events.back()) - cut);
  EXPECT_EQ(reader.status().skipped_bytes, 0);
  EXPECT_FALSE(reader.status().complete());

  ExportOptions options;
  options.log_path = (dir / "t.lcmlog").string();
  options.out_dir = (dir / "out").string();
  const ExportResult result = exportLog(options);
  int64_t rows = 0;
  for (const ExportedChannel& c : result.channels) rows += c.rows;
  EXPECT_EQ(rows, 99);
  EXPECT_EQ(FlightLog::load(options.log_path, "QUAD1").file.events, 99);
  std::cout << "[ figures  ] cut " << cut << " of " << eventBytes(events.back()) << " bytes of the last event: "
            << read << " of 100 events readable\n";
}

TEST(LogReader, DamagedEventIsSkippedAndTheRestRead) {
  ScratchDir dir("damaged");
  const Flight flight = makeFlight();
  std::vector<RawEvent> events(flight.events.begin(), flight.events.begin() + 50);
  writeLog(dir / "d.lcmlog", events);
  int64_t offset = 0;
  for (int i = 0; i < 20; ++i) offset += eventBytes(events[static_cast<size_t>(i)]);
  {
    // Event 20 claims an impossible channel length (bytes 20..23 of its header).
    std::fstream file(dir / "d.lcmlog", std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(offset + 20);
    const char bad[4] = {0x7f, 0x00, 0x00, 0x00};
    file.write(bad, 4);
  }
  LogReader reader((dir / "d.lcmlog").string());
  LogEvent event;
  std::vector<int64_t> numbers;
  while (reader.next(&event)) numbers.push_back(event.event_number);
  ASSERT_EQ(numbers.size(), 49u);
  EXPECT_EQ(numbers[19], 19);
  EXPECT_EQ(numbers[20], 21);
  EXPECT_EQ(reader.status().skipped_bytes, eventBytes(events[20]));
  EXPECT_EQ(reader.status().truncated_tail_bytes, 0);
}

TEST(LogReader, MissingEmptyAndForeignFilesAreErrors) {
  ScratchDir dir("errors");
  EXPECT_THROW(LogReader((dir / "missing.lcmlog").string()), LogError);
  EXPECT_THROW(LogReader(dir.path().string()), LogError);
  { std::ofstream empty(dir / "empty.lcmlog"); }
  {
    std::ofstream text(dir / "text.lcmlog");
    text << "this is not an LCM log\n";
  }
  for (const char* name : {"empty.lcmlog", "text.lcmlog"}) {
    ExportOptions options;
    options.log_path = (dir / name).string();
    options.out_dir = (dir / "out").string();
    EXPECT_THROW(exportLog(options), LogError) << name;
    EXPECT_THROW(FlightLog::load(options.log_path), LogError) << name;
    EXPECT_FALSE(fs::exists(dir / "out")) << "nothing is written for " << name;
  }
  try {
    FlightLog::load((dir / "text.lcmlog").string());
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("not an LCM event log"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sdlqr::logger
