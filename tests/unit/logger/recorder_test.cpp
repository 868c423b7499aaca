// The recorder writes what it is given to a standard LCM log, flushes on its own, and never
// overwrites a file. No bus: events are pushed as the LCM handler would.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "sdlqr/logger/log_reader.hpp"
#include "sdlqr/logger/recorder.hpp"
#include "test_support.hpp"

namespace sdlqr::logger {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

std::vector<uint8_t> payload(int i, size_t size) {
  std::vector<uint8_t> bytes(size);
  for (size_t k = 0; k < size; ++k) bytes[k] = static_cast<uint8_t>(i * 31 + static_cast<int>(k));
  return bytes;
}

TEST(Recorder, WritesEveryEventInOrder) {
  ScratchDir dir("recorder");
  RecorderOptions options;
  options.path = (dir / "r.lcmlog").string();
  {
    Recorder recorder(options);
    for (int i = 0; i < 5000; ++i) {
      const std::vector<uint8_t> data = payload(i, static_cast<size_t>(8 + i % 200));
      ASSERT_TRUE(recorder.push(i % 3 ? "QUAD1/IMU" : "QUAD1/STATE_EST", data.data(), data.size(), 1000 + i));
    }
    recorder.stop();
    const RecorderStats stats = recorder.stats();
    EXPECT_EQ(stats.written, 5000);
    EXPECT_EQ(stats.dropped, 0);
    EXPECT_EQ(stats.write_errors, 0);
  }
  LogReader reader(options.path);
  LogEvent event;
  int i = 0;
  while (reader.next(&event)) {
    const std::vector<uint8_t> data = payload(i, static_cast<size_t>(8 + i % 200));
    ASSERT_EQ(event.channel, i % 3 ? "QUAD1/IMU" : "QUAD1/STATE_EST");
    ASSERT_EQ(event.receive_utime, 1000 + i);
    ASSERT_EQ(std::vector<uint8_t>(event.data, event.data + event.size), data) << i;
    ++i;
  }
  EXPECT_EQ(i, 5000);
  EXPECT_TRUE(reader.status().complete());
}

TEST(Recorder, RefusesToOverwrite) {
  ScratchDir dir("overwrite");
  const fs::path path = dir / "exists.lcmlog";
  {
    std::ofstream existing(path);
    existing << "precious";
  }
  RecorderOptions options;
  options.path = path.string();
  try {
    Recorder recorder(options);
    ADD_FAILURE() << "an existing file was opened";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("refusing to overwrite"), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::readText(path), "precious");
  options.path = (dir / "no_such_folder" / "x.lcmlog").string();
  EXPECT_THROW(Recorder{options}, std::invalid_argument);
}

// Without stop(), data reaches the file within the flush period: what kill -9 would leave.
TEST(Recorder, FlushesWithoutBeingStopped) {
  ScratchDir dir("flush");
  RecorderOptions options;
  options.path = (dir / "f.lcmlog").string();
  options.flush_period = std::chrono::milliseconds(200);
  Recorder recorder(options);
  const std::vector<uint8_t> data = payload(1, 100);
  const auto pushed = std::chrono::steady_clock::now();
  ASSERT_TRUE(recorder.push("IMU", data.data(), data.size(), 1));
  const uintmax_t expected = 28 + 3 + 100;
  double visible_ms = -1.0;
  while (std::chrono::steady_clock::now() - pushed < std::chrono::seconds(2)) {
    if (fs::file_size(options.path) == expected) {
      visible_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - pushed).count();
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::cout << "[ figures  ] an event reached the file " << visible_ms << " ms after it was pushed (period 200 ms)\n";
  ASSERT_GE(visible_ms, 0.0) << "not flushed within 2 s";
  EXPECT_LT(visible_ms, 1000.0);
  EXPECT_GE(recorder.stats().flushes, 1);
}

TEST(Recorder, OverflowIsCountedNotBlocking) {
  ScratchDir dir("overflow");
  RecorderOptions options;
  options.path = (dir / "o.lcmlog").string();
  options.queue_events = 64;
  Recorder recorder(options);
  const std::vector<uint8_t> data = payload(2, 64);
  const int pushes = 200000;
  const auto start = std::chrono::steady_clock::now();
  int accepted = 0;
  for (int i = 0; i < pushes; ++i) accepted += recorder.push("IMU", data.data(), data.size(), i) ? 1 : 0;
  const double push_ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / pushes;
  recorder.stop();
  const RecorderStats stats = recorder.stats();
  std::cout << "[ figures  ] " << pushes << " pushes into a 64-slot queue: " << push_ns << " ns each, "
            << stats.dropped << " dropped, " << stats.written << " written, max depth " << stats.max_queue_depth
            << "\n";
  EXPECT_EQ(stats.written + stats.dropped, pushes);
  EXPECT_EQ(stats.written, accepted);
  EXPECT_LE(stats.max_queue_depth, 64);
}

}  // namespace
}  // namespace sdlqr::logger
