#include "sdlqr/replay/output_comparison.hpp"

#include <cstdio>

namespace sdlqr::replay {

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
