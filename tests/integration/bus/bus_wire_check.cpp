// Node's own udpm receive path against LCM's publisher, over real multicast (run in a private
// network namespace): short and fragmented messages arrive byte for byte on several ports
// polled together, and a queue-capacity-1 subscription gets the first of a burst waiting, the
// others dropped (LCM's semantics).
//   bus_wire_check          exit 0 when every check passes

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"

#include "node_checks.hpp"

using namespace sdlqr;
using test::check;
using test::spinFor;

namespace {

// What the node under test received: every message raw (a recorder's subscription) and the seqs of
// a capacity-1 IMU subscription.
struct Received {
  std::vector<std::pair<std::string, std::vector<uint8_t>>> raw;
  std::vector<int64_t> imu_seqs;
};

void subscribe(bus::Node& node, Received& received) {
  node.subscribeRaw("BIG|SMALL|IMU", [&](const std::string& channel, const void* data, uint32_t size, int64_t) {
    const auto* bytes = static_cast<const uint8_t*>(data);
    received.raw.emplace_back(channel, std::vector<uint8_t>(bytes, bytes + size));
  }, 1000);
  node.subscribe<imu_t>(channel::kImu, [&](const imu_t& m) { received.imu_seqs.push_back(m.seq); }, 1);
}

void publishImu(lcm::LCM& port, int64_t seq, int64_t utime) {
  ImuSample s;
  s.utime = utime;
  s.seq = seq;
  const imu_t m = bus::toLcm(s);
  port.publish("IMU", &m);
}

void checkWholeMessages(bus::Node& node, lcm::LCM& base_port, const Received& received) {
  std::vector<uint8_t> big(300000);
  for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<uint8_t>(i * 7 + i / 251);
  const std::vector<uint8_t> small{1, 2, 3, 0, 5};
  base_port.publish("BIG", big.data(), static_cast<unsigned>(big.size()));
  base_port.publish("SMALL", small.data(), static_cast<unsigned>(small.size()));
  spinFor(node, 0.5);
  bool big_ok = false, small_ok = false;
  for (const auto& [channel, bytes] : received.raw) {
    if (channel == "BIG") big_ok = bytes == big;
    if (channel == "SMALL") small_ok = bytes == small;
  }
  check(big_ok, "a 300 kB message (LCM fragments) arrives byte for byte");
  check(small_ok, "a short message arrives byte for byte");
}

// A burst of 10 IMU samples waiting in one batch: the capacity-1 subscription gets the first; the
// 9 others are queue drops, and once seq 10 arrives, lost.
void checkImuBurst(bus::Node& node, lcm::LCM& imu_port, Received& received) {
  received.raw.clear();
  for (int64_t seq = 0; seq < 10; ++seq) publishImu(imu_port, seq, 1000 * (seq + 1));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  spinFor(node, 0.3);
  int raw_imu = 0;
  for (const auto& entry : received.raw) raw_imu += entry.first == "IMU" ? 1 : 0;
  const std::vector<int64_t>& imu_seqs = received.imu_seqs;
  check(raw_imu == 10, "the recorder's subscription (capacity 1000) got all 10 IMU, got " + std::to_string(raw_imu));
  check(imu_seqs.size() == 1 && imu_seqs.back() == 0,
        "the capacity-1 subscription got only the first IMU (seq 0), got " + std::to_string(imu_seqs.size()) +
            " message(s)" + (imu_seqs.empty() ? "" : ", last seq " + std::to_string(imu_seqs.back())));
  check(node.dropped() == 0, "no sequence gap before the first IMU is counted (dropped " +
                                 std::to_string(node.dropped()) + ")");
  auto counter = [&](const char* name) { return node.counters().value(node.counters().find(name)); };
  check(counter("queue_drop.IMU") == 9, "the 9 IMU over capacity count as queue_drop.IMU, got " +
                                            std::to_string(counter("queue_drop.IMU")));
  publishImu(imu_port, 10, 11000);
  spinFor(node, 0.3);
  check(counter("lost.IMU") == 9 && node.dropped() == 9,
        "seq 10 after seq 0: the 9 never handled count as lost.IMU, got " + std::to_string(counter("lost.IMU")));
}

// Why the split layout uses ports, not groups: a socket bound to INADDR_ANY:port gets the
// datagrams of every group joined on that port on the host (Linux IP_MULTICAST_ALL, default
// on). Reported as found; what the layout relies on, that another port stays silent, is checked.
void checkPortsNotGroups() {
  ProcessOptions a;
  a.lcm_url = "udpm://239.255.76.67:7690?ttl=0";
  a.bus_layout = "single";
  ProcessOptions b = a;
  b.lcm_url = "udpm://239.255.76.68:7690?ttl=0";
  ProcessOptions c = a;
  c.lcm_url = "udpm://239.255.76.68:7691?ttl=0";
  bus::Node group_a("group_a", a), group_b("group_b", b), other_port("other_port", c);
  int heard_a = 0, heard_b = 0, heard_other_port = 0;
  group_a.subscribeRaw("PROBE", [&](const std::string&, const void*, uint32_t, int64_t) { ++heard_a; }, 100);
  group_b.subscribeRaw("PROBE", [&](const std::string&, const void*, uint32_t, int64_t) { ++heard_b; }, 100);
  other_port.subscribeRaw("PROBE", [&](const std::string&, const void*, uint32_t, int64_t) { ++heard_other_port; }, 100);
  lcm::LCM to_group_b(b.lcm_url);
  const uint8_t probe[4] = {1, 2, 3, 4};
  for (int i = 0; i < 5; ++i) to_group_b.publish("PROBE", probe, sizeof probe);
  for (int i = 0; i < 20; ++i) {
    group_a.spin(5);
    group_b.spin(5);
    other_port.spin(5);
  }
  std::printf("fact: 5 datagrams to group 239.255.76.68:7690 reached its members %d times and a socket of "
              "group 239.255.76.67 on the same port %d times (IP_MULTICAST_ALL)\n", heard_b, heard_a);
  check(heard_b == 5, "the group's own member heard all 5");
  check(heard_other_port == 0, "a socket of the same group on another port heard none, heard " +
                                   std::to_string(heard_other_port));
}

// A process that does not read while its socket's buffer fills loses datagrams in the kernel:
// what it never got is counted as bus.kernel_dropped, exactly (received + dropped = sent).
void checkKernelDrops() {
  ProcessOptions slow;
  slow.lcm_url = "udpm://239.255.76.67:7700?ttl=0&recv_buf_size=65536";
  slow.bus_layout = "single";
  bus::Node reader("slow_reader", slow);
  int heard = 0;
  reader.subscribeRaw("FLOOD", [&](const std::string&, const void*, uint32_t, int64_t) { ++heard; }, 100000);
  lcm::LCM flood(slow.lcm_url);
  const std::vector<uint8_t> payload(1000, 7);
  constexpr int kSent = 3000;
  for (int i = 0; i < kSent; ++i) flood.publish("FLOOD", payload.data(), static_cast<unsigned>(payload.size()));
  spinFor(reader, 0.3);
  reader.publishHeartbeat();  // the counters are brought up to date with each heartbeat
  const int64_t kernel_dropped = reader.counters().value(reader.counters().find("bus.kernel_dropped"));
  std::printf("fact: %d messages into a 64 KiB receive buffer unread: %d heard, %lld dropped by the kernel\n", kSent,
              heard, static_cast<long long>(kernel_dropped));
  check(kernel_dropped > 0 && heard + kernel_dropped == kSent,
        "every message the unread socket lost counts as bus.kernel_dropped: heard " + std::to_string(heard) +
            " + kernel_dropped " + std::to_string(kernel_dropped) + " = " + std::to_string(kSent));
}

}  // namespace

int main() {
  const std::string base = "udpm://239.255.76.67:7667?ttl=0";
  ProcessOptions options;
  options.lcm_url = base;
  bus::Node node("bus_wire_check", options);
  Received received;
  subscribe(node, received);
  check(node.receiveUrls().size() == 8, "a recorder's subscription listens on the 8 ports of the split layout");

  // Plain LCM publishers, one per port, as another process would be.
  lcm::LCM base_port(base);
  lcm::LCM imu_port(bus::channelUrl(bus::BusLayout::kSplit, base, "IMU"));
  checkWholeMessages(node, base_port, received);
  checkImuBurst(node, imu_port, received);
  checkPortsNotGroups();
  checkKernelDrops();
  std::printf("%s\n", test::failedChecks() == 0 ? "PASS" : "FAIL");
  return test::failedChecks() == 0 ? 0 : 1;
}
