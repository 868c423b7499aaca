#include "sdlqr/view/latest_store.hpp"

#include <cstring>

#include "sdlqr/bus/decode.hpp"
#include "sdlqr/messages/channels.hpp"

namespace sdlqr::view {

bool LatestStore::put(std::string_view channel, std::string_view source, int64_t receive_utime, const void* data,
                      std::size_t size) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (size > max_message_bytes_) {
    ++stats_.refused_size;
    return false;
  }
  key_.assign(channel).push_back('\0');
  key_.append(source);
  auto it = index_.find(key_);
  if (it == index_.end()) {
    if (index_.size() >= max_slots_) {
      ++stats_.refused_slots;
      return false;
    }
    std::size_t slot = 0;  // a slot cleared by clear() is reused
    while (slot < slots_.size() && !slots_[slot].channel.empty()) ++slot;
    if (slot == slots_.size()) slots_.emplace_back();
    slots_[slot].channel = std::string(channel);
    slots_[slot].source = std::string(source);
    it = index_.emplace(key_, slot).first;
  }
  StoredMessage& m = slots_[it->second];
  m.receive_utime = receive_utime;
  m.version = ++version_;
  m.bytes.resize(size);
  if (size > 0) std::memcpy(m.bytes.data(), data, size);
  ++stats_.puts;
  return true;
}

uint64_t LatestStore::changedSince(uint64_t since, std::vector<StoredMessage>* out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::size_t n = 0;
  for (const StoredMessage& m : slots_) {
    if (m.channel.empty() || m.version <= since) continue;
    if (out->size() <= n) out->emplace_back();
    StoredMessage& copy = (*out)[n++];
    copy.channel = m.channel;
    copy.source = m.source;
    copy.receive_utime = m.receive_utime;
    copy.version = m.version;
    copy.bytes.assign(m.bytes.begin(), m.bytes.end());
  }
  out->resize(n);
  return version_;
}

void LatestStore::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (StoredMessage& m : slots_) {
    m.channel.clear();
    m.bytes.clear();
    m.version = 0;
  }
  index_.clear();
}

StoreStats LatestStore::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  StoreStats s = stats_;
  s.slots = index_.size();
  return s;
}

std::string sourceOf(std::string_view channel, const void* data, std::size_t size) {
  if (channel::baseName(channel) != channel::kHeartbeat) return {};
  heartbeat_t heartbeat;
  if (size > UINT32_MAX || bus::decode(data, static_cast<uint32_t>(size), heartbeat) != RejectReason::kNone) return {};
  return heartbeat.process;
}

}  // namespace sdlqr::view
