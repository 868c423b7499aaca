#pragma once
// The transports of a MAVLink link (operating-system I/O, for the mains; the cores never see it):
//   udp://[HOST]:PORT         listen on HOST:PORT (PX4's offboard link sends to 14540: SITL's
//                             `mavlink start -u 14580 -m onboard -o 14540`) and answer whoever sent
//                             the last datagram that held a frame the receiver accepted
//   udpout://HOST:PORT[:BIND] send to HOST:PORT from local port BIND (any when absent); datagrams
//                             from elsewhere are dropped (counted)
//   serial:DEVICE:BAUD        a serial port, raw 8N1, e.g. serial:/dev/ttyACM0:921600
// A datagram is read whole; a serial read takes what is there. Nothing blocks: the main polls fd()
// beside the bus (bus::Node::watchDescriptor).

#include <netinet/in.h>

#include <cstdint>
#include <memory>
#include <string>

#include "sdlqr/px4/mavlink_endpoint.hpp"

namespace sdlqr::px4 {

class LinkIo : public ByteSink {
 public:
  // Throws std::invalid_argument "--mavlink URL: reason" for a URL it cannot open.
  static std::unique_ptr<LinkIo> open(const std::string& url);
  ~LinkIo() override;
  LinkIo(const LinkIo&) = delete;
  LinkIo& operator=(const LinkIo&) = delete;

  int fd() const { return fd_; }
  bool datagrams() const { return kind_ != Kind::kSerial; }
  // Reads what is ready: on_bytes(data, size) per datagram (UDP) or per read (serial). Returns the
  // number of reads; -1 on an error that ends the link (a serial port unplugged).
  template <class OnBytes>
  int readReady(OnBytes&& on_bytes) {
    int reads = 0;
    for (;;) {
      const long n = readOnce();
      if (n == -2) return reads;  // nothing more now
      if (n < 0) return -1;
      ++reads;
      on_bytes(buffer_, static_cast<size_t>(n));
    }
  }
  // udp://: the last datagram held a frame the receiver accepted; answer its sender from now on.
  void acceptLastSender();
  bool write(const uint8_t* data, size_t size) override;
  bool hasPeer() const { return peer_known_; }
  int64_t foreignDatagrams() const { return foreign_; }
  std::string describe() const { return description_; }

 private:
  enum class Kind { kUdpListen, kUdpOut, kSerial };
  LinkIo() = default;
  long readOnce();  // bytes read; -2 when nothing is ready; -1 on an error

  Kind kind_ = Kind::kUdpListen;
  int fd_ = -1;
  sockaddr_in peer_{};
  sockaddr_in last_sender_{};
  bool peer_known_ = false;
  int64_t foreign_ = 0;
  std::string description_;
  uint8_t buffer_[65536];
};

}  // namespace sdlqr::px4
