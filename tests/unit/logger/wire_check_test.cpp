// encodingFits must accept exactly the complete encodings, and reject corrupt lengths before
// an lcm-gen decoder would allocate for them.

#include <gtest/gtest.h>

#include <random>

#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/logger/decode.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/lcmtypes/generated/wire_fits.hpp"
#include "sdlqr/tables/csv_row.hpp"
#include "allocation_counter.hpp"
#include "test_support.hpp"

namespace sdlqr::logger {
namespace {
using namespace ::sdlqr::tables;

using test::encode;

// Index of the 4-byte big-endian int32 holding `value` (unique in the probe message).
size_t findInt32(const std::vector<uint8_t>& bytes, int32_t value) {
  const uint32_t v = static_cast<uint32_t>(value);
  const uint8_t pattern[4] = {static_cast<uint8_t>(v >> 24), static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8),
                              static_cast<uint8_t>(v)};
  for (size_t i = 8; i + 4 <= bytes.size(); ++i) {
    if (std::equal(pattern, pattern + 4, bytes.begin() + static_cast<std::ptrdiff_t>(i))) return i;
  }
  return bytes.size();
}

void setInt32(std::vector<uint8_t>& bytes, size_t at, uint32_t value) {
  for (int k = 0; k < 4; ++k) bytes[at + static_cast<size_t>(k)] = static_cast<uint8_t>(value >> (24 - 8 * k));
}

LogEvent eventOf(const std::vector<uint8_t>& bytes) {
  LogEvent e;
  e.channel = "X";
  e.data = bytes.data();
  e.size = static_cast<int64_t>(bytes.size());
  return e;
}

TEST(WireCheck, AbsurdArrayLengthsFailWithoutAllocating) {
  trajectory_t trajectory{};
  trajectory.num_samples = 0;
  heartbeat_t heartbeat{};
  heartbeat.process = "p";
  heartbeat.num_counters = 1;
  heartbeat.counter_names = {"c"};
  heartbeat.counter_values = {0x0a0b0c0d};
  heartbeat.pid = 0x01020304;

  std::vector<uint8_t> bytes = encode(trajectory);
  // num_samples follows utime, seq, start_utime, tracking, closed after the fingerprint.
  setInt32(bytes, 8 + 8 + 8 + 8 + 1 + 1, 0x7fffffff);
  std::vector<uint8_t> hb = encode(heartbeat);
  const size_t pid_at = findInt32(hb, 0x01020304);
  ASSERT_LT(pid_at, hb.size());
  // num_counters: after pid (4), state (1) and received..errors (6 x 8) and cpu_percent (8).
  const size_t counters_at = pid_at + 4 + 1 + 6 * 8 + 8;
  ASSERT_EQ(hb[counters_at + 3], 1) << "layout of heartbeat_t changed";
  setInt32(hb, counters_at, 0x7ffffff0);

  // Refused by the size walk before the decoder runs: not one allocation (an lcm-gen decoder
  // would first resize a vector to the claimed 2^31 elements).
  Trajectory decoded_trajectory;
  HeartbeatRecord decoded_heartbeat;
  const sdlqr::testing::AllocationCounter allocations;
  EXPECT_FALSE(decodeMessage(eventOf(bytes), &decoded_trajectory));
  EXPECT_FALSE(decodeMessage(eventOf(hb), &decoded_heartbeat));
  EXPECT_EQ(allocations.count(), 0);
  setInt32(hb, counters_at, 0xfffffffe);  // negative count
  EXPECT_FALSE(decodeMessage(eventOf(hb), &decoded_heartbeat));
}

// Every type: valid encodings fit, truncated or extended ones do not, and whatever fits after
// random corruption (fingerprint kept) decodes with LCM and consumes exactly its bytes.
TEST(WireCheck, AgreesWithTheLcmDecoderUnderCorruption) {
  test::RandomCells random(5);
  std::mt19937_64 rng(11);
  int64_t fitted = 0;
  int64_t rejected = 0;
  for (const ChannelType& channel : channelTypes()) {
    lcmtypes::visitLcmType(channel.lcm_type, [&](auto tag) {
      using LcmType = typename decltype(tag)::type;
      const lcmtypes::TypeDescriptor& descriptor = lcmtypes::LcmFields<LcmType>::type;
      const LcmType* type = nullptr;
      for (int round = 0; round < 200; ++round) {
        LcmType message;
        std::string error;
        ASSERT_TRUE(readCsvRow(random.make(descriptor), message, &error)) << error;
        std::vector<uint8_t> bytes = encode(message);
        ASSERT_TRUE(lcmtypes::encodingFits(type, bytes.data(), static_cast<int64_t>(bytes.size()))) << channel.lcm_type;
        const int64_t cut = static_cast<int64_t>(rng() % bytes.size());
        EXPECT_FALSE(lcmtypes::encodingFits(type, bytes.data(), cut)) << channel.lcm_type << " cut to " << cut;
        std::vector<uint8_t> longer = bytes;
        longer.push_back(0);
        EXPECT_FALSE(lcmtypes::encodingFits(type, longer.data(), static_cast<int64_t>(longer.size())));
        for (int flip = 0; flip < 3; ++flip) {
          bytes[8 + rng() % (bytes.size() - 8)] = static_cast<uint8_t>(rng());
        }
        if (lcmtypes::encodingFits(type, bytes.data(), static_cast<int64_t>(bytes.size()))) {
          ++fitted;
          LcmType back;
          EXPECT_EQ(back.decode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()))
              << channel.lcm_type;
        } else {
          ++rejected;
        }
      }
    });
  }
  std::cout << "[ figures  ] corrupted encodings: " << fitted << " still complete (and decoded), " << rejected
            << " rejected before decoding\n";
  EXPECT_GT(fitted, 0);
  EXPECT_GT(rejected, 0);
}

}  // namespace
}  // namespace sdlqr::logger
