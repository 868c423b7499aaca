#pragma once
// One end of a MAVLink 2 link, without the transport: frames what a core sends (sequence,
// signing) and hands the bytes to a ByteSink (a UDP socket, a serial port, a test's buffer);
// parses what arrives (bytes of datagrams or of a stream) into checked frames. The signing clock
// is injected (a main passes the wall clock; tests a counter), so the endpoint stays clock-free.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include "sdlqr/mavlink/frame.hpp"
#include "sdlqr/mavlink/messages.hpp"
#include "sdlqr/mavlink/parser.hpp"

namespace sdlqr::px4 {

class ByteSink {
 public:
  virtual ~ByteSink() = default;
  // One whole frame. Returns false when the transport could not take it (counted).
  virtual bool write(const uint8_t* data, size_t size) = 0;
};
// Takes every frame and keeps none (benchmarks and fuzzing, where only the work of writing counts).
class DiscardingSink : public ByteSink {
 public:
  bool write(const uint8_t*, size_t) override { return true; }
};

// signing.hpp's clock (10 us since 2015), read when a frame is signed or checked.
using SigningClock = std::function<uint64_t()>;

class MavlinkEndpoint;
// Frames a message and writes it out (MessageSinkTo calls it for every generated message).
struct FrameAndWrite {
  MavlinkEndpoint* endpoint;
  template <class Message>
  void operator()(const Message& m) const;
};

class MavlinkEndpoint final : public mavlink::MessageSinkTo<FrameAndWrite> {
 public:
  // With a key every frame sent is signed (link `link_id`) and only frames signed with it pass.
  MavlinkEndpoint(mavlink::Address self, ByteSink& out, SigningClock clock,
                  const std::optional<mavlink::SigningKey>& key = std::nullopt, uint8_t link_id = 0);

  // Bytes from the transport; on_frame(const Frame&) for each frame that passes. `datagram`: they
  // are one whole datagram (a frame cut at its end is truncated).
  template <class OnFrame>
  void receive(const uint8_t* data, size_t size, bool datagram, OnFrame&& on_frame) {
    parser_.feed(data, size, clock_(), on_frame);
    if (datagram) parser_.endDatagram();
  }

  const mavlink::ParserCounts& received() const { return parser_.counts(); }
  int64_t sent() const { return sent_; }
  int64_t sendFailures() const { return send_failures_; }
  bool signing() const { return writer_.signing(); }

  template <class Message>
  void put(const Message& m) {
    const size_t size = writer_.write(m, clock_(), buffer_);
    if (out_.write(buffer_, size)) {
      ++sent_;
    } else {
      ++send_failures_;
    }
  }


 private:
  mavlink::FrameWriter writer_;
  mavlink::Parser parser_;
  ByteSink& out_;
  SigningClock clock_;
  uint8_t buffer_[mavlink::kMaxFrameSize];
  int64_t sent_ = 0;
  int64_t send_failures_ = 0;
};

template <class Message>
void FrameAndWrite::operator()(const Message& m) const {
  endpoint->put(m);
}

}  // namespace sdlqr::px4
