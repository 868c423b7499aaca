#pragma once
// A recorded flight played into the view's store (latest_store.hpp) as the bus would have
// delivered it: the log is the source, so the page is the same for live and recorded flights.
// Events are played in the order of their receive times (the recorder's clock), paced against the
// wall time the caller passes, at `speed` (log seconds per wall second); play, pause, speed and
// seek. A seek empties the store and puts the newest event of each channel at or before the new
// position, so the page at once shows the flight as it was then. Clock-free and not thread-safe:
// the caller serializes (view_main.cpp holds a mutex).

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/foxglove/lcm_json.hpp"
#include "sdlqr/view/latest_store.hpp"

namespace sdlqr::view {

using Json = foxglove::Json;

class LogPlayback {
 public:
  // Events in file order; finishLoading() sorts them by receive time (stable).
  void add(std::string_view channel, int64_t receive_utime, const void* data, std::size_t size);
  void finishLoading();

  // Moves the playhead on by wall_dt_s × speed while playing, putting every event it passes into
  // the store; pauses at the last event.
  void advance(double wall_dt_s, LatestStore& store);
  void play();
  void pause() { playing_ = false; }
  // False (nothing changes) outside (0, 64].
  bool setSpeed(double speed);
  // Clamped to [0, duration].
  void seek(double position_s, LatestStore& store);

  double positionSeconds() const;
  double durationSeconds() const;
  bool playing() const { return playing_; }
  std::size_t events() const { return events_.size(); }
  // The playhead as sdlqr/playback publishes it.
  Json state(const std::string& log_path) const;

 private:
  struct Event {
    int64_t receive_utime = 0;
    uint32_t channel = 0;
    std::size_t offset = 0;  // into bytes_
    std::size_t size = 0;
  };
  void put(const Event& e, LatestStore& store) const;

  std::vector<std::string> channels_;
  std::map<std::string, uint32_t, std::less<>> channel_index_;
  std::vector<Event> events_;
  std::vector<uint8_t> bytes_;
  std::size_t next_ = 0;        // the next event to play
  int64_t position_utime_ = 0;  // [us] playhead in receive time
  double speed_ = 1.0;
  bool playing_ = true;
  uint64_t seek_count_ = 0;
};

}  // namespace sdlqr::view
