// The LCM side of every process over LCM's in-process memq:// provider (no network): typed
// decoding, reject counting, sequence-gap counting, vehicle prefixes, and no heap allocation by
// our code per message once running (the 1 kHz and 100 Hz paths).

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <unistd.h>

#include "allocation_counter.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "bus_test_helpers.hpp"


namespace sdlqr::bus {
namespace {

using test::keyOf;
using test::memq;

state_estimate_t estimate(int64_t seq) {
  StateEstimate s;
  s.utime = seq * 4000;
  s.seq = seq;
  s.position = Vec3(1.0, 2.0, 3.0);
  s.status = EstimatorStatus::kOk;
  return toLcm(s);
}

TEST(Node, DeliversDecodedMessagesOnThePrefixedChannel) {
  Node node("test", memq("QUAD7"));
  int received = 0;
  Vec3 position = Vec3::Zero();
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t& m) {
    ++received;
    position = fromLcm(m).position;
  }, 8);
  EXPECT_EQ(node.channel(channel::kStateEstimate), "QUAD7/STATE_EST");
  node.publish(channel::kStateEstimate, estimate(0));
  node.lcm().publish("STATE_EST", "not for this vehicle", 20);  // unprefixed: another stack
  node.spin(0);
  node.spin(0);
  EXPECT_EQ(received, 1);
  EXPECT_EQ(position, Vec3(1.0, 2.0, 3.0));
}

TEST(Node, UndecodableMessagesAreCountedAndNeverReachTheHandler) {
  Node node("test", memq());
  int received = 0;
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t&) { ++received; }, 8);
  const char garbage[] = "definitely not a state estimate";
  node.lcm().publish("STATE_EST", garbage, sizeof garbage);
  node.spin(0);
  EXPECT_EQ(received, 0);
  EXPECT_EQ(node.rejected(), 1);
  EXPECT_EQ(node.received(), 1);
}

TEST(Node, SequenceGapsCountAsDropped) {
  Node node("test", memq());
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [](const state_estimate_t&) {}, 16);
  for (int64_t seq : {0, 1, 2, 6, 7}) {  // 3, 4, 5 lost
    node.publish(channel::kStateEstimate, estimate(seq));
    node.spin(0);
  }
  EXPECT_EQ(node.dropped(), 3);
  node.publish(channel::kStateEstimate, estimate(0));  // a restarted publisher: no loss counted
  node.spin(0);
  EXPECT_EQ(node.dropped(), 3);
}

TEST(Node, PublishingAndHandlingAllocateNothingOnceRunning) {
  Node node("test", memq("QUAD_WITH_A_LONG_NAME"));
  int64_t last_seq = -1;
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t& m) { last_seq = m.seq; }, 1);
  node.subscribe<rate_cmd_t>(channel::kRateCommand, [&](const rate_cmd_t&) {}, 1);
  state_estimate_t message = estimate(0);
  rate_cmd_t command{};
  for (int64_t seq = 0; seq < 10; ++seq) {  // warm-up: channel names, heartbeat, buffers
    message.seq = seq;
    node.publish(channel::kStateEstimate, message);
    node.publish(channel::kRateCommand, command);
    node.spin(0);
  }
  const long before = sdlqr::testing::allocationCount();
  for (int64_t seq = 10; seq < 1010; ++seq) {
    message.seq = seq;
    node.publish(channel::kStateEstimate, message);
    command.seq = seq;
    node.publish(channel::kRateCommand, command);
    while (node.lcm().handleTimeout(0) > 0) {
    }
  }
  const long allocations = sdlqr::testing::allocationCount() - before;
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(last_seq, 1009);
}

TEST(Node, AHandlerOverItsBudgetCountsADeadlineMiss) {
  Node node("test", memq());
  bool slow = false;
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t&) {
    if (slow) std::this_thread::sleep_for(std::chrono::milliseconds(3));
  }, 8, std::chrono::microseconds(1000));
  node.subscribe<rate_cmd_t>(channel::kRateCommand, [](const rate_cmd_t&) {
    std::this_thread::sleep_for(std::chrono::milliseconds(3));  // no budget: never counted
  }, 8);
  for (int64_t seq = 0; seq < 3; ++seq) {
    node.publish(channel::kStateEstimate, estimate(seq));
    node.spin(0);
  }
  rate_cmd_t command{};
  node.publish(channel::kRateCommand, command);
  node.spin(0);
  EXPECT_EQ(node.deadlineMisses(), 0);
  slow = true;
  node.publish(channel::kStateEstimate, estimate(3));
  node.spin(0);
  EXPECT_EQ(node.deadlineMisses(), 1);
}

TEST(Node, WithoutPortsEveryLayoutIsOneConnection) {
  // GIVEN the split layout asked for on memq:// (no ports to separate channels)
  ProcessOptions options = memq();
  options.bus_layout = "split";
  Node node("test", options);
  EXPECT_EQ(node.busLayout(), BusLayout::kSingle);
  int imu = 0, gains = 0;
  node.subscribe<imu_t>(channel::kImu, [&](const imu_t&) { ++imu; });
  node.subscribe<gains_t>(channel::kGains, [&](const gains_t&) { ++gains; });
  int raw = 0;
  node.subscribeRaw("IMU|GAINS", [&](const std::string&, const void*, uint32_t, int64_t) { ++raw; }, 16);
  // THEN it receives on the one URL, and publishEncoded() delivers there
  EXPECT_EQ(node.receiveUrls(), std::vector<std::string>{"memq://"});
  imu_t m = toLcm(ImuSample{});
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  node.publishEncoded("IMU", bytes.data(), static_cast<int>(bytes.size()));
  node.publish(channel::kGains, toLcm(GainSet{}));
  for (int i = 0; i < 8; ++i) node.spin(0);
  EXPECT_EQ(imu, 1);
  EXPECT_EQ(gains, 1);
  EXPECT_EQ(raw, 2);
}

TEST(Node, ABadLayoutNameIsAnOptionError) {
  ProcessOptions options;
  options.lcm_url = "udpm://239.255.76.67:7667?ttl=0";
  options.bus_layout = "both";
  EXPECT_THROW(Node("test", options), std::invalid_argument);
}

}  // namespace
}  // namespace sdlqr::bus

namespace sdlqr::bus {
namespace {

// A MAVLink link beside the bus (px4/link_binding.hpp): the node's own loop waits on its descriptor
// and hands it over when readable, nothing otherwise.
TEST(Node, AWatchedDescriptorIsHandledInTheSameLoop) {
  Node node("test", test::memq());
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  int calls = 0;
  node.watchDescriptor(fds[0], [&] {
    char byte;
    ASSERT_EQ(read(fds[0], &byte, 1), 1);
    ++calls;
  });
  node.spin(0);
  EXPECT_EQ(calls, 0);
  ASSERT_EQ(write(fds[1], "x", 1), 1);
  EXPECT_TRUE(node.waitReadable(std::chrono::milliseconds(100)));
  node.spin(0);
  EXPECT_EQ(calls, 1);
  for (int i = 0; i < 3; ++i) node.watchDescriptor(fds[0], [] {});
  EXPECT_THROW(node.watchDescriptor(fds[0], [] {}), std::invalid_argument);  // four at most
  close(fds[0]);
  close(fds[1]);
}

}  // namespace
}  // namespace sdlqr::bus
