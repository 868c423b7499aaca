#include "sdlqr/logger/recorder.hpp"

#include <fcntl.h>
#include <lcm/eventlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace sdlqr::logger {

struct Recorder::Log {
  lcm_eventlog_t* log = nullptr;
  bool dirty = false;  // written since the last flush
  std::chrono::steady_clock::time_point last_flush = std::chrono::steady_clock::now();
};

Recorder::Recorder(const RecorderOptions& options)
    : path_(options.path),
      flush_period_(options.flush_period),
      queue_(options.queue_events, options.queue_bytes),
      log_(std::make_unique<Log>()) {
  // O_EXCL claims the name atomically: two recorders can never share or clobber a file.
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    if (errno == EEXIST) throw std::invalid_argument("refusing to overwrite existing '" + path_ + "'");
    throw std::invalid_argument("cannot create '" + path_ + "': " + std::strerror(errno));
  }
  ::close(fd);
  log_->log = lcm_eventlog_create(path_.c_str(), "w");
  if (!log_->log) {
    const std::string reason = std::strerror(errno);
    ::unlink(path_.c_str());  // the empty file we just claimed
    throw std::invalid_argument("cannot open '" + path_ + "' for writing: " + reason);
  }
  writer_ = std::thread(&Recorder::writerLoop, this);
}

Recorder::~Recorder() { stop(); }

void Recorder::stop() {
  if (stopped_) return;
  stopped_ = true;
  queue_.close();
  if (writer_.joinable()) writer_.join();
  flush();
  lcm_eventlog_destroy(log_->log);
  log_->log = nullptr;
}

void Recorder::noteError(const std::string& what) {
  ++write_errors_;
  std::lock_guard<std::mutex> lock(error_mutex_);
  last_error_ = what;
}

void Recorder::flush() {
  if (!log_->dirty) return;
  if (std::fflush(log_->log->f) != 0) noteError(std::string("flush failed: ") + std::strerror(errno));
  log_->dirty = false;
  log_->last_flush = std::chrono::steady_clock::now();
  ++flushes_;
}

void Recorder::writerLoop() {
  QueuedEvent event;
  // Waking at least twice per flush period bounds the age of unflushed data by ~1.5 periods
  // even when the bus goes quiet.
  const auto wait = std::max(std::chrono::milliseconds(1), flush_period_ / 2);
  while (true) {
    if (queue_.pop(&event, wait)) {
      lcm_eventlog_event_t record{};
      record.timestamp = event.receive_utime;
      record.channellen = static_cast<int32_t>(event.channel.size());
      record.datalen = static_cast<int32_t>(event.data.size());
      record.channel = event.channel.data();
      record.data = event.data.data();
      if (lcm_eventlog_write_event(log_->log, &record) != 0) {
        noteError(std::string("write failed: ") + std::strerror(errno));
      } else {
        ++written_;
        bytes_written_ += record.datalen;
      }
      log_->dirty = true;
    } else if (queue_.closedAndEmpty()) {
      return;
    }
    if (std::chrono::steady_clock::now() - log_->last_flush >= flush_period_) flush();
  }
}

RecorderStats Recorder::stats() const {
  const EventQueueStats q = queue_.stats();
  RecorderStats s;
  s.queued = q.pushed;
  s.dropped = q.dropped;
  s.max_queue_depth = q.max_depth;
  s.written = written_.load();
  s.bytes_written = bytes_written_.load();
  s.write_errors = write_errors_.load();
  s.flushes = flushes_.load();
  std::lock_guard<std::mutex> lock(error_mutex_);
  s.last_error = last_error_;
  return s;
}

}  // namespace sdlqr::logger
