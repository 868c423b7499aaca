#include "sdlqr/health/process_health.hpp"

namespace sdlqr {

Counters::Id Counters::add(const std::string& name) {
  const Id known = find(name);
  if (known >= 0) return known;
  names_.push_back(name);
  values_.push_back(0);
  return static_cast<Id>(names_.size() - 1);
}

Counters::Id Counters::find(std::string_view name) const {
  for (size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return static_cast<Id>(i);
  }
  return -1;
}

int64_t ProcessHealth::rejections(RejectReason reason) const {
  int64_t total = 0;
  for (const auto& stream : rejects_) total += stream[index(reason)];
  return total;
}

namespace {

std::string streamCounterName(int stream, int reason) {
  return std::string("reject.") + streamName(static_cast<Stream>(stream)) + "." +
         reasonName(static_cast<RejectReason>(reason));
}

}  // namespace

void ProcessHealth::exportCounters(std::vector<std::string>& names, std::vector<int64_t>& values) const {
  names.clear();
  values.clear();
  for (int r = 1; r < kRejectReasonCount; ++r) {
    names.emplace_back(counterName(static_cast<RejectReason>(r)));
    values.push_back(rejections(static_cast<RejectReason>(r)));
  }
  for (int s = 0; s < kStreamCount; ++s) {
    for (int r = 1; r < kRejectReasonCount; ++r) {
      if (rejects_[static_cast<size_t>(s)][static_cast<size_t>(r)] == 0) continue;
      names.push_back(streamCounterName(s, r));
      values.push_back(rejects_[static_cast<size_t>(s)][static_cast<size_t>(r)]);
    }
  }
  names.insert(names.end(), counters_.names().begin(), counters_.names().end());
  values.insert(values.end(), counters_.values().begin(), counters_.values().end());
}

std::string ProcessHealth::describeRejections() const {
  std::string text;
  for (int s = 0; s < kStreamCount; ++s) {
    for (int r = 1; r < kRejectReasonCount; ++r) {
      const int64_t n = rejects_[static_cast<size_t>(s)][static_cast<size_t>(r)];
      if (n == 0) continue;
      if (!text.empty()) text += ' ';
      text += streamCounterName(s, r) + "=" + std::to_string(n);
    }
  }
  return text;
}

int64_t ProcessHealth::counter(std::string_view name) const {
  for (int r = 1; r < kRejectReasonCount; ++r) {
    if (name == counterName(static_cast<RejectReason>(r))) return rejections(static_cast<RejectReason>(r));
  }
  for (int s = 0; s < kStreamCount; ++s) {
    for (int r = 1; r < kRejectReasonCount; ++r) {
      if (name == streamCounterName(s, r)) return rejects_[static_cast<size_t>(s)][static_cast<size_t>(r)];
    }
  }
  const Counters::Id id = counters_.find(name);
  return id >= 0 ? counters_.value(id) : 0;
}

}  // namespace sdlqr
