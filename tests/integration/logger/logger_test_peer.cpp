// Test peer of the sdlqr-logger integration test: publishes known messages on several channels
// over the bus (through the Node, as the flight processes do) and checks a recorded log
// against what was published.
//
//   logger_test_peer publish --count N --rate HZ --published FILE [--vehicle V] [--duration S]
//   logger_test_peer check LOG --published FILE [--vehicle V] [--before UTIME] [--logger-heartbeat]
//
// Every message carries utime = wall clock at publication [us] and contents that are a function
// of its seq, so the checker regenerates each expected message. FILE lists "channel seq utime"
// per published message (written when publishing ends).


#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>
#include <vector>

#include "sdlqr/messages/channels.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/wall_clock.hpp"

namespace {

using namespace sdlqr;

ImuSample imuFor(int64_t seq, int64_t utime) {
  ImuSample s;
  s.utime = utime;
  s.seq = seq;
  s.gyro = Vec3(1e-3 * static_cast<double>(seq), -static_cast<double>(seq), 0.5);
  s.accel = Vec3(0.0, 0.1, 9.81 + 1e-6 * static_cast<double>(seq));
  return s;
}
StateEstimate stateFor(int64_t seq, int64_t utime) {
  StateEstimate s;
  s.utime = utime;
  s.seq = seq;
  s.position = Vec3(0.01 * static_cast<double>(seq), 2.0, -1.0);
  s.imu_seq = 4 * seq;
  return s;
}
RateCommand rateFor(int64_t seq, int64_t utime) {
  RateCommand c;
  c.utime = utime;
  c.seq = seq;
  c.body_rate = Vec3(0.1, -0.2, 0.001 * static_cast<double>(seq));
  c.thrust = 9.81;
  c.state_seq = seq;
  return c;
}
GainSet gainsFor(int64_t seq, int64_t utime) {
  GainSet g;
  g.utime = utime;
  g.seq = seq;
  for (int k = 0; k < 40; ++k) g.K(k / 10, k % 10) = static_cast<double>(seq) + 0.01 * k;
  g.solve_us = 10.0 + static_cast<double>(seq);
  g.iterations = 13;
  return g;
}

struct Published {
  std::string channel;
  int64_t seq = 0;
  int64_t utime = 0;
};

int publish(int argc, const char* const* argv) {
  ProcessOptions process;
  int count = 0;
  double rate_hz = 500.0;
  double duration_s = 0.0;
  std::string published_path;
  ArgParser parser("logger_test_peer publish", "Publishes IMU every tick, STATE_EST every 4th, RATE_CMD every 5th, GAINS every 50th.");
  parser.addOption("--count", &count, "N", "ticks to publish (0: until --duration or a signal)");
  parser.addOption("--rate", &rate_hz, "HZ", "ticks per second");
  parser.addOption("--duration", &duration_s, "S", "stop after S seconds");
  parser.addOption("--published", &published_path, "FILE", "where to list what was published");
  parser.addOption("--lcm-url", &process.lcm_url, "URL", "LCM provider");
  addBusLayoutOption(parser, &process);
  parser.addOption("--vehicle", &process.vehicle, "PREFIX", "channel prefix");
  parser.parseOrExit(argc, argv);
  if (published_path.empty() || rate_hz <= 0.0) throw std::invalid_argument("need --published FILE and --rate > 0");

  bus::Node node("logger_test_peer", process);
  node.setState(bus::ProcessState::kRunning);
  std::vector<Published> published;
  auto note = [&](std::string_view base, int64_t seq, int64_t utime) {
    published.push_back({node.channel(base), seq, utime});
  };
  const auto period = std::chrono::duration<double>(1.0 / rate_hz);
  const auto start = std::chrono::steady_clock::now();
  for (int64_t tick = 0; count == 0 || tick < count; ++tick) {
    std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(period * tick));
    if (!node.spin(0)) break;
    if (duration_s > 0.0 && std::chrono::steady_clock::now() - start >= std::chrono::duration<double>(duration_s)) break;
    const int64_t utime = bus::realtimeUtime();
    node.publish(channel::kImu, bus::toLcm(imuFor(tick, utime)));
    note(channel::kImu, tick, utime);
    if (tick % 4 == 0) {
      node.publish(channel::kStateEstimate, bus::toLcm(stateFor(tick / 4, utime)));
      note(channel::kStateEstimate, tick / 4, utime);
    }
    if (tick % 5 == 0) {
      node.publish(channel::kRateCommand, bus::toLcm(rateFor(tick / 5, utime)));
      note(channel::kRateCommand, tick / 5, utime);
    }
    if (tick % 50 == 0) {
      node.publish(channel::kGains, bus::toLcm(gainsFor(tick / 50, utime)));
      note(channel::kGains, tick / 50, utime);
    }
  }
  std::ofstream out(published_path);
  for (const Published& p : published) out << p.channel << " " << p.seq << " " << p.utime << "\n";
  std::cout << "logger_test_peer: published " << published.size() << " messages" << std::endl;
  return 0;
}

template <class T>
bool equalEncoding(const T& a, const T& b) {
  const auto la = bus::toLcm(a);
  const auto lb = bus::toLcm(b);
  std::vector<uint8_t> ea(static_cast<size_t>(la.getEncodedSize()));
  std::vector<uint8_t> eb(static_cast<size_t>(lb.getEncodedSize()));
  la.encode(ea.data(), 0, static_cast<int>(ea.size()));
  lb.encode(eb.data(), 0, static_cast<int>(eb.size()));
  return ea == eb;
}

// Checks one channel: every required message is in the log with exactly the expected contents.
template <class T, class Make>
bool checkSeries(const std::string& name, const logger::Series<T>& series, const std::vector<Published>& published,
                 int64_t before, Make make) {
  std::map<int64_t, const T*> logged;
  for (const T& m : series.messages) logged[m.seq] = &m;
  int64_t required = 0;
  int64_t required_present = 0;
  int64_t later = 0;
  int64_t later_present = 0;
  bool ok = true;
  for (const Published& p : published) {
    const auto it = logged.find(p.seq);
    const bool present = it != logged.end();
    if (present && !equalEncoding(*it->second, make(p.seq, p.utime))) {
      std::cerr << "FAIL " << name << " seq " << p.seq << ": contents differ\n";
      ok = false;
    }
    if (before == 0 || p.utime < before) {
      ++required;
      required_present += present ? 1 : 0;
      if (!present && ok) std::cerr << "FAIL " << name << " seq " << p.seq << " (utime " << p.utime << ") missing\n";
      ok = ok && present;
    } else {
      ++later;
      later_present += present ? 1 : 0;
    }
  }
  std::cout << "  " << name << ": " << required_present << "/" << required << " required present";
  if (before != 0) std::cout << "; of the " << later << " published in the last second, " << later_present << " recorded";
  std::cout << "; decode failures " << series.decode_failures << "\n";
  return ok && series.decode_failures == 0 && static_cast<int64_t>(logged.size()) == static_cast<int64_t>(series.size());
}

int check(int argc, const char* const* argv) {
  std::vector<std::string> positional;
  std::string published_path;
  std::string vehicle;
  long long before = 0;
  bool logger_heartbeat = false;
  ArgParser parser("logger_test_peer check", "Checks a recorded log against a publish list.");
  parser.allowPositional(&positional, "LOG");
  parser.addOption("--published", &published_path, "FILE", "publish list of `publish`");
  parser.addOption("--vehicle", &vehicle, "PREFIX", "vehicle of the published channels");
  parser.addOption("--before", &before, "UTIME", "require only messages published before this wall time [us]");
  parser.addFlag("--logger-heartbeat", &logger_heartbeat, "require sdlqr-logger's final STOPPING heartbeat, no drops");
  parser.parseOrExit(argc, argv);
  if (positional.size() != 1 || published_path.empty()) throw std::invalid_argument("need LOG and --published FILE");

  std::map<std::string, std::vector<Published>> published;
  std::ifstream in(published_path);
  Published p;
  while (in >> p.channel >> p.seq >> p.utime) published[p.channel].push_back(p);
  if (published.empty()) throw std::invalid_argument("empty publish list " + published_path);

  const logger::FlightLog log = logger::FlightLog::load(positional[0], vehicle);
  std::cout << "log: " << log.file.events << " events, " << log.file.file_bytes << " bytes, truncated tail "
            << log.file.truncated_tail_bytes << " bytes, skipped " << log.file.skipped_bytes << "\n";
  const auto listOf = [&](std::string_view base) { return published[channel::name(vehicle, base)]; };
  bool ok = true;
  ok &= checkSeries("IMU", log.imu, listOf(channel::kImu), before, imuFor);
  ok &= checkSeries("STATE_EST", log.state_estimate, listOf(channel::kStateEstimate), before, stateFor);
  ok &= checkSeries("RATE_CMD", log.rate_command, listOf(channel::kRateCommand), before, rateFor);
  ok &= checkSeries("GAINS", log.gains, listOf(channel::kGains), before, gainsFor);
  if (logger_heartbeat) {
    const logger::HeartbeatRecord* last = nullptr;
    int count = 0;
    for (const logger::HeartbeatRecord& h : log.heartbeat.messages) {
      if (h.process == "sdlqr-logger") {
        last = &h;
        ++count;
      }
    }
    if (!last) {
      std::cerr << "FAIL no sdlqr-logger heartbeat in the log\n";
      ok = false;
    } else {
      std::cout << "  sdlqr-logger heartbeats: " << count << ", last state " << logger::processStateName(last->state)
                << ", received " << last->received << ", dropped " << last->dropped << "\n";
      if (last->state != static_cast<int8_t>(bus::ProcessState::kStopping) || last->dropped != 0) {
        std::cerr << "FAIL sdlqr-logger's last heartbeat is not a clean STOPPING one\n";
        ok = false;
      }
    }
  }
  std::cout << (ok ? "PASS" : "FAIL") << std::endl;
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return sdlqr::runMain("logger_test_peer", [&]() {
    const std::string mode = argc >= 2 ? argv[1] : "";
    if (mode == "publish") return publish(argc - 1, argv + 1);
    if (mode == "check") return check(argc - 1, argv + 1);
    const bool help = mode == "--help" || mode == "-h";
    (help ? std::cout : std::cerr) << "usage: logger_test_peer publish|check ... (--help on each)\n";
    return help ? 0 : 2;
  });
}
