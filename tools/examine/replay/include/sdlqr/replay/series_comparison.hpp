#pragma once
// Compares recomputed messages with recorded ones, message by message (paired by seq) and field
// by field: bit for bit (doubles compared by their bits), and the largest absolute difference
// of every field that differs. The fields are those of the generated plain struct
// (lcmtypes/*.lcm), every one of them but those marked @wall_time (GAINS.solve_us: the
// solver's wall time, measured by the process, not a function of the inputs).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "sdlqr/lcmtypes/generated/plain_fields.hpp"
#include "sdlqr/lcmtypes/leaves.hpp"

namespace sdlqr::replay {

struct FieldDifference {
  std::string field;          // e.g. "body_rate[0]"
  int64_t messages = 0;       // messages in which it differs
  double max_abs = 0.0;       // largest |recorded - replayed|
};

struct ChannelComparison {
  std::string channel;        // STATE_EST, RATE_CMD, REFERENCE, GAINS
  int64_t recorded = 0;
  int64_t replayed = 0;
  int64_t compared = 0;       // seqs present in both
  int64_t identical = 0;      // bit for bit
  int64_t within_tolerance = 0;  // identical or every field within the tolerance
  int64_t only_recorded = 0;
  int64_t only_replayed = 0;
  // Recomputed after the last recorded message of the channel: the recorder stopped before the
  // process published it (the log's end cuts the flight at a different place on each channel).
  int64_t after_recording = 0;
  double max_abs = 0.0;       // over every field
  std::vector<FieldDifference> fields;  // only the fields that differ somewhere
  std::string first_difference;         // empty when none
  std::vector<std::string> excluded;    // fields not compared

  bool complete() const { return compared == recorded && compared + after_recording == replayed; }
  bool bitForBit() const { return complete() && identical == compared; }
  bool withinTolerance() const { return complete() && within_tolerance == compared; }
};

namespace detail {

inline std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// Compares one recorded/replayed pair leaf by leaf (sdlqr/lcmtypes/leaves.hpp: every field of
// the generated plain struct), accumulating into a ChannelComparison. Doubles are compared by
// their bits; @wall_time fields are left out.
class FieldWalker {
 public:
  FieldWalker(ChannelComparison& channel, std::map<std::string, FieldDifference>& fields, double tolerance,
              int64_t seq)
      : channel_(channel), fields_(fields), tolerance_(tolerance), seq_(seq) {}

  template <class T>
  void leaf(const lcmtypes::LeafName& name, const T& recorded, const T& replayed) {
    if (name.field.wall_time) return;
    if constexpr (std::is_floating_point_v<T>) {
      if (std::memcmp(&recorded, &replayed, sizeof recorded) == 0) return;
      const double diff = std::fabs(static_cast<double>(recorded) - static_cast<double>(replayed));
      note(name.text(), std::isnan(diff) ? INFINITY : diff, number(recorded), number(replayed));
    } else if constexpr (std::is_same_v<T, std::string>) {
      if (recorded != replayed) note(name.text(), INFINITY, "'" + recorded + "'", "'" + replayed + "'");
    } else {
      const int64_t a = static_cast<int64_t>(recorded);
      const int64_t b = static_cast<int64_t>(replayed);
      if (a != b) note(name.text(), std::fabs(static_cast<double>(a - b)), std::to_string(a), std::to_string(b));
    }
  }

  template <class Vector>
  std::size_t rows(const lcmtypes::LeafName& name, const Vector& recorded, const Vector& replayed) {
    leaf(lcmtypes::LeafName{name.path + ".size()", -1, name.field}, static_cast<int64_t>(recorded.size()),
         static_cast<int64_t>(replayed.size()));
    return std::min(recorded.size(), replayed.size());
  }

  bool identical() const { return identical_; }
  bool withinTolerance() const { return within_; }

 private:
  void note(const std::string& field, double diff, const std::string& recorded, const std::string& replayed) {
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

// The fields of T that are not compared (@wall_time in its .lcm file).
template <class T>
std::vector<std::string> excludedFields() {
  std::vector<std::string> out;
  const T any{};
  lcmtypes::visitFields(
      [&](const lcmtypes::PlainField& f, const auto&) {
        if (f.wall_time) out.push_back(std::string(f.name) + " (wall time)");
      },
      any);
  return out;
}

}  // namespace detail

// One channel: `recorded` and `replayed` paired by seq. T is a generated plain struct.
template <class T>
ChannelComparison compareSeries(const char* channel, const std::vector<T>& recorded, const std::vector<T>& replayed,
                                double tolerance) {
  ChannelComparison out;
  out.channel = channel;
  out.excluded = detail::excludedFields<T>();
  out.recorded = static_cast<int64_t>(recorded.size());
  out.replayed = static_cast<int64_t>(replayed.size());
  std::map<int64_t, const T*> by_seq;
  for (const T& m : replayed) by_seq.emplace(m.seq, &m);
  std::map<std::string, FieldDifference> fields;
  // The recording ends at its last message the replay also computed: a foreign publisher's
  // messages (recorded only, any seq: a rogue's RATE_CMD from seq 1000000) do not move that end.
  int64_t last_matched = -1;
  bool any_matched = false;
  for (const T& r : recorded) {
    auto it = by_seq.find(r.seq);
    if (it == by_seq.end()) {
      ++out.only_recorded;
      if (out.first_difference.empty()) {
        out.first_difference = out.channel + " seq " + std::to_string(r.seq) + ": recorded, not recomputed";
      }
      continue;
    }
    detail::FieldWalker walker(out, fields, tolerance, r.seq);
    lcmtypes::visitLeaves(walker, r, *it->second);
    ++out.compared;
    last_matched = any_matched ? std::max(last_matched, r.seq) : r.seq;
    any_matched = true;
    if (walker.identical()) ++out.identical;
    if (walker.withinTolerance()) ++out.within_tolerance;
    by_seq.erase(it);
  }
  if (any_matched) {
    for (auto it = by_seq.upper_bound(last_matched); it != by_seq.end();) {
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

}  // namespace sdlqr::replay
