#pragma once
// Fixed-capacity ring buffer of past filter states on the output grid: for each grid time the
// state and covariance there and the IMU window that led to it. A delayed VIO pose rewinds to the
// entry at or before its capture time, is fused there, and the newer entries are recomputed from
// their stored IMU windows (PX4 EKF2's delayed horizon, with the re-propagation done eagerly).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sdlqr/estimator/nav_state.hpp"

namespace sdlqr::estimator {

struct HistoryEntry {
  int64_t utime = 0;          // [us] time of `state`: the end of `input`
  NavState state;
  ErrorCovariance covariance = ErrorCovariance::Zero();
  ImuDelta input;             // IMU window from the previous entry's time to utime
  int64_t imu_seq = -1;
};

class StateHistory {
 public:
  // Allocates all entries here, never later.
  explicit StateHistory(int capacity);

  void clear() { size_ = 0; }
  int size() const { return size_; }
  int capacity() const { return static_cast<int>(entries_.size()); }
  bool empty() const { return size_ == 0; }

  // Slot for a new newest entry; the oldest is dropped when full. The slot keeps stale contents.
  HistoryEntry& pushNewest();
  // 0 is the oldest, size() - 1 the newest.
  HistoryEntry& at(int index) { return entries_[physical(index)]; }
  const HistoryEntry& at(int index) const { return entries_[physical(index)]; }
  HistoryEntry& newest() { return at(size_ - 1); }
  const HistoryEntry& newest() const { return at(size_ - 1); }
  const HistoryEntry& oldest() const { return at(0); }

  // Index of the newest entry with utime <= t, or -1 when t is older than every entry.
  int indexAtOrBefore(int64_t t) const;

 private:
  size_t physical(int index) const { return (head_ + static_cast<size_t>(index)) % entries_.size(); }

  std::vector<HistoryEntry> entries_;
  size_t head_ = 0;  // physical slot of the oldest entry
  int size_ = 0;
};

}  // namespace sdlqr::estimator
