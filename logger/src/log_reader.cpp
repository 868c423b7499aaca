#include "sdlqr/logger/log_reader.hpp"

#include <lcm/eventlog.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace sdlqr::logger {

namespace {

// Sync word, event number, timestamp, channel length, data length (LCM log format).
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;

}  // namespace

struct LogReader::Impl {
  lcm_eventlog_t* log = nullptr;
  lcm_eventlog_event_t* current = nullptr;
  ~Impl() {
    if (current) lcm_eventlog_free_event(current);
    if (log) lcm_eventlog_destroy(log);
  }
};

LogReader::LogReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  status_.path = path;
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw LogError("cannot open log '" + path + "': " + std::strerror(errno));
  if (!S_ISREG(info.st_mode)) throw LogError("'" + path + "' is not a regular file");
  status_.file_bytes = static_cast<int64_t>(info.st_size);
  impl_->log = lcm_eventlog_create(path.c_str(), "r");
  if (!impl_->log) throw LogError("cannot open log '" + path + "': " + std::strerror(errno));
}

LogReader::~LogReader() = default;

bool LogReader::next(LogEvent* event) {
  if (impl_->current) {
    lcm_eventlog_free_event(impl_->current);
    impl_->current = nullptr;
  }
  while (true) {
    lcm_eventlog_event_t* e = lcm_eventlog_read_next_event(impl_->log);
    const int64_t offset = static_cast<int64_t>(ftello(impl_->log->f));
    if (!e) {
      // LCM gives up on an event with an implausible header but leaves the file positioned
      // after it: reading on resynchronizes on the next sync word.
      if (offset >= 0 && offset < status_.file_bytes && offset > status_.readable_bytes) continue;
      status_.truncated_tail_bytes = status_.file_bytes - status_.readable_bytes;
      return false;
    }
    const int64_t start = offset - kEventHeaderBytes - e->channellen - e->datalen;
    if (start > status_.readable_bytes) status_.skipped_bytes += start - status_.readable_bytes;
    status_.readable_bytes = offset;
    if (status_.events == 0) status_.first_receive_utime = e->timestamp;
    status_.last_receive_utime = e->timestamp;
    ++status_.events;
    impl_->current = e;
    event->event_number = e->eventnum;
    event->receive_utime = e->timestamp;
    event->channel = std::string_view(e->channel, static_cast<size_t>(e->channellen));
    event->data = static_cast<const uint8_t*>(e->data);
    event->size = e->datalen;
    return true;
  }
}

void readFirstEvent(LogReader& reader, LogEvent* event) {
  if (reader.next(event)) return;
  throw LogError("'" + reader.status().path + "' holds no LCM event" +
                 std::string(reader.status().file_bytes == 0 ? " (empty file)" : " (not an LCM event log?)"));
}

void ReadProgress::update(const LogReader& reader) {
  if (!report_) return;
  const int64_t file_bytes = std::max<int64_t>(1, reader.status().file_bytes);
  while (next_percent_ <= 100 && reader.position() * 100 >= next_percent_ * file_bytes) {
    report_(next_percent_, reader.status().events);
    next_percent_ += 10;
  }
}

}  // namespace sdlqr::logger
