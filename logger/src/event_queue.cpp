#include "sdlqr/logger/event_queue.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace sdlqr::logger {

EventQueue::EventQueue(std::size_t max_events, std::size_t max_bytes) : slots_(max_events), max_bytes_(max_bytes) {
  if (max_events == 0) throw std::invalid_argument("event queue needs at least one slot");
  for (QueuedEvent& slot : slots_) {
    slot.channel.reserve(kSlotChannel);
    slot.data.reserve(kSlotBytes);
  }
}

bool EventQueue::push(std::string_view channel, const void* data, std::size_t size, int64_t receive_utime) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (closed_ || count_ == slots_.size() || bytes_ + size > max_bytes_) {
    ++stats_.dropped;
    return false;
  }
  QueuedEvent& slot = slots_[(head_ + count_) % slots_.size()];
  if (size <= kSlotBytes && slot.data.capacity() > kSlotBytes) {
    // The buffer a large message got is given back, in this thread, which allocated it: freed
    // by the writer thread, glibc's per-thread caches made the memory creep all the same.
    std::vector<uint8_t> typical;
    typical.reserve(kSlotBytes);
    slot.data.swap(typical);
  }
  slot.channel.assign(channel);
  slot.data.resize(size);
  if (size > 0) std::memcpy(slot.data.data(), data, size);
  slot.receive_utime = receive_utime;
  ++count_;
  bytes_ += size;
  ++stats_.pushed;
  stats_.depth = static_cast<int64_t>(count_);
  stats_.max_depth = std::max(stats_.max_depth, stats_.depth);
  ready_.notify_one();
  return true;
}

bool EventQueue::pop(QueuedEvent* out, std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!ready_.wait_for(lock, timeout, [this] { return count_ > 0 || closed_; })) return false;
  if (count_ == 0) return false;
  QueuedEvent& slot = slots_[head_];
  bytes_ -= slot.data.size();
  out->channel.assign(slot.channel);
  out->data.assign(slot.data.begin(), slot.data.end());
  out->receive_utime = slot.receive_utime;
  head_ = (head_ + 1) % slots_.size();
  --count_;
  stats_.depth = static_cast<int64_t>(count_);
  return true;
}

void EventQueue::close() {
  std::lock_guard<std::mutex> lock(mutex_);
  closed_ = true;
  ready_.notify_all();
}

bool EventQueue::closedAndEmpty() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return closed_ && count_ == 0;
}

std::size_t EventQueue::reservedBytes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::size_t bytes = 0;
  for (const QueuedEvent& slot : slots_) bytes += slot.data.capacity() + slot.channel.capacity();
  return bytes;
}

EventQueueStats EventQueue::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

}  // namespace sdlqr::logger
