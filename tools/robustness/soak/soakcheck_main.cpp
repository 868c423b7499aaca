// sdlqr-soakcheck: judges a soak flight (./sdlqr soak): the log is whole and long enough, and
// memory, file descriptors, CPU and bus latency do not grow against the first window of the run.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/soak/soak_check.hpp"
#include "sdlqr/soak/soak_log.hpp"

using namespace sdlqr;

namespace {

std::vector<std::string> names(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (!name.empty()) out.push_back(name);
  }
  return out;
}

// Options through the shared parser (CLI11): --help, one-line errors, exit code 2.
struct SoakCheckCommand {
  std::string samples_path, log_path;
  std::vector<std::string> expected;
  double airborne = -1.0;
  soak::GrowthLimits limits;
};

SoakCheckCommand parseCommand(int argc, const char* const* argv) {
  SoakCheckCommand c;
  std::string expect;
  ArgParser parser("sdlqr-soakcheck",
                   "Judge a soak flight (./sdlqr soak): the log is whole and long enough, and memory, file\n"
                   "descriptors, CPU and bus latency do not grow against the first window of the run.");
  parser.addOption("--samples", &c.samples_path, "CSV",
                   "/proc samples of the stack's processes (t,process,rss_kib,fds,cpu_seconds)", Presence::kRequired);
  parser.addOption("--log", &c.log_path, "LOG", "the flight log", Presence::kRequired);
  parser.addOption("--airborne", &c.airborne, "S", "simulation seconds the vehicle must have been airborne",
                   Range::above(0), Presence::kRequired);
  parser.addOption("--window", &c.limits.window_s, "S", "window length (default 60); the first window is the reference",
                   Range::above(0));
  parser.addOption("--expect", &expect, "A,B", "processes that must have samples in every window (the launcher's)");
  parser.setEpilog("exit codes: 0 every check holds, 1 one fails, 2 bad arguments or input");
  parser.parseOrExit(argc, argv);
  c.expected = names(expect);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const SoakCheckCommand command = parseCommand(argc, argv);
  const std::string& samples_path = command.samples_path;
  const std::string& log_path = command.log_path;
  const std::vector<std::string>& expected = command.expected;
  const double airborne = command.airborne;
  const soak::GrowthLimits& limits = command.limits;
  try {
    const logger::FlightLog log = logger::FlightLog::load(log_path);
    const soak::LogWholeness whole = soak::checkLogWhole(log);
    std::printf("log: %s, %lld message(s) missing by seq%s%s, airborne %.1f s of simulation (>= %.1f required)%s\n",
                whole.file_complete ? "complete" : "INCOMPLETE (corrupt or torn)",
                static_cast<long long>(whole.seq_lost), whole.worst_channel.empty() ? "" : ", most on ",
                whole.worst_channel.c_str(), whole.airborne_sim_s, airborne, whole.crashed ? ", CRASHED" : "");
    const soak::SoakReport report = soak::judgeGrowth(soak::readSamples(samples_path), soak::commandLatencyOverTime(log),
                                                      whole.airborne_start, whole.airborne_end, limits, expected);
    std::printf("%-8s %-22s %10s %5s %8s   (latency median STATE_EST->RATE_CMD)\n", "window", "process", "rss_kib",
                "fds", "cpu_%");
    for (size_t i = 0; i < report.windows.size(); ++i) {
      const soak::WindowFigures& w = report.windows[i];
      for (const auto& p : w.processes) {
        std::printf("%-8zu %-22s %10.0f %5lld %8.1f\n", i + 1, p.name.c_str(), p.rss_max_kib,
                    static_cast<long long>(p.fds_max), p.cpu_percent);
      }
      std::printf("%-8zu %-22s %.0f us over %lld commands\n", i + 1, "latency", w.latency_median_us,
                  static_cast<long long>(w.latency_samples));
    }
    for (const soak::SoakCheck& c : report.checks) {
      std::printf("%s %-52s %12.1f <= %12.1f\n", c.pass ? "ok  " : "FAIL", c.name.c_str(), c.value, c.limit);
    }
    const bool pass = report.passed() && whole.passed(airborne);
    std::printf("soak: %s\n", pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sdlqr-soakcheck: %s\n", e.what());
    return 2;
  }
}
