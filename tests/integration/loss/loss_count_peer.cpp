// Publishes N IMU samples (seq 0..N-1) on the split bus's IMU port and receives them with a
// Node, as a flight process would; prints the Node's per-channel loss counters. The test around
// it (loss_count.sh) drops packets in the kernel with nftables and compares the counts.
//   loss_count_peer N      prints "lost.IMU=<n> queue_drop.IMU=<n> handled=<n> first=<seq> last=<seq>"
//   loss_count_peer port   prints the IMU channel's UDP port

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"

using namespace sdlqr;

int main(int argc, char** argv) {
  const std::string imu_url = bus::channelUrl(bus::BusLayout::kSplit, bus::resolveLcmUrl(""), "IMU");
  if (argc == 2 && std::string(argv[1]) == "port") {
    std::printf("%d\n", bus::parseUdpmUrl(imu_url).port);
    return 0;
  }
  if (argc != 2 || std::atoi(argv[1]) <= 0) {
    std::fprintf(stderr, "usage: loss_count_peer N\n");
    return 2;
  }
  const int count = std::atoi(argv[1]);
  ProcessOptions options;
  bus::Node receiver("loss_count_peer", options);
  int64_t handled = 0, first = -1, last = -1;
  receiver.subscribe<imu_t>(channel::kImu, [&](const imu_t& m) {
    ++handled;
    if (first < 0) first = m.seq;
    last = m.seq;
  }, 1000);
  lcm::LCM sender(imu_url);
  for (int seq = 0; seq < count; ++seq) {
    ImuSample s;
    s.utime = 1000 * (seq + 1);
    s.seq = seq;
    const imu_t m = bus::toLcm(s);
    sender.publish("IMU", &m);
    receiver.spin(0);
    std::this_thread::sleep_for(std::chrono::microseconds(200));  // no queue overflow: loss only
  }
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  while (std::chrono::steady_clock::now() < end) receiver.spin(5);
  const Counters& c = receiver.counters();
  std::printf("lost.IMU=%lld queue_drop.IMU=%lld handled=%lld first=%lld last=%lld\n",
              static_cast<long long>(c.value(c.find("lost.IMU"))), static_cast<long long>(c.value(c.find("queue_drop.IMU"))),
              static_cast<long long>(handled), static_cast<long long>(first), static_cast<long long>(last));
  return 0;
}
