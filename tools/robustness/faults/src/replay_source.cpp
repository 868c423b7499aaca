#include "sdlqr/faults/replay_source.hpp"

namespace sdlqr::faults {

void ReplaySource::heard(const uint8_t* data, uint32_t size, double now_s) {
  if (candidate_taken_s_ >= 0.0 && now_s - candidate_taken_s_ < age_s_) return;
  if (candidate_taken_s_ >= 0.0) {
    replayed_.swap(candidate_);
    replayed_taken_s_ = candidate_taken_s_;
  }
  candidate_.assign(data, data + size);
  candidate_taken_s_ = now_s;
}

const std::vector<uint8_t>* ReplaySource::replayable(double now_s) const {
  if (replayed_taken_s_ >= 0.0) return &replayed_;
  // Before the first turnover the candidate itself becomes old enough.
  if (candidate_taken_s_ >= 0.0 && now_s - candidate_taken_s_ >= age_s_) return &candidate_;
  return nullptr;
}

}  // namespace sdlqr::faults
