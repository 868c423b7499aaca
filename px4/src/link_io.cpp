#include "sdlqr/px4/link_io.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sdlqr::px4 {

namespace {

[[noreturn]] void fail(const std::string& url, const std::string& reason) {
  throw std::invalid_argument("--mavlink " + url + ": " + reason);
}

int portOf(const std::string& url, const std::string& text) {
  char* end = nullptr;
  const long port = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || port < 0 || port > 65535) fail(url, "'" + text + "' is no port");
  return static_cast<int>(port);
}

sockaddr_in addressOf(const std::string& url, const std::string& host, int port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  if (host.empty() || host == "0.0.0.0") {
    a.sin_addr.s_addr = htonl(INADDR_ANY);
    return a;
  }
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), nullptr, &hints, &found) != 0 || found == nullptr) fail(url, "cannot resolve " + host);
  a.sin_addr = reinterpret_cast<sockaddr_in*>(found->ai_addr)->sin_addr;
  freeaddrinfo(found);
  return a;
}

int udpSocket(const std::string& url, const sockaddr_in& bind_to) {
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) fail(url, std::string("socket: ") + std::strerror(errno));
  const int yes = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  if (bind(fd, reinterpret_cast<const sockaddr*>(&bind_to), sizeof bind_to) != 0) {
    const std::string reason = std::strerror(errno);
    close(fd);
    fail(url, "bind: " + reason);
  }
  return fd;
}

speed_t baudOf(const std::string& url, const std::string& text) {
  static const std::pair<long, speed_t> rates[] = {
      {9600, B9600},     {19200, B19200},   {38400, B38400},     {57600, B57600},     {115200, B115200},
      {230400, B230400}, {460800, B460800}, {921600, B921600},   {1500000, B1500000}, {2000000, B2000000},
      {3000000, B3000000}};
  const long baud = std::strtol(text.c_str(), nullptr, 10);
  for (const auto& [value, speed] : rates) {
    if (value == baud) return speed;
  }
  fail(url, "baud rate '" + text + "' not supported (9600 ... 3000000)");
}

int serialPort(const std::string& url, const std::string& device, const std::string& baud) {
  const speed_t speed = baudOf(url, baud);
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail(url, device + ": " + std::strerror(errno));
  termios tty{};
  if (tcgetattr(fd, &tty) != 0) {
    close(fd);
    fail(url, device + " is no serial port");
  }
  cfmakeraw(&tty);
  tty.c_cflag |= CLOCAL | CREAD;
  tty.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);
  cfsetispeed(&tty, speed);
  cfsetospeed(&tty, speed);
  if (tcsetattr(fd, TCSANOW, &tty) != 0) {
    close(fd);
    fail(url, device + ": cannot set " + baud + " baud");
  }
  return fd;
}

// "HOST:PORT" -> host, port text (HOST may be empty).
std::pair<std::string, std::string> hostAndPort(const std::string& url, const std::string& rest) {
  const size_t colon = rest.rfind(':');
  if (colon == std::string::npos) fail(url, "expected HOST:PORT");
  return {rest.substr(0, colon), rest.substr(colon + 1)};
}

}  // namespace

std::unique_ptr<LinkIo> LinkIo::open(const std::string& url) {
  std::unique_ptr<LinkIo> link(new LinkIo());
  if (url.rfind("udp://", 0) == 0) {
    const auto [host, port] = hostAndPort(url, url.substr(6));
    link->kind_ = Kind::kUdpListen;
    link->fd_ = udpSocket(url, addressOf(url, host, portOf(url, port)));
    link->description_ = "UDP, listening on " + (host.empty() ? std::string("*") : host) + ":" + port;
  } else if (url.rfind("udpout://", 0) == 0) {
    std::string rest = url.substr(9);
    int bind_port = 0;
    const size_t first = rest.find(':');
    const size_t last = rest.rfind(':');
    if (first != last) {
      bind_port = portOf(url, rest.substr(last + 1));
      rest = rest.substr(0, last);
    }
    const auto [host, port] = hostAndPort(url, rest);
    if (host.empty()) fail(url, "udpout:// needs the host to send to");
    link->kind_ = Kind::kUdpOut;
    link->fd_ = udpSocket(url, addressOf(url, "", bind_port));
    link->peer_ = addressOf(url, host, portOf(url, port));
    link->peer_known_ = true;
    link->description_ = "UDP to " + host + ":" + port + (bind_port ? " from port " + std::to_string(bind_port) : "");
  } else if (url.rfind("serial:", 0) == 0) {
    const auto [device, baud] = hostAndPort(url, url.substr(7));
    link->kind_ = Kind::kSerial;
    link->fd_ = serialPort(url, device, baud);
    link->description_ = "serial " + device + " at " + baud + " baud";
  } else {
    fail(url, "expected udp://[HOST]:PORT, udpout://HOST:PORT[:BIND] or serial:DEVICE:BAUD");
  }
  return link;
}

LinkIo::~LinkIo() {
  if (fd_ >= 0) close(fd_);
}

long LinkIo::readOnce() {
  if (kind_ == Kind::kSerial) {
    const ssize_t n = ::read(fd_, buffer_, sizeof buffer_);
    if (n > 0) return n;
    if (n == 0) return -1;  // end of file: the device went away
    return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR ? -2 : -1;
  }
  for (;;) {
    sockaddr_in from{};
    socklen_t length = sizeof from;
    const ssize_t n = recvfrom(fd_, buffer_, sizeof buffer_, 0, reinterpret_cast<sockaddr*>(&from), &length);
    if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR ? -2 : -1;
    const bool from_peer = from.sin_addr.s_addr == peer_.sin_addr.s_addr && from.sin_port == peer_.sin_port;
    if (kind_ == Kind::kUdpOut && !from_peer) {
      ++foreign_;
      continue;
    }
    last_sender_ = from;
    return n;
  }
}

void LinkIo::acceptLastSender() {
  if (kind_ != Kind::kUdpListen) return;
  peer_ = last_sender_;
  peer_known_ = true;
}

bool LinkIo::write(const uint8_t* data, size_t size) {
  if (kind_ == Kind::kSerial) return ::write(fd_, data, size) == static_cast<ssize_t>(size);
  if (!peer_known_) return false;  // udp:// before the autopilot spoke: nobody to answer yet
  return sendto(fd_, data, size, 0, reinterpret_cast<const sockaddr*>(&peer_), sizeof peer_) ==
         static_cast<ssize_t>(size);
}

}  // namespace sdlqr::px4
