// sdlqr-fuzz-publisher: a hostile publisher for fault tests. On every channel of one vehicle, at
// --rate messages per second per channel, it sends in turn random bytes, truncated, oversized and
// wrong-fingerprint encodings, valid encodings with NaN/Inf or huge doubles, and messages it heard
// on the bus --replay-age seconds earlier (old timestamps). Never use it on a bus that flies.

#include <chrono>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/faults/fuzz_messages.hpp"
#include "sdlqr/faults/replay_source.hpp"
#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/bus/node.hpp"

using namespace sdlqr;

namespace {

struct Target {
  explicit Target(double replay_age_s) : replay(replay_age_s) {}
  std::string channel;
  const lcmtypes::TypeDescriptor* type = nullptr;
  std::vector<uint8_t> latest;  // newest valid encoding heard (or a default one)
  faults::ReplaySource replay;  // one heard replay_age to twice that ago
};

std::vector<uint8_t> defaultEncoding(std::string_view lcm_type) {
  std::vector<uint8_t> bytes;
  lcmtypes::visitLcmType(lcm_type, [&](auto tag) {
    typename decltype(tag)::type message{};
    bytes.resize(static_cast<size_t>(message.getEncodedSize()));
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  });
  return bytes;
}

// Every channel of the vehicle but those in skip_text (comma-separated bases), each with a
// default encoding until one is heard.
std::vector<Target> makeTargets(bus::Node& bus, const std::string& skip_text, double replay_age) {
  std::vector<Target> targets;
  for (const logger::ChannelType& channel : logger::channelTypes()) {
    if (("," + skip_text + ",").find("," + std::string(channel.base) + ",") != std::string::npos) continue;
    Target target(replay_age);
    target.channel = bus.channel(channel.base);
    target.type = lcmtypes::findType(channel.lcm_type);
    target.latest = defaultEncoding(channel.lcm_type);
    if (target.type == nullptr || target.latest.empty()) continue;
    targets.push_back(std::move(target));
  }
  return targets;
}

void printSent(bus::Node& bus, const bus::Counters::Id (&sent_ids)[faults::kFuzzKindCount], double seconds) {
  std::cout << "sdlqr-fuzz-publisher: sent";
  for (int k = 0; k < faults::kFuzzKindCount; ++k) {
    std::cout << " " << faults::toString(static_cast<faults::FuzzKind>(k)) << "=" << bus.counters().value(sent_ids[k]);
  }
  std::cout << " in " << seconds << " s\n";
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-fuzz-publisher", [&] {
    ProcessOptions options;
    double duration = 10.0, rate = 1000.0, replay_age = 1.0;
    long long seed = 1;
    std::string skip_text = "SIM_TRUTH";
    ArgParser parser("sdlqr-fuzz-publisher",
                     "Floods every channel of a vehicle with malformed, out-of-range and replayed messages (fault\n"
                     "tests; see SECURITY.md). Kinds, in turn per channel: random_bytes, truncated, oversized,\n"
                     "wrong_fingerprint, nonfinite, huge, replayed. Counts per kind in HEARTBEAT (fuzz.sent.*).");
    parser.addOption("--duration", &duration, "S", "seconds of wall time to send for (default 10)", Range::openClosed(0, 3600));
    parser.addOption("--rate", &rate, "HZ", "messages per second on each channel (default 1000)", Range::openClosed(0, 20000));
    parser.addOption("--replay-age", &replay_age, "S", "age of the replayed messages (default 1)", Range::openClosed(0, 60));
    parser.addOption("--seed", &seed, "N", "random seed (default 1)", Range::atLeast(0));
    parser.addOption("--skip", &skip_text, "A,B",
                     "channels left alone (default SIM_TRUTH: the simulator's measurement for tests,\n"
                     "                          read by no flight process; forging it corrupts only the test's own figures)");
    addProcessOptions(parser, &options);
    parser.setEpilog("exit codes: 0 done or stopped by SIGINT/SIGTERM, 1 runtime failure, 2 bad option");
    parser.parseOrExit(argc, argv);

    bus::Node bus("sdlqr-fuzz-publisher", options);
    std::vector<Target> targets = makeTargets(bus, skip_text, replay_age);
    bus::Counters::Id sent_ids[faults::kFuzzKindCount];
    for (int k = 0; k < faults::kFuzzKindCount; ++k) {
      sent_ids[k] = bus.counters().add(std::string("fuzz.sent.") + faults::toString(static_cast<faults::FuzzKind>(k)));
    }
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    for (size_t i = 0; i < targets.size(); ++i) {
      Target* target = &targets[i];
      bus.subscribeRaw("^" + target->channel + "$", [target, &seconds](const std::string&, const void* data,
                                                                   uint32_t size, int64_t) {
        const auto* bytes = static_cast<const uint8_t*>(data);
        target->latest.assign(bytes, bytes + size);
        target->replay.heard(bytes, size, seconds());
      }, 64);
    }

    faults::FuzzGenerator generator(static_cast<uint64_t>(seed));
    std::vector<uint8_t> out;
    const auto period = std::chrono::duration<double>(1.0 / rate);
    int64_t round = 0;
    bus.setState(bus::ProcessState::kRunning);
    std::cerr << "sdlqr-fuzz-publisher: " << targets.size() << " channels at " << rate << " Hz each for " << duration
              << " s\n";
    while (bus.running() && seconds() < duration) {
      for (size_t i = 0; i < targets.size(); ++i) {
        Target& target = targets[i];
        const auto kind = static_cast<faults::FuzzKind>((round + static_cast<int64_t>(i)) % faults::kFuzzKindCount);
        const std::vector<uint8_t>* source = &target.latest;
        if (kind == faults::FuzzKind::kReplayed) {
          // A replay needs a message at least replay_age old; until then nothing is sent for it.
          source = target.replay.replayable(seconds());
          if (source == nullptr) continue;
        }
        if (!generator.make(kind, *target.type, *source, out)) continue;
        bus.publishEncoded(target.channel, out.data(), static_cast<int>(out.size()));
        bus.counters().increment(sent_ids[static_cast<int>(kind)]);
      }
      ++round;
      const auto next = start + std::chrono::duration_cast<Clock::duration>(round * period);
      // At least one spin a round: behind schedule, the heartbeat must still go out.
      do {
        const int wait_ms = static_cast<int>(std::chrono::duration<double, std::milli>(next - Clock::now()).count());
        bus.spin(std::max(0, wait_ms));
      } while (bus.running() && Clock::now() < next);
    }
    printSent(bus, sent_ids, seconds());
    bus.shutdown();
    return 0;
  });
}
