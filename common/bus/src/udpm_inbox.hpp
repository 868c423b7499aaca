#pragma once
// LCM's UDP multicast receive path, in the caller's thread. LCM 1.3.1's udpm provider reads its
// socket in a thread of its own and wakes the handling thread through a pipe: two thread
// wake-ups, a pipe write and read and two lock round trips per message, which on a 2-vCPU VM
// cost more than most handlers (bench/README.md, "The bus"). The Node publishes with LCM and
// reads udpm sockets itself: one wake-up, then every datagram ready is read at once.
//
// Wire format (LCM's UDP multicast protocol, all integers big-endian):
//   short message:  uint32 magic "LC02", uint32 sequence, channel + NUL, payload
//   fragment:       uint32 magic "LC03", uint32 sequence, uint32 payload size, uint32 offset
//                   of this fragment's data in the payload, uint16 fragment number, uint16
//                   fragment count; fragment 0 carries channel + NUL before its data.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sdlqr::bus {

// One complete message; the pointers stay valid until the next UdpmInbox::drain().
struct WireMessage {
  std::string_view channel;
  const uint8_t* data = nullptr;
  uint32_t size = 0;
  int64_t receive_utime = 0;  // [us] kernel receive time of its last datagram (wall clock)
};

// Reassembles fragmented messages, one in progress per sender (an LCM publisher sends the
// fragments of a message back to back from one socket; a new sequence number drops the old one).
class FragmentAssembler {
 public:
  // Offers one "LC03" datagram; true when it completes a message, which is then in channel()
  // and data() until the next call for that sender.
  bool add(uint64_t sender, const uint8_t* packet, size_t size);
  const std::string& channel() const { return completed_->channel; }
  const std::vector<uint8_t>& data() const { return completed_->data; }

 private:
  struct Partial {
    uint64_t sender = 0;
    uint32_t sequence = 0;
    uint32_t remaining = 0;  // fragments still missing
    std::string channel;
    std::vector<uint8_t> data;
  };
  std::vector<Partial> partials_;  // one per sender, few
  const Partial* completed_ = nullptr;
};

// Parses a short message datagram; false for anything else or a malformed one.
bool parseShortMessage(const uint8_t* packet, size_t size, WireMessage* out);
bool isFragment(const uint8_t* packet, size_t size);

// A socket bound to the URL's port, joined to its group, read without blocking.
class UdpmInbox {
 public:
  // Throws std::runtime_error naming the URL when the socket cannot be set up.
  explicit UdpmInbox(const std::string& url);
  ~UdpmInbox();
  UdpmInbox(const UdpmInbox&) = delete;
  UdpmInbox& operator=(const UdpmInbox&) = delete;

  int fd() const { return fd_; }
  // Reads every datagram ready now (at most kMaxBatch) and returns the complete messages in
  // arrival order. Returns false on a socket error.
  bool drain(std::vector<WireMessage>* messages);
  int64_t datagrams() const { return datagrams_; }  // read so far
  int64_t malformed() const { return malformed_; }  // not LCM, or broken
  // Datagrams the kernel dropped for this socket since it opened (its receive buffer was full:
  // the process did not read in time), as of the last datagram read (SO_RXQ_OVFL).
  int64_t kernelDropped() const { return kernel_dropped_; }

  static constexpr size_t kMaxBatch = 64;

 private:
  int fd_ = -1;
  std::vector<uint8_t> packet_;  // one datagram (up to 64 KiB)
  std::vector<uint8_t> arena_;   // the batch's messages, back to back
  std::vector<std::string> fragment_channels_;  // channels of reassembled messages of the batch
  FragmentAssembler fragments_;
  int64_t datagrams_ = 0;
  int64_t malformed_ = 0;
  int64_t kernel_dropped_ = 0;
};

}  // namespace sdlqr::bus
