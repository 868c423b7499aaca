#include "sdlqr/logger/logger_core.hpp"

#include "sdlqr/logger/channel_types.hpp"

namespace sdlqr::logger {

namespace {

// All our messages start with int64_t utime after LCM's 8-byte fingerprint (big-endian).
bool peekUtime(const std::string& channel, const void* data, uint32_t size, int64_t* utime) {
  if (size < 16 || !findChannelType(splitChannel(channel).base)) return false;
  const auto* bytes = static_cast<const uint8_t*>(data) + 8;
  uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | bytes[i];
  *utime = static_cast<int64_t>(value);
  return true;
}

}  // namespace

LoggerCore::LoggerCore(const RecorderOptions& options)
    : recorder_(options),
      written_(health_.counters().add("logger.written")),
      bytes_(health_.counters().add("logger.bytes")),
      overflow_(health_.counters().add("logger.queue_overflow")),
      write_errors_(health_.counters().add("logger.write_errors")),
      flushes_(health_.counters().add("logger.flushes")),
      max_depth_(health_.counters().add("logger.queue_max_depth")) {
  health_.setState(ProcessState::kRunning);
}

void LoggerCore::onMessage(const std::string& channel, const void* data, uint32_t size, int64_t receive_utime) {
  if (!recorder_.push(channel, data, size, receive_utime)) health_.countDropped(1);
  int64_t utime = 0;
  if (peekUtime(channel, data, size, &utime) && utime > latest_utime_) latest_utime_ = utime;
}

void LoggerCore::onWallTime(double now_s) {
  if (now_s < next_stats_s_) return;
  next_stats_s_ = now_s + 0.1;
  mirrorStats();
}

void LoggerCore::stop() {
  recorder_.stop();
  mirrorStats();
}

void LoggerCore::mirrorStats() {
  const RecorderStats s = recorder_.stats();
  Counters& c = health_.counters();
  for (int64_t i = c.value(write_errors_); i < s.write_errors; ++i) health_.countError();
  c.set(written_, s.written);
  c.set(bytes_, s.bytes_written);
  c.set(overflow_, s.dropped);
  c.set(write_errors_, s.write_errors);
  c.set(flushes_, s.flushes);
  c.set(max_depth_, s.max_queue_depth);
  health_.setSimTime(latest_utime_);
  if (s.write_errors > 0) {
    health_.setState(ProcessState::kDegraded);
    health_.setLastError(s.last_error);
  }
}

}  // namespace sdlqr::logger
