// sdlqr-soakcheck: judges a soak flight (./sdlqr soak): the log is whole and long enough, and
// memory, file descriptors, CPU and bus latency do not grow against the first window of the run.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "sdlqr/soak/soak_check.hpp"
#include "sdlqr/soak/soak_log.hpp"

using namespace sdlqr;

namespace {

void usage(std::FILE* to) {
  std::fprintf(to,
               "usage: sdlqr-soakcheck --samples CSV --log LOG --airborne S [--window S]\n"
               "  --samples CSV   /proc samples of the stack's processes (t,process,rss_kib,fds,cpu_seconds)\n"
               "  --log LOG       the flight log\n"
               "  --airborne S    simulation seconds the vehicle must have been airborne\n"
               "  --window S      window length (default 60); the first window is the reference\n"
               "  --expect A,B    processes that must have samples in every window (the launcher's)\n"
               "Exit 0 when every check holds, 1 when one fails, 2 on bad arguments or input.\n");
}

double number(const std::string& key, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(v > 0.0)) {
    std::fprintf(stderr, "sdlqr-soakcheck: %s: expected a positive number, got '%s'\n", key.c_str(), text);
    std::exit(2);
  }
  return v;
}

std::vector<std::string> names(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (!name.empty()) out.push_back(name);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string samples_path, log_path;
  std::vector<std::string> expected;
  double airborne = -1.0;
  soak::GrowthLimits limits;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      usage(stdout);
      return 0;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "sdlqr-soakcheck: %s needs a value (see --help)\n", arg.c_str());
      return 2;
    }
    const char* value = argv[++i];
    if (arg == "--samples") samples_path = value;
    else if (arg == "--log") log_path = value;
    else if (arg == "--airborne") airborne = number(arg, value);
    else if (arg == "--window") limits.window_s = number(arg, value);
    else if (arg == "--expect") expected = names(value);
    else {
      std::fprintf(stderr, "sdlqr-soakcheck: unknown option '%s' (see --help)\n", arg.c_str());
      return 2;
    }
  }
  if (samples_path.empty() || log_path.empty() || airborne < 0.0) {
    std::fprintf(stderr, "sdlqr-soakcheck: --samples, --log and --airborne are required (see --help)\n");
    return 2;
  }
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
