#include "sdlqr/view/log_playback.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

namespace sdlqr::view {

void LogPlayback::add(std::string_view channel, int64_t receive_utime, const void* data, std::size_t size) {
  auto it = channel_index_.find(channel);
  if (it == channel_index_.end()) {
    it = channel_index_.emplace(std::string(channel), static_cast<uint32_t>(channels_.size())).first;
    channels_.emplace_back(channel);
  }
  events_.push_back({receive_utime, it->second, bytes_.size(), size});
  bytes_.resize(bytes_.size() + size);
  if (size > 0) std::memcpy(bytes_.data() + events_.back().offset, data, size);
}

void LogPlayback::finishLoading() {
  std::stable_sort(events_.begin(), events_.end(),
                   [](const Event& a, const Event& b) { return a.receive_utime < b.receive_utime; });
  next_ = 0;
  position_utime_ = events_.empty() ? 0 : events_.front().receive_utime;
}

void LogPlayback::put(const Event& e, LatestStore& store) const {
  const uint8_t* data = bytes_.data() + e.offset;
  store.put(channels_[e.channel], sourceOf(channels_[e.channel], data, e.size), e.receive_utime, data, e.size);
}

void LogPlayback::advance(double wall_dt_s, LatestStore& store) {
  if (!playing_ || events_.empty()) return;
  position_utime_ += static_cast<int64_t>(std::llround(wall_dt_s * speed_ * 1e6));
  while (next_ < events_.size() && events_[next_].receive_utime <= position_utime_) put(events_[next_++], store);
  if (next_ == events_.size()) {
    position_utime_ = events_.back().receive_utime;
    playing_ = false;
  }
}

void LogPlayback::play() {
  if (!events_.empty() && next_ == events_.size()) return;  // at the end: seek first
  playing_ = true;
}

bool LogPlayback::setSpeed(double speed) {
  if (!(speed > 0.0 && speed <= 64.0)) return false;
  speed_ = speed;
  return true;
}

void LogPlayback::seek(double position_s, LatestStore& store) {
  if (events_.empty()) return;
  const int64_t start = events_.front().receive_utime;
  position_utime_ = start + static_cast<int64_t>(std::llround(std::clamp(position_s, 0.0, durationSeconds()) * 1e6));
  next_ = static_cast<std::size_t>(
      std::upper_bound(events_.begin(), events_.end(), position_utime_,
                       [](int64_t t, const Event& e) { return t < e.receive_utime; }) - events_.begin());
  // The newest event of each channel and source (sourceOf: each process of a HEARTBEAT channel)
  // at or before the playhead, oldest first.
  std::set<std::pair<uint32_t, std::string>> seen;
  std::vector<const Event*> newest;
  for (std::size_t i = next_; i-- > 0;) {
    const Event& e = events_[i];
    if (seen.emplace(e.channel, sourceOf(channels_[e.channel], bytes_.data() + e.offset, e.size)).second) newest.push_back(&e);
  }
  store.clear();
  for (auto it = newest.rbegin(); it != newest.rend(); ++it) put(**it, store);
  ++seek_count_;
}

double LogPlayback::positionSeconds() const {
  return events_.empty() ? 0.0 : 1e-6 * static_cast<double>(position_utime_ - events_.front().receive_utime);
}

double LogPlayback::durationSeconds() const {
  return events_.empty() ? 0.0 : 1e-6 * static_cast<double>(events_.back().receive_utime - events_.front().receive_utime);
}

Json LogPlayback::state(const std::string& log_path) const {
  return {{"log", log_path},
          {"position_s", positionSeconds()},
          {"duration_s", durationSeconds()},
          {"speed", speed_},
          {"playing", playing_},
          {"seek_count", seek_count_},
          {"start_utime", events_.empty() ? int64_t{0} : events_.front().receive_utime}};
}

}  // namespace sdlqr::view
