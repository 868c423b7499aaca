#include "sdlqr/calibrate/calibration.hpp"

#include <cmath>
#include <cstdio>

#include "sdlqr/config/config.hpp"

namespace sdlqr::calibrate {

Calibration Calibration::load(const std::string& path) {
  const ConfigReader file(loadYamlFile(path), "calibration");
  file.allowOnly({"echo_rate_hz", "pings", "pongs", "rtt_median_us", "rtt_p99_us", "cpu_percent", "window_s", "host",
                  "date"});
  for (const char* key : {"echo_rate_hz", "pings", "pongs", "rtt_median_us", "rtt_p99_us", "cpu_percent", "window_s"}) {
    if (!file.has(key)) throw ConfigError(file.keyPath(key), "missing (" + path + ")");
  }
  Calibration c;
  long long pings = 0, pongs = 0;
  file.read("echo_rate_hz", c.echo_rate_hz);
  file.read("pings", pings);
  file.read("pongs", pongs);
  file.read("rtt_median_us", c.rtt_median_us);
  file.read("rtt_p99_us", c.rtt_p99_us);
  file.read("cpu_percent", c.cpu_percent);
  file.read("window_s", c.window_s);
  file.read("host", c.host);
  file.read("date", c.date);
  c.pings = pings;
  c.pongs = pongs;
  const std::string reason = c.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(file.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return c;
}

std::string Calibration::invalidReason() const {
  if (!(echo_rate_hz > 0.0)) return "echo_rate_hz: must be > 0";
  if (pings <= 0) return "pings: must be > 0";
  if (pongs <= 0 || pongs > pings) return "pongs: must be in [1, pings] (no answer: is the bus up?)";
  if (!(rtt_median_us > 0.0)) return "rtt_median_us: must be > 0";
  if (!(rtt_p99_us >= rtt_median_us)) return "rtt_p99_us: must be >= rtt_median_us";
  if (!(cpu_percent > 0.0)) return "cpu_percent: must be > 0";
  if (!(window_s > 0.0)) return "window_s: must be > 0";
  return {};
}

void Calibration::write(std::ostream& out) const {
  char line[160];
  out << "# sdlqr-calibrate: a 1 kHz ping/pong between two processes on this bus, just before the flight\n";
  std::snprintf(line, sizeof line, "echo_rate_hz: %.1f        # [Hz]\n", echo_rate_hz);
  out << line;
  out << "pings: " << pings << "                # [-] sent in the window\n";
  out << "pongs: " << pongs << "                # [-] answered\n";
  std::snprintf(line, sizeof line, "rtt_median_us: %.1f       # [us] ping published -> pong handled\n", rtt_median_us);
  out << line;
  std::snprintf(line, sizeof line, "rtt_p99_us: %.1f          # [us]\n", rtt_p99_us);
  out << line;
  std::snprintf(line, sizeof line, "cpu_percent: %.2f         # [%% of one core] both processes together\n", cpu_percent);
  out << line;
  std::snprintf(line, sizeof line, "window_s: %.3f            # [s] wall time measured\n", window_s);
  out << line;
  out << "host: \"" << host << "\"\n";
  out << "date: \"" << date << "\"\n";
}

}  // namespace sdlqr::calibrate
