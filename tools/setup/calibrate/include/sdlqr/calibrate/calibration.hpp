#pragma once
// What this machine's bus costs, measured just before a flight on the same bus (sdlqr-calibrate):
// two processes exchanging a small message at 1 kHz, one publishing a ping and timing the pong
// the other answers with. The flight's machine-dependent figures (CPU of the stack, latency on
// the bus) are judged only relative to these, so a slower or busier machine moves both alike.
//
// Stored as YAML beside the flight log (calibration.yaml).

#include <cstdint>
#include <ostream>
#include <string>

namespace sdlqr::calibrate {

struct Calibration {
  double echo_rate_hz = 0.0;     // [Hz] pings per second
  int64_t pings = 0;             // [-] sent in the measured window
  int64_t pongs = 0;             // [-] answered within the window
  double rtt_median_us = 0.0;    // [us] ping published -> pong handled
  double rtt_p99_us = 0.0;       // [us]
  double cpu_percent = 0.0;      // [% of one core] both processes together over the window
  double window_s = 0.0;         // [s] wall time measured
  std::string host;              // machine name
  std::string date;              // ISO 8601, local time

  // One-way latency estimate: half the median round trip (the median: a p99 over 1.5 s of a
  // busy machine swings several-fold from run to run).
  double oneWayMedianUs() const { return 0.5 * rtt_median_us; }
  // The bus's tail, for judging a flight's tail (jitter, p99 latency) against: half the p99 round
  // trip. Noisier than the median, so only budgets for gross regressions divide by it.
  double oneWayP99Us() const { return 0.5 * rtt_p99_us; }

  // Throws ConfigError naming the key ("calibration.cpu_percent: ...") on a bad or missing file.
  static Calibration load(const std::string& path);
  void write(std::ostream& out) const;
  // "" when usable, else "key: reason".
  std::string invalidReason() const;
};

}  // namespace sdlqr::calibrate
