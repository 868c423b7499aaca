#include "sdlqr/soak/soak_check.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace sdlqr::soak {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  return values[mid];
}

WindowFigures figuresIn(const std::vector<ResourceSample>& samples, const std::vector<LatencySample>& latency,
                        double start, double end) {
  WindowFigures w;
  w.start = start;
  w.end = end;
  // CPU: the first and last cumulative reading inside the window of each process.
  struct Span {
    WindowFigures::Process figures;
    double t0 = 0.0, cpu0 = 0.0, t1 = 0.0, cpu1 = 0.0;
    bool seen = false;
  };
  std::map<std::string, Span> spans;
  for (const ResourceSample& s : samples) {
    if (s.t < start || s.t >= end) continue;
    Span& span = spans[s.process];
    span.figures.name = s.process;
    span.figures.rss_max_kib = std::max(span.figures.rss_max_kib, s.rss_kib);
    span.figures.fds_max = std::max(span.figures.fds_max, s.fds);
    if (!span.seen) {
      span.t0 = s.t;
      span.cpu0 = s.cpu_seconds;
      span.seen = true;
    }
    span.t1 = s.t;
    span.cpu1 = s.cpu_seconds;
  }
  for (auto& [name, span] : spans) {
    if (span.t1 > span.t0) span.figures.cpu_percent = 100.0 * (span.cpu1 - span.cpu0) / (span.t1 - span.t0);
    w.processes.push_back(span.figures);
  }
  std::vector<double> us;
  for (const LatencySample& l : latency) {
    if (l.t >= start && l.t < end) us.push_back(l.us);
  }
  w.latency_samples = static_cast<int64_t>(us.size());
  w.latency_median_us = median(std::move(us));
  return w;
}

const WindowFigures::Process* find(const WindowFigures& w, const std::string& name) {
  for (const auto& p : w.processes) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

// Keeps every failure and, per name prefix, the worst passing value (a 30-window report stays short).
void record(SoakReport& report, const std::string& name, double value, double limit) {
  SoakCheck check{name, value, limit, value <= limit};
  if (!check.pass) {
    report.checks.push_back(check);
    return;
  }
  const std::string key = name.substr(0, name.find('@'));
  for (SoakCheck& known : report.checks) {
    if (known.pass && known.name.substr(0, known.name.find('@')) == key) {
      if (value - limit > known.value - known.limit) known = check;
      return;
    }
  }
  report.checks.push_back(check);
}

}  // namespace

bool SoakReport::passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const SoakCheck& c) { return c.pass; });
}

SoakReport judgeGrowth(const std::vector<ResourceSample>& samples, const std::vector<LatencySample>& latency,
                       double start, double end, const GrowthLimits& limits,
                       const std::vector<std::string>& expected) {
  if (!(limits.window_s > 0.0)) throw std::invalid_argument("window must be > 0 s");
  SoakReport report;
  for (double a = start; a + limits.window_s <= end + 1e-9; a += limits.window_s) {
    report.windows.push_back(figuresIn(samples, latency, a, a + limits.window_s));
  }
  if (report.windows.size() < 2) {
    throw std::invalid_argument("the flight holds fewer than two full " + std::to_string(limits.window_s) +
                                " s windows: nothing to compare");
  }
  const WindowFigures& ref = report.windows.front();
  const WindowFigures& last = report.windows.back();
  for (const std::string& name : expected) {
    if (find(ref, name) == nullptr) record(report, "sampled[" + name + "]@window 1", 1.0, 0.0);  // never judged
  }
  for (const auto& p : ref.processes) {
    const double rss_limit = std::max(p.rss_max_kib * (1.0 + limits.rss_growth_fraction),
                                      p.rss_max_kib + limits.rss_growth_min_kib);
    for (size_t i = 1; i < report.windows.size(); ++i) {
      const auto* later = find(report.windows[i], p.name);
      const std::string at = "@window " + std::to_string(i + 1);
      if (later == nullptr) {
        record(report, "sampled[" + p.name + "]" + at, 1.0, 0.0);  // the process vanished
        continue;
      }
      record(report, "rss_kib[" + p.name + "]" + at, later->rss_max_kib, rss_limit);
      record(report, "fds[" + p.name + "]" + at, static_cast<double>(later->fds_max),
             static_cast<double>(p.fds_max + limits.fd_growth));
    }
    const auto* final_window = find(last, p.name);
    if (final_window != nullptr) {
      record(report, "cpu_percent[" + p.name + "]@last window", final_window->cpu_percent,
             p.cpu_percent * limits.cpu_growth_factor + limits.cpu_growth_points);
    }
  }
  if (ref.latency_samples == 0 || last.latency_samples == 0) {
    record(report, "latency_samples@first and last window", 1.0, 0.0);
  } else {
    record(report, "state_to_command_median_us@last window", last.latency_median_us,
           ref.latency_median_us * limits.latency_growth_factor + limits.latency_growth_us);
  }
  return report;
}

std::vector<ResourceSample> readSamples(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::string line;
  std::getline(in, line);
  if (line != "t,process,rss_kib,fds,cpu_seconds") {
    throw std::runtime_error(path + ":1: expected the header t,process,rss_kib,fds,cpu_seconds");
  }
  std::vector<ResourceSample> samples;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    std::istringstream row(line);
    ResourceSample s;
    std::string t, rss, fds, cpu;
    if (!std::getline(row, t, ',') || !std::getline(row, s.process, ',') || !std::getline(row, rss, ',') ||
        !std::getline(row, fds, ',') || !std::getline(row, cpu) || s.process.empty()) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected 5 comma-separated fields");
    }
    try {
      s.t = std::stod(t);
      s.rss_kib = std::stod(rss);
      s.fds = std::stoll(fds);
      s.cpu_seconds = std::stod(cpu);
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": not a number in '" + line + "'");
    }
    samples.push_back(s);
  }
  return samples;
}

}  // namespace sdlqr::soak
