// sdlqr-calibrate: measures what this machine's bus costs, just before a flight on the same bus,
// so the flight's CPU and latency can be judged against this machine rather than against ours.
// A forked child answers each 1 kHz ping with a pong; the parent times the round trips and sums
// the CPU both processes spent (all threads, LCM's receive threads included).

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "sdlqr/bus/node.hpp"
#include "sdlqr/calibrate/calibration.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/imu_t.hpp"
#include "sdlqr/tables/statistics.hpp"

namespace sdlqr::calibrate {
namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kPing = "CALIBRATE_PING";
constexpr const char* kPong = "CALIBRATE_PONG";

double selfCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// CPU of every thread of another process [s], from the scheduler's nanosecond counters.
double processCpuSeconds(pid_t pid) {
  double total = 0.0;
  for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/task")) {
    std::ifstream in(task.path() / "schedstat");
    double on_cpu_ns = 0.0;
    if (in >> on_cpu_ns) total += on_cpu_ns * 1e-9;
  }
  return total;
}

[[noreturn]] void runEcho(const ProcessOptions& options) {
  bus::Node node("sdlqr-calibrate-echo", options);
  node.setFaultInjection(bus::FaultInjection{});  // the machine's bus, not SDLQR_FAULTS' injected loss
  node.subscribe<imu_t>(kPing, [&](const imu_t& ping) { node.publish(kPong, ping); }, 64);
  while (node.spin(100)) {
  }
  std::_Exit(0);
}

std::string localDate() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", std::localtime(&now));
  return text;
}

struct Measurement {
  std::vector<double> rtt_us;
  int64_t pings = 0;
  double window_s = 0.0;
  double cpu_s = 0.0;
};

// Pings at `rate_hz` for `seconds`; each ping waits up to 50 ms for its pong before the next.
Measurement measure(bus::Node& node, pid_t echo, double rate_hz, double seconds) {
  int64_t answered_seq = -1;
  Clock::time_point answered_at;
  node.subscribe<imu_t>(kPong, [&](const imu_t& pong) {
    answered_seq = pong.seq;
    answered_at = Clock::now();
  }, 64);
  imu_t ping{};
  const auto exchange = [&](int64_t seq) {
    ping.seq = seq;
    const auto sent = Clock::now();
    node.publish(kPing, ping);
    while (answered_seq < seq && Clock::now() - sent < std::chrono::milliseconds(50)) node.spin(5);
    return answered_seq >= seq ? std::chrono::duration<double, std::micro>(answered_at - sent).count() : -1.0;
  };
  // The echo subscribes after the fork: wait until it answers before measuring.
  int64_t seq = 0;
  const auto give_up = Clock::now() + std::chrono::seconds(5);
  while (exchange(seq++) < 0.0) {
    if (Clock::now() > give_up || !node.running()) {
      throw std::runtime_error("no answer from the echo process in 5 s: is multicast routed on this bus?");
    }
  }
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz));
  Measurement m;
  const double cpu_start = selfCpuSeconds() + processCpuSeconds(echo);
  const auto start = Clock::now();
  auto next = start;
  while (node.running() && Clock::now() - start < std::chrono::duration<double>(seconds)) {
    const double rtt = exchange(seq++);
    ++m.pings;
    if (rtt >= 0.0) m.rtt_us.push_back(rtt);
    next += period;
    std::this_thread::sleep_until(next);
  }
  m.window_s = std::chrono::duration<double>(Clock::now() - start).count();
  m.cpu_s = selfCpuSeconds() + processCpuSeconds(echo) - cpu_start;
  return m;
}

int run(int argc, char** argv) {
  ProcessOptions options;
  std::string out_path;
  double seconds = 1.5, rate_hz = 1000.0;
  ArgParser parser("sdlqr-calibrate",
                   "Measures this machine's bus before a flight: a forked echo answers 1 kHz pings; prints and\n"
                   "writes the round-trip times and the CPU both processes spent (calibration.yaml), which the\n"
                   "flight's relative budgets (stack_cpu_relative_max, ...) divide by.");
  addProcessOptions(parser, &options);
  parser.addOption("--out", &out_path, "FILE", "write the calibration as YAML (default: print only)");
  parser.addOption("--duration", &seconds, "S", "measured window, default 1.5 s", Range::closed(0.2, 60));
  parser.addOption("--rate", &rate_hz, "HZ", "pings per second, default 1000", Range::closed(10, 5000));
  parser.setEpilog("exit codes: 0 measured, 1 no answer on the bus, 2 bad option");
  parser.parseOrExit(argc, argv);

  const pid_t echo = fork();
  if (echo < 0) throw std::runtime_error("fork failed");
  if (echo == 0) runEcho(options);
  Measurement m;
  try {
    bus::Node node("sdlqr-calibrate", options);
    node.setFaultInjection(bus::FaultInjection{});
    m = measure(node, echo, rate_hz, seconds);
  } catch (...) {
    kill(echo, SIGTERM);
    waitpid(echo, nullptr, 0);
    throw;
  }
  kill(echo, SIGTERM);
  waitpid(echo, nullptr, 0);

  const tables::Distribution rtt = tables::describe(m.rtt_us);
  Calibration c;
  c.echo_rate_hz = rate_hz;
  c.pings = m.pings;
  c.pongs = static_cast<int64_t>(m.rtt_us.size());
  c.rtt_median_us = rtt.median;
  c.rtt_p99_us = rtt.p99;
  c.cpu_percent = 100.0 * m.cpu_s / m.window_s;
  c.window_s = m.window_s;
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  c.host = host;
  c.date = localDate();
  c.write(std::cout);
  if (!out_path.empty()) {
    std::ofstream out(out_path);
    c.write(out);
    if (!out) throw std::invalid_argument("--out: cannot write " + out_path);
  }
  const std::string reason = c.invalidReason();
  if (!reason.empty()) throw std::runtime_error("measurement unusable: " + reason);
  return 0;
}

}  // namespace
}  // namespace sdlqr::calibrate

int main(int argc, char** argv) {
  return sdlqr::runMain("sdlqr-calibrate", [&] { return sdlqr::calibrate::run(argc, argv); });
}
