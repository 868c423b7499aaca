#include "sdlqr/estimator/state_history.hpp"

#include <stdexcept>

namespace sdlqr::estimator {

StateHistory::StateHistory(int capacity) {
  if (capacity < 2) throw std::invalid_argument("StateHistory: capacity must be >= 2");
  entries_.resize(static_cast<size_t>(capacity));
}

HistoryEntry& StateHistory::pushNewest() {
  if (size_ == capacity()) {
    head_ = (head_ + 1) % entries_.size();
  } else {
    ++size_;
  }
  return newest();
}

int StateHistory::indexAtOrBefore(int64_t t) const {
  // Entries are in time order; a binary search keeps the rewind cost independent of history length.
  int lo = 0;
  int hi = size_ - 1;
  int found = -1;
  while (lo <= hi) {
    const int mid = lo + (hi - lo) / 2;
    if (at(mid).utime <= t) {
      found = mid;
      lo = mid + 1;
    } else {
      hi = mid - 1;
    }
  }
  return found;
}

}  // namespace sdlqr::estimator
