// The hostile inputs of tests/support/hostile_inputs.hpp on the real bus, and the check of what
// each path counted for them:
//   hostile_peer attack --copies FILE [--at S] [--lcm-url URL]   waits for the flight (simulation
//       time >= S), publishes the set from what it heard, then reads every process's HEARTBEAT.
//       A copy the receiver dropped on arrival (its one-message queue still held a newer message:
//       a busy machine) is no rejection, so an input with a rejection not counted yet is sent
//       again, rebuilt from the newest messages, up to 8 times. Writes the copies sent of
//       each input to FILE; exit 0 when each expected rejection is counted at least once and at
//       most once per copy (printed either way)
//   hostile_peer check-replay FILE --copies FILE   the same check on sdlqr-replay's output
//       ("rejections P: ..."): the log holds every copy, so each is counted once per copy

#include <algorithm>
#include <array>
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hostile_inputs.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/heartbeat_t.hpp"

using namespace sdlqr;

namespace {

using CounterTable = std::map<std::string, std::map<std::string, int64_t>>;  // process -> name -> value
using Copies = std::array<int64_t, static_cast<size_t>(testing::Hostile::kCount)>;

std::vector<std::string> mismatchesOf(const CounterTable& table, testing::Path path, const Copies& copies) {
  return testing::rejectionMismatches(
      [&](const std::string& process, const std::string& counter) -> int64_t {
        const auto p = table.find(process);
        if (p == table.end()) return -1;
        const auto c = p->second.find(counter);
        return c == p->second.end() ? 0 : c->second;
      },
      path, [&](testing::Hostile h) { return copies[static_cast<size_t>(h)]; });
}

int report(const CounterTable& table, testing::Path path, const char* path_name, const Copies& copies) {
  const auto mismatches = mismatchesOf(table, path, copies);
  for (const testing::ExpectedRejection& row : testing::expectedRejections()) {
    if (!row.on(path)) continue;
    const auto p = table.find(row.process);
    const int64_t value = p == table.end() ? -1 : (p->second.count(row.counter) ? p->second.at(row.counter) : 0);
    std::cout << path_name << ": " << row.process << " " << row.counter << " = " << value << "\n";
  }
  for (const std::string& m : mismatches) std::cout << path_name << ": MISMATCH " << m << "\n";
  std::cout << path_name << ": " << (mismatches.empty() ? "every hostile input rejected as expected" : "FAILED") << "\n";
  return mismatches.empty() ? 0 : 1;
}

void writeCopies(const std::string& path, const Copies& copies) {
  std::ofstream out(path);
  for (size_t i = 0; i < copies.size(); ++i) {
    out << testing::nameOf(static_cast<testing::Hostile>(i)) << " " << copies[i] << "\n";
  }
  if (!out) throw std::runtime_error(path + ": cannot write");
}

Copies readCopies(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read");
  Copies copies{};
  std::string name;
  int64_t count = 0;
  while (in >> name >> count) {
    for (size_t i = 0; i < copies.size(); ++i) {
      if (name == testing::nameOf(static_cast<testing::Hostile>(i))) copies[i] = count;
    }
  }
  return copies;
}

// Sends the inputs of `wanted` once each, built from the newest messages heard.
void publishSet(bus::Node& node, const testing::HeardMessages& heard, const std::vector<bool>& wanted, Copies* copies) {
  using testing::Hostile;
  const testing::HostileInputs h = testing::makeHostileInputs(heard);
  auto send = [&](Hostile which, auto&& publish) {
    if (!wanted[static_cast<size_t>(which)]) return;
    publish();
    ++(*copies)[static_cast<size_t>(which)];
  };
  send(Hostile::kFarFutureEstimate, [&] { node.publish(channel::kStateEstimate, bus::toLcm(h.far_future_estimate)); });
  send(Hostile::kDestabilizingGains, [&] { node.publish(channel::kGains, bus::toLcm(h.destabilizing_gains)); });
  send(Hostile::kReplayedCommand, [&] { node.publish(channel::kCommand, bus::toLcm(h.replayed_command)); });
  send(Hostile::kNanParams, [&] { node.publish(channel::kParams, bus::toLcm(h.nan_params)); });
  send(Hostile::kNanImu, [&] { node.publish(channel::kImu, bus::toLcm(h.nan_imu)); });
  send(Hostile::kFutureRateCommand, [&] { node.publish(channel::kRateCommand, bus::toLcm(h.future_rate_command)); });
  send(Hostile::kNanMotorCommand, [&] { node.publish(channel::kMotorCommand, bus::toLcm(h.nan_motor_command)); });
  send(Hostile::kNanReference, [&] { node.publish(channel::kReference, bus::toLcm(h.nan_reference)); });
  send(Hostile::kTruncatedGains, [&] {
    const gains_t truncated = bus::toLcm(heard.gains);
    std::vector<uint8_t> bytes(static_cast<size_t>(truncated.getEncodedSize()));
    truncated.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    node.lcm().publish(node.channel(channel::kGains), bytes.data(), static_cast<unsigned>(bytes.size() - 8));
  });
}

// The inputs with a bus rejection not counted yet.
std::vector<bool> uncounted(const CounterTable& table) {
  std::vector<bool> wanted(static_cast<size_t>(testing::Hostile::kCount), false);
  for (const testing::ExpectedRejection& row : testing::expectedRejections()) {
    const auto p = table.find(row.process);
    const bool counted = p != table.end() && p->second.count(row.counter) > 0 && p->second.at(row.counter) > 0;
    if (!counted) wanted[static_cast<size_t>(row.input)] = true;
  }
  return wanted;
}

int attack(int argc, const char* const* argv) {
  ProcessOptions options;
  double at_s = 5.0, listen_s = 2.5;
  std::string copies_path;
  ArgParser parser("hostile_peer attack", "Publishes the hostile set mid-flight and checks the HEARTBEAT counters.");
  parser.addOption("--at", &at_s, "S", "simulation time to attack at (default 5)");
  parser.addOption("--listen", &listen_s, "S", "wall seconds of HEARTBEAT to read afterwards (default 2.5)");
  parser.addOption("--lcm-url", &options.lcm_url, "URL", "LCM provider");
  parser.addOption("--copies", &copies_path, "FILE", "where to write the copies sent of each input (required)");
  parser.parseOrExit(argc, argv);
  if (copies_path.empty()) throw std::invalid_argument("--copies: required");

  bus::Node node("hostile-peer", options);
  testing::HeardMessages heard;
  int heard_mask = 0;
  auto hear = [&](int bit, auto& slot) {
    return [&, bit](const auto& m) {
      slot = bus::fromLcm(m);
      heard_mask |= bit;
    };
  };
  node.subscribe<state_estimate_t>(channel::kStateEstimate, hear(1, heard.estimate));
  node.subscribe<gains_t>(channel::kGains, hear(2, heard.gains));
  node.subscribe<command_t>(channel::kCommand, hear(4, heard.command), 16);
  node.subscribe<imu_t>(channel::kImu, hear(8, heard.imu));
  node.subscribe<reference_t>(channel::kReference, hear(16, heard.reference));
  node.subscribe<rate_cmd_t>(channel::kRateCommand, hear(32, heard.rate_command));
  node.subscribe<motor_cmd_t>(channel::kMotorCommand, hear(64, heard.motor_command));
  CounterTable table;
  node.subscribe<heartbeat_t>(channel::kHeartbeat, [&](const heartbeat_t& hb) {
    auto& counters = table[hb.process];
    for (int i = 0; i < hb.num_counters; ++i) counters[hb.counter_names[i]] = hb.counter_values[i];
  }, 64);

  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (node.spin(10) && !(heard_mask == 127 && heard.estimate.utime >= static_cast<int64_t>(at_s * 1e6))) {
    if (std::chrono::steady_clock::now() > give_up) {
      std::cout << "attack: no flight heard (mask " << heard_mask << ")\n";
      return 1;
    }
  }
  Copies copies{};
  publishSet(node, heard, std::vector<bool>(copies.size(), true), &copies);
  std::cout << "attack: published the hostile set at t=" << 1e-6 * static_cast<double>(heard.estimate.utime) << " s\n";
  table.clear();  // heartbeats from after the attack only
  constexpr int kMaxCopies = 8;
  for (int round = 1;; ++round) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(listen_s);
    while (node.spin(20) && std::chrono::steady_clock::now() < until) {
    }
    const std::vector<bool> wanted = uncounted(table);
    if (round >= kMaxCopies || std::none_of(wanted.begin(), wanted.end(), [](bool w) { return w; })) break;
    for (size_t i = 0; i < wanted.size(); ++i) {
      if (wanted[i]) std::cout << "attack: no rejection of " << testing::nameOf(static_cast<testing::Hostile>(i)) << " yet: sending it again\n";
    }
    publishSet(node, heard, wanted, &copies);
  }
  writeCopies(copies_path, copies);
  return report(table, testing::Path::kBus, "bus", copies);
}

// Lines "rejections sdlqr-controller: reject.gains.unstable=1 reject...=1".
int checkReplay(const std::string& path, const std::string& copies_path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read");
  CounterTable table;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("rejections ", 0) != 0) continue;
    const auto colon = line.find(':');
    auto& counters = table[line.substr(11, colon - 11)];
    std::istringstream items(line.substr(colon + 1));
    std::string item;
    while (items >> item) {
      const auto eq = item.find('=');
      counters[item.substr(0, eq)] = std::stoll(item.substr(eq + 1));
    }
  }
  return report(table, testing::Path::kReplay, "replay", readCopies(copies_path));
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("hostile_peer", [&] {
    const std::string mode = argc >= 2 ? argv[1] : "";
    if (mode == "attack") return attack(argc - 1, argv + 1);
    if (mode == "check-replay" && argc == 5 && std::string(argv[3]) == "--copies") return checkReplay(argv[2], argv[4]);
    const char* usage = "usage: hostile_peer attack --copies FILE [--at S] | hostile_peer check-replay FILE --copies FILE";
    if (mode == "--help" || mode == "-h") {
      std::cout << usage << "\n";
      return 0;
    }
    throw std::invalid_argument(usage);
  });
}
