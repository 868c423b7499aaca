#pragma once
// Judges a long flight for growth (docs/loss-and-starved.md, Soak): memory, file descriptors, CPU and bus latency
// in every window of the flight against the first window of the same run, on the same machine,
// so the verdict never depends on how fast the machine is — only on whether the figures grow.
// Inputs are plain series: what the soak runner sampled from /proc for each process, and the
// STATE_EST -> RATE_CMD latency of the log (soak_log.hpp).

#include <cstdint>
#include <string>
#include <vector>

namespace sdlqr::soak {

// One /proc sample of one process.
struct ResourceSample {
  double t = 0.0;            // [s] since the flight started (wall clock)
  std::string process;       // name in the stack table
  double rss_kib = 0.0;      // [KiB] resident set
  int64_t fds = 0;           // [-] open file descriptors
  double cpu_seconds = 0.0;  // [s] user + system since the process started
};

// One latency sample at its flight time.
struct LatencySample {
  double t = 0.0;   // [s] same clock as ResourceSample::t
  double us = 0.0;  // [us]
};

// Growth allowed over the first window (the reference) — a leak of 1 KiB/s grows the RSS by
// 1.8 MiB in 30 minutes and fails; the CPU and latency allowances absorb a busy neighbour.
struct GrowthLimits {
  double window_s = 60.0;                // [s] window length; the first is the reference
  double rss_growth_fraction = 0.05;     // [-] RSS max of a window <= ref max * (1 + this) ...
  double rss_growth_min_kib = 1024.0;    // [KiB] ... or ref max + this, whichever is larger
  int64_t fd_growth = 0;                 // [-] fds max of a window <= ref max + this
  double cpu_growth_factor = 1.5;        // [-] CPU % of the last window <= ref * this + points
  double cpu_growth_points = 5.0;        // [% of one core]
  double latency_growth_factor = 2.0;    // [-] median latency of the last window <= ref * this + us
  double latency_growth_us = 200.0;      // [us]
};

struct WindowFigures {
  double start = 0.0, end = 0.0;  // [s]
  struct Process {
    std::string name;
    double rss_max_kib = 0.0;
    int64_t fds_max = 0;
    double cpu_percent = 0.0;  // [% of one core] over the window
  };
  std::vector<Process> processes;
  double latency_median_us = 0.0;
  int64_t latency_samples = 0;
};

struct SoakCheck {
  std::string name;         // e.g. "rss[sdlqr-controller]@window 12"
  double value = 0.0;
  double limit = 0.0;
  bool pass = false;
};

struct SoakReport {
  std::vector<WindowFigures> windows;  // full windows only, in time order
  std::vector<SoakCheck> checks;       // failed ones, and one per resource and process that held
  bool passed() const;
};

// Splits [start, end) into full windows of limits.window_s and judges every later window's RSS
// and fds (which never shrink back by themselves) and the last window's CPU and latency (noisy)
// against the first. Every `expected` process (those the launcher started) must have samples in
// every window: one without is a failed check ("sampled[NAME]@window 1"), never a process left
// unjudged. Throws std::invalid_argument when fewer than two full windows fit.
SoakReport judgeGrowth(const std::vector<ResourceSample>& samples, const std::vector<LatencySample>& latency,
                       double start, double end, const GrowthLimits& limits,
                       const std::vector<std::string>& expected = {});

// The runner's CSV: header "t,process,rss_kib,fds,cpu_seconds", one row per sample. Throws
// std::runtime_error naming the file and line on a malformed row.
std::vector<ResourceSample> readSamples(const std::string& path);

}  // namespace sdlqr::soak
