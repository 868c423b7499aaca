// A signed Node's udpm receive path over real multicast (run in a private network namespace):
// messages refused for their signature take no place in a subscription's queue, so a burst of
// unsigned RATE_CMD ahead of the controller's signed one cannot crowd it out of a capacity-1
// queue; the capacity still holds for signed messages (the second of two is dropped).
//   signed_queue_check      exit 0 when every check passes

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"

#include "node_checks.hpp"

using namespace sdlqr;
using test::check;
using test::spinFor;

namespace {

std::vector<uint8_t> encoded(int64_t seq) {
  RateCommand command;
  command.seq = seq;
  const rate_cmd_t message = bus::toLcm(command);
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()) + bus::kSignatureSize);
  message.encode(bytes.data(), 0, message.getEncodedSize());
  return bytes;
}

uint64_t now() {
  return bus::signatureTime(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count());
}

}  // namespace

int main() {
  const std::string base = "udpm://239.255.76.67:7667?ttl=0";
  ProcessOptions options;
  options.lcm_url = base;
  bus::BusKey key;
  key.bytes.fill(0x5a);
  bus::Node node("signed_queue_check", options);
  node.setBusKey(key);
  std::vector<int64_t> handled;
  node.subscribe<rate_cmd_t>(channel::kRateCommand, [&](const rate_cmd_t& m) { handled.push_back(m.seq); }, 1);
  lcm::LCM port(bus::channelUrl(bus::BusLayout::kSplit, base, "RATE_CMD"));
  const bus::BusSigner signer(key);

  // A burst waiting at once: 20 unsigned, then the signed one.
  for (int64_t seq = 100; seq < 120; ++seq) {
    const std::vector<uint8_t> bytes = encoded(seq);
    port.publish("RATE_CMD", bytes.data(), static_cast<unsigned>(bytes.size() - bus::kSignatureSize));
  }
  std::vector<uint8_t> good = encoded(1);
  signer.sign("RATE_CMD", good.data(), good.size() - bus::kSignatureSize, {77, now()});
  port.publish("RATE_CMD", good.data(), static_cast<unsigned>(good.size()));
  spinFor(node, 0.3);
  check(handled == std::vector<int64_t>{1}, "the signed RATE_CMD behind 20 unsigned ones reaches the handler");
  check(node.health().counter("reject.rate_cmd.unsigned") == 20, "the 20 unsigned ones are counted as unsigned");

  // Two signed ones at once: the capacity-1 queue keeps the first, as without signing.
  handled.clear();
  for (int64_t seq : {2, 3}) {
    std::vector<uint8_t> bytes = encoded(seq);
    signer.sign("RATE_CMD", bytes.data(), bytes.size() - bus::kSignatureSize, {77, now() + static_cast<uint64_t>(seq)});
    port.publish("RATE_CMD", bytes.data(), static_cast<unsigned>(bytes.size()));
  }
  spinFor(node, 0.3);
  check(handled == std::vector<int64_t>{2}, "of two signed ones waiting, a capacity-1 queue takes the first");
  check(node.health().counter("queue_drop.RATE_CMD") == 1, "and drops the second (queue_drop.RATE_CMD)");
  std::printf("%s\n", test::failedChecks() == 0 ? "PASS" : "FAILED");
  return test::failedChecks() == 0 ? 0 : 1;
}
