#include "sdlqr/replay/output_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

namespace sdlqr::replay {

namespace {

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// Walks the fields of one recorded/replayed pair, accumulating into a ChannelComparison.
class FieldWalker {
 public:
  FieldWalker(ChannelComparison& channel, std::map<std::string, FieldDifference>& fields, double tolerance,
              int64_t seq)
      : channel_(channel), fields_(fields), tolerance_(tolerance), seq_(seq) {}

  void real(const char* name, int index, double recorded, double replayed) {
    if (std::memcmp(&recorded, &replayed, sizeof recorded) == 0) return;
    const double diff = std::fabs(recorded - replayed);
    note(name, index, std::isnan(diff) ? INFINITY : diff, number(recorded), number(replayed));
  }
  void integer(const char* name, int64_t recorded, int64_t replayed) {
    if (recorded == replayed) return;
    note(name, -1, std::fabs(static_cast<double>(recorded - replayed)), std::to_string(recorded),
         std::to_string(replayed));
  }
  template <class Vector>
  void vector(const char* name, const Vector& recorded, const Vector& replayed) {
    for (int i = 0; i < recorded.size(); ++i) real(name, i, recorded[i], replayed[i]);
  }

  bool identical() const { return identical_; }
  bool withinTolerance() const { return within_; }

 private:
  void note(const char* name, int index, double diff, const std::string& recorded, const std::string& replayed) {
    const std::string field = index < 0 ? std::string(name) : std::string(name) + "[" + std::to_string(index) + "]";
    identical_ = false;
    if (!(diff <= tolerance_)) within_ = false;
    FieldDifference& d = fields_[field];
    d.field = field;
    if (last_counted_ != field + "#" + std::to_string(seq_)) ++d.messages;
    last_counted_ = field + "#" + std::to_string(seq_);
    d.max_abs = std::max(d.max_abs, diff);
    channel_.max_abs = std::max(channel_.max_abs, diff);
    if (channel_.first_difference.empty()) {
      channel_.first_difference = channel_.channel + " seq " + std::to_string(seq_) + " " + field + ": recorded " +
                                  recorded + ", replayed " + replayed;
    }
  }

  ChannelComparison& channel_;
  std::map<std::string, FieldDifference>& fields_;
  double tolerance_;
  int64_t seq_;
  bool identical_ = true;
  bool within_ = true;
  std::string last_counted_;
};

void walk(FieldWalker& w, const StateEstimate& a, const StateEstimate& b) {
  w.integer("utime", a.utime, b.utime);
  w.integer("seq", a.seq, b.seq);
  w.vector("position", a.position, b.position);
  w.vector("orientation", a.orientation, b.orientation);
  w.vector("velocity", a.velocity, b.velocity);
  w.vector("body_rate", a.body_rate, b.body_rate);
  w.vector("gyro_bias", a.gyro_bias, b.gyro_bias);
  w.vector("accel_bias", a.accel_bias, b.accel_bias);
  w.vector("position_std", a.position_std, b.position_std);
  w.vector("attitude_std", a.attitude_std, b.attitude_std);
  w.integer("imu_seq", a.imu_seq, b.imu_seq);
  w.integer("vio_seq", a.vio_seq, b.vio_seq);
  w.integer("status", static_cast<int64_t>(a.status), static_cast<int64_t>(b.status));
}

void walk(FieldWalker& w, const RateCommand& a, const RateCommand& b) {
  w.integer("utime", a.utime, b.utime);
  w.integer("seq", a.seq, b.seq);
  w.vector("body_rate", a.body_rate, b.body_rate);
  w.real("thrust", -1, a.thrust, b.thrust);
  w.integer("state_seq", a.state_seq, b.state_seq);
  w.integer("gains_seq", a.gains_seq, b.gains_seq);
  w.integer("reference_seq", a.reference_seq, b.reference_seq);
  w.integer("saturated", a.saturated, b.saturated);
  w.integer("gains_status", static_cast<int64_t>(a.gains_status), static_cast<int64_t>(b.gains_status));
}

void walk(FieldWalker& w, const Reference& a, const Reference& b) {
  w.integer("utime", a.utime, b.utime);
  w.integer("seq", a.seq, b.seq);
  w.vector("x", a.x, b.x);
  w.vector("u", a.u, b.u);
  w.integer("index", a.index, b.index);
  w.real("gamma", -1, a.gamma, b.gamma);
  w.integer("trajectory_seq", a.trajectory_seq, b.trajectory_seq);
  w.integer("state_seq", a.state_seq, b.state_seq);
  w.integer("command_seq", a.command_seq, b.command_seq);
  w.integer("params_seq", a.params_seq, b.params_seq);
  w.integer("mode", static_cast<int64_t>(a.mode), static_cast<int64_t>(b.mode));
}

void walk(FieldWalker& w, const GainSet& a, const GainSet& b) {
  w.integer("utime", a.utime, b.utime);
  w.integer("seq", a.seq, b.seq);
  // Row-major as published: K[r * 10 + c].
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 10; ++c) w.real("K", r * 10 + c, a.K(r, c), b.K(r, c));
  }
  w.vector("x_lin", a.x_lin, b.x_lin);
  w.vector("u_lin", a.u_lin, b.u_lin);
  w.vector("q_diag", a.q_diag, b.q_diag);
  w.vector("r_diag", a.r_diag, b.r_diag);
  w.real("dt", -1, a.dt, b.dt);
  w.real("residual", -1, a.residual, b.residual);
  w.integer("iterations", a.iterations, b.iterations);
  w.integer("state_seq", a.state_seq, b.state_seq);
  w.integer("params_seq", a.params_seq, b.params_seq);
  w.integer("reference_seq", a.reference_seq, b.reference_seq);
  w.integer("method", static_cast<int64_t>(a.method), static_cast<int64_t>(b.method));
  w.integer("status", static_cast<int64_t>(a.status), static_cast<int64_t>(b.status));
}

template <class T>
ChannelComparison compareSeries(const char* channel, const std::vector<T>& recorded, const std::vector<T>& replayed,
                                double tolerance) {
  ChannelComparison out;
  out.channel = channel;
  out.recorded = static_cast<int64_t>(recorded.size());
  out.replayed = static_cast<int64_t>(replayed.size());
  std::map<int64_t, const T*> by_seq;
  for (const T& m : replayed) by_seq.emplace(m.seq, &m);
  std::map<std::string, FieldDifference> fields;
  for (const T& r : recorded) {
    auto it = by_seq.find(r.seq);
    if (it == by_seq.end()) {
      ++out.only_recorded;
      if (out.first_difference.empty()) {
        out.first_difference = out.channel + " seq " + std::to_string(r.seq) + ": recorded, not recomputed";
      }
      continue;
    }
    FieldWalker walker(out, fields, tolerance, r.seq);
    walk(walker, r, *it->second);
    ++out.compared;
    if (walker.identical()) ++out.identical;
    if (walker.withinTolerance()) ++out.within_tolerance;
    by_seq.erase(it);
  }
  if (!recorded.empty()) {
    const int64_t last_recorded = std::max_element(recorded.begin(), recorded.end(), [](const T& a, const T& b) {
                                    return a.seq < b.seq;
                                  })->seq;
    for (auto it = by_seq.upper_bound(last_recorded); it != by_seq.end();) {
      ++out.after_recording;
      it = by_seq.erase(it);
    }
  }
  out.only_replayed = static_cast<int64_t>(by_seq.size());
  if (out.first_difference.empty() && !by_seq.empty()) {
    out.first_difference =
        out.channel + " seq " + std::to_string(by_seq.begin()->first) + ": recomputed, not in the recording";
  }
  for (auto& [name, d] : fields) out.fields.push_back(d);
  return out;
}

}  // namespace

bool Comparison::bitForBit() const {
  for (const ChannelComparison& c : channels) {
    if (!c.bitForBit()) return false;
  }
  return !channels.empty();
}

bool Comparison::withinTolerance() const {
  for (const ChannelComparison& c : channels) {
    if (!c.withinTolerance()) return false;
  }
  return !channels.empty();
}

Comparison compareOutputs(const RecordedFlight& recorded, const ReplayOutputs& replayed, double tolerance) {
  Comparison out;
  out.tolerance = tolerance;
  out.channels.push_back(compareSeries("STATE_EST", recorded.state_estimate, replayed.state_estimate, tolerance));
  out.channels.push_back(compareSeries("RATE_CMD", recorded.rate_command, replayed.rate_command, tolerance));
  out.channels.push_back(compareSeries("REFERENCE", recorded.reference, replayed.reference, tolerance));
  out.channels.push_back(compareSeries("GAINS", recorded.gains, replayed.gains, tolerance));
  out.channels.back().excluded.push_back("solve_us (wall time of the solve)");
  return out;
}

std::string formatComparison(const Comparison& comparison) {
  std::string text;
  char line[256];
  std::snprintf(line, sizeof line, "%-10s %9s %9s %9s %9s %9s  %s\n", "channel", "recorded", "replayed", "compared",
                "identical", "max|diff|", "result");
  text += line;
  for (const ChannelComparison& c : comparison.channels) {
    const char* result = c.bitForBit()          ? "identical bit for bit"
                         : c.withinTolerance()  ? "within tolerance"
                                                : "DIFFERENT";
    std::snprintf(line, sizeof line, "%-10s %9lld %9lld %9lld %9lld %9.2g  %s", c.channel.c_str(),
                  static_cast<long long>(c.recorded), static_cast<long long>(c.replayed),
                  static_cast<long long>(c.compared), static_cast<long long>(c.identical), c.max_abs, result);
    text += line;
    for (const std::string& e : c.excluded) text += " (not compared: " + e + ")";
    text += "\n";
  }
  for (const ChannelComparison& c : comparison.channels) {
    if (c.after_recording) {
      std::snprintf(line, sizeof line, "  %s: %lld recomputed after the recording ended (not compared)\n",
                    c.channel.c_str(), static_cast<long long>(c.after_recording));
      text += line;
    }
    if (c.first_difference.empty()) continue;
    text += "first difference: " + c.first_difference + "\n";
    for (const FieldDifference& d : c.fields) {
      std::snprintf(line, sizeof line, "  %s.%s: max |diff| %.3g in %lld messages\n", c.channel.c_str(),
                    d.field.c_str(), d.max_abs, static_cast<long long>(d.messages));
      text += line;
    }
    if (c.only_recorded || c.only_replayed) {
      std::snprintf(line, sizeof line, "  %s: %lld recorded only, %lld recomputed only\n", c.channel.c_str(),
                    static_cast<long long>(c.only_recorded), static_cast<long long>(c.only_replayed));
      text += line;
    }
  }
  if (comparison.bitForBit()) {
    text += "verdict: every output identical bit for bit\n";
  } else if (comparison.withinTolerance()) {
    char tolerance[32];
    std::snprintf(tolerance, sizeof tolerance, "%.3g", comparison.tolerance);
    text += std::string("verdict: outputs differ, every difference within ") + tolerance + "\n";
  } else {
    text += "verdict: outputs DIFFER\n";
  }
  return text;
}

}  // namespace sdlqr::replay
