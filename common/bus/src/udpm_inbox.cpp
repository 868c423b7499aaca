#include "udpm_inbox.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "sdlqr/bus/bus_layout.hpp"

namespace sdlqr::bus {

namespace {

constexpr uint32_t kMagicShort = 0x4c433032;  // "LC02"
constexpr uint32_t kMagicFragment = 0x4c433033;  // "LC03"
constexpr size_t kShortHeader = 8;
constexpr size_t kFragmentHeader = 20;
constexpr size_t kMaxChannel = 63;  // LCM_MAX_CHANNEL_NAME_LENGTH
constexpr uint32_t kMaxMessage = 1u << 28;  // LCM_MAX_MESSAGE_SIZE
constexpr size_t kMaxDatagram = 65536;
// The socket is read only when the process spins: room for a burst of large messages (the
// kernel caps it at net.core.rmem_max). `recv_buf_size=N` in the URL sets it, as for LCM.
constexpr int kDefaultReceiveBuffer = 1 << 20;

int receiveBufferSize(const std::string& options) {
  const std::string key = "recv_buf_size=";
  size_t at = 0;
  while (at < options.size()) {
    const size_t end = std::min(options.find('&', at), options.size());
    if (options.compare(at, key.size(), key) == 0) {
      const std::string value = options.substr(at + key.size(), end - at - key.size());
      if (value.empty() || value.size() > 9 || value.find_first_not_of("0123456789") != std::string::npos) {
        throw std::invalid_argument("--lcm-url: recv_buf_size: expected a number of bytes, got '" + value + "'");
      }
      return std::stoi(value);
    }
    at = end + 1;
  }
  return kDefaultReceiveBuffer;
}

uint32_t be32(const uint8_t* p) { return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3]; }
uint16_t be16(const uint8_t* p) { return static_cast<uint16_t>((p[0] << 8) | p[1]); }

// Length of the NUL-terminated channel at p (within size), or 0 when it has none or is too long.
size_t channelLength(const uint8_t* p, size_t size) {
  const void* nul = std::memchr(p, 0, std::min(size, kMaxChannel + 1));
  if (nul == nullptr) return 0;
  return static_cast<size_t>(static_cast<const uint8_t*>(nul) - p);
}

}  // namespace

bool parseShortMessage(const uint8_t* packet, size_t size, WireMessage* out) {
  if (size < kShortHeader + 1 || be32(packet) != kMagicShort) return false;
  const uint8_t* channel = packet + kShortHeader;
  const size_t length = channelLength(channel, size - kShortHeader);
  if (length == 0) return false;
  out->channel = std::string_view(reinterpret_cast<const char*>(channel), length);
  out->data = channel + length + 1;
  out->size = static_cast<uint32_t>(size - kShortHeader - length - 1);
  return true;
}

bool isFragment(const uint8_t* packet, size_t size) {
  return size >= kFragmentHeader && be32(packet) == kMagicFragment;
}

bool FragmentAssembler::add(uint64_t sender, const uint8_t* packet, size_t size) {
  if (!isFragment(packet, size)) return false;
  const uint32_t sequence = be32(packet + 4);
  const uint32_t total = be32(packet + 8);
  const uint32_t offset = be32(packet + 12);
  const uint16_t number = be16(packet + 16);
  const uint16_t count = be16(packet + 18);
  const uint8_t* body = packet + kFragmentHeader;
  size_t body_size = size - kFragmentHeader;
  if (total > kMaxMessage || count == 0 || number >= count) return false;

  Partial* partial = nullptr;
  for (Partial& p : partials_) {
    if (p.sender == sender) partial = &p;
  }
  if (partial == nullptr) {
    partials_.push_back(Partial{});
    partial = &partials_.back();
    partial->sender = sender;
  }
  if (number == 0) {
    // A new message from this sender: whatever was in progress is lost (as in LCM).
    const size_t length = channelLength(body, body_size);
    if (length == 0) return false;
    partial->sequence = sequence;
    partial->remaining = count;
    partial->channel.assign(reinterpret_cast<const char*>(body), length);
    partial->data.assign(total, 0);
    body += length + 1;
    body_size -= length + 1;
  } else if (partial->remaining == 0 || partial->sequence != sequence || partial->data.size() != total) {
    return false;  // its first fragment was lost
  }
  if (static_cast<uint64_t>(offset) + body_size > total) {
    partial->remaining = 0;
    return false;
  }
  std::memcpy(partial->data.data() + offset, body, body_size);
  if (--partial->remaining != 0) return false;
  completed_ = partial;
  return true;
}

UdpmInbox::UdpmInbox(const std::string& url) : packet_(kMaxDatagram) {
  const UdpmUrl parts = parseUdpmUrl(url);
  const int buffer_size = receiveBufferSize(parts.options);
  in_addr group{};
  if (inet_aton(parts.address.c_str(), &group) == 0) throw std::runtime_error("bad multicast address in '" + url + "'");
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  const int on = 1;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_ANY);
  address.sin_port = htons(static_cast<uint16_t>(parts.port));
  ip_mreq membership{};
  membership.imr_multiaddr = group;
  membership.imr_interface.s_addr = htonl(INADDR_ANY);
  // As LCM: several processes share the port; the kernel stamps each datagram's arrival.
  if (fd_ < 0 || setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) != 0 ||
      setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMP, &on, sizeof on) != 0 ||
      setsockopt(fd_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on) != 0 ||
      setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &buffer_size, sizeof buffer_size) != 0 ||
      bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
      setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0) {
    const std::string reason = std::strerror(errno);
    if (fd_ >= 0) close(fd_);
    throw std::runtime_error("cannot receive on LCM bus '" + url + "': " + reason +
                             " (is multicast routed? see README, Troubleshooting)");
  }
  arena_.reserve(kMaxBatch * 2048);
  fragment_channels_.reserve(kMaxBatch);
}

UdpmInbox::~UdpmInbox() {
  if (fd_ >= 0) close(fd_);
}

bool UdpmInbox::drain(std::vector<WireMessage>* messages) {
  messages->clear();
  arena_.clear();
  fragment_channels_.clear();
  // Messages are first placed by arena offset: the arena may grow while the batch is read.
  struct Placed {
    size_t channel_offset;  // in arena_, or the index in fragment_channels_ when fragmented
    size_t channel_size;
    bool fragmented;
    size_t data_offset;
    uint32_t size;
    int64_t receive_utime;
  };
  Placed placed[kMaxBatch];
  size_t count = 0;
  while (count < kMaxBatch) {
    sockaddr_in from{};
    iovec vector{packet_.data(), packet_.size()};
    alignas(cmsghdr) char control[128];  // SCM_TIMESTAMP and SO_RXQ_OVFL
    msghdr header{};
    header.msg_name = &from;
    header.msg_namelen = sizeof from;
    header.msg_iov = &vector;
    header.msg_iovlen = 1;
    header.msg_control = control;
    header.msg_controllen = sizeof control;
    const ssize_t size = recvmsg(fd_, &header, MSG_DONTWAIT);
    if (size < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK) break;
      if (errno == EINTR) continue;
      return false;
    }
    ++datagrams_;
    int64_t receive_utime = 0;
    for (cmsghdr* c = CMSG_FIRSTHDR(&header); c != nullptr; c = CMSG_NXTHDR(&header, c)) {
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_TIMESTAMP) {
        timeval stamp{};
        std::memcpy(&stamp, CMSG_DATA(c), sizeof stamp);
        receive_utime = int64_t{stamp.tv_sec} * 1000000 + stamp.tv_usec;
      } else if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
        uint32_t dropped = 0;  // the socket's total so far, sent with each datagram
        std::memcpy(&dropped, CMSG_DATA(c), sizeof dropped);
        kernel_dropped_ = dropped;
      }
    }
    const uint8_t* packet = packet_.data();
    const size_t packet_size = static_cast<size_t>(size);
    WireMessage message;
    if ((header.msg_flags & MSG_TRUNC) == 0 && parseShortMessage(packet, packet_size, &message)) {
      const size_t channel_offset = arena_.size();
      arena_.insert(arena_.end(), message.channel.begin(), message.channel.end());
      const size_t data_offset = arena_.size();
      arena_.insert(arena_.end(), message.data, message.data + message.size);
      placed[count++] = {channel_offset, message.channel.size(), false, data_offset, message.size, receive_utime};
      continue;
    }
    const uint64_t sender = (uint64_t{from.sin_addr.s_addr} << 16) | from.sin_port;
    if ((header.msg_flags & MSG_TRUNC) == 0 && isFragment(packet, packet_size)) {
      if (!fragments_.add(sender, packet, packet_size)) continue;
      fragment_channels_.push_back(fragments_.channel());
      const size_t data_offset = arena_.size();
      arena_.insert(arena_.end(), fragments_.data().begin(), fragments_.data().end());
      placed[count++] = {fragment_channels_.size() - 1, fragments_.channel().size(), true, data_offset,
                         static_cast<uint32_t>(fragments_.data().size()), receive_utime};
      continue;
    }
    ++malformed_;
  }
  for (size_t i = 0; i < count; ++i) {
    const Placed& p = placed[i];
    WireMessage m;
    m.channel = p.fragmented ? std::string_view(fragment_channels_[p.channel_offset])
                             : std::string_view(reinterpret_cast<const char*>(arena_.data() + p.channel_offset), p.channel_size);
    m.data = arena_.data() + p.data_offset;
    m.size = p.size;
    m.receive_utime = p.receive_utime;
    messages->push_back(m);
  }
  return true;
}

}  // namespace sdlqr::bus
