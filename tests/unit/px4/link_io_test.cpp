// The link transports (px4/link_io.hpp): a serial port (a pseudo-terminal standing in for
// /dev/ttyACM0) carries frames both ways at the baud asked; a URL it cannot open is a one-line
// error naming it.

#include <gtest/gtest.h>

#include <pty.h>
#include <unistd.h>

#include <vector>

#include "sdlqr/mavlink/parser.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/px4/bench_display.hpp"
#include "sdlqr/px4/frames.hpp"
#include "sdlqr/px4/link_io.hpp"

namespace sdlqr::px4 {
namespace {

std::string errorOf(const std::string& url) {
  try {
    LinkIo::open(url);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "opened";
}

TEST(LinkIo, ASerialPortCarriesFramesBothWays) {
  int master = -1, slave = -1;
  char name[64];
  ASSERT_EQ(openpty(&master, &slave, name, nullptr, nullptr), 0);
  const auto link = LinkIo::open(std::string("serial:") + name + ":921600");
  EXPECT_FALSE(link->datagrams());
  mavlink::FrameWriter autopilot(mavlink::Address{1, 1});
  mavlink::Heartbeat heartbeat;
  heartbeat.custom_mode = 393216;
  uint8_t bytes[mavlink::kMaxFrameSize];
  const size_t size = autopilot.write(heartbeat, 0, bytes);
  ASSERT_EQ(write(master, bytes, size), static_cast<ssize_t>(size));
  mavlink::Parser parser;
  std::vector<mavlink::Frame> frames;
  for (int tries = 0; tries < 100 && frames.empty(); ++tries) {
    link->readReady([&](const uint8_t* data, size_t n) {
      parser.feed(data, n, 0, [&](const mavlink::Frame& f) { frames.push_back(f); });
    });
    usleep(1000);
  }
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].as<mavlink::Heartbeat>().custom_mode, 393216u);
  EXPECT_TRUE(link->write(bytes, size));  // and back
  uint8_t echoed[mavlink::kMaxFrameSize];
  EXPECT_EQ(read(master, echoed, sizeof echoed), static_cast<ssize_t>(size));
  close(master);
  close(slave);
}

TEST(LinkIo, AUrlItCannotOpenIsAOneLineErrorNamingIt) {
  EXPECT_EQ(errorOf("tcp://1.2.3.4:5"),
            "--mavlink tcp://1.2.3.4:5: expected udp://[HOST]:PORT, udpout://HOST:PORT[:BIND] or serial:DEVICE:BAUD");
  EXPECT_EQ(errorOf("udp://:99999"), "--mavlink udp://:99999: '99999' is no port");
  EXPECT_EQ(errorOf("udpout://:14540"), "--mavlink udpout://:14540: udpout:// needs the host to send to");
  EXPECT_EQ(errorOf("serial:/dev/null:921600"), "--mavlink serial:/dev/null:921600: /dev/null is no serial port");
  EXPECT_EQ(errorOf("serial:/dev/ttyS0:1234"),
            "--mavlink serial:/dev/ttyS0:1234: baud rate '1234' not supported (9600 ... 3000000)");
}

TEST(BenchDisplay, ARollOf30DegreesReadsAlikeInBothConventions) {
  struct Discard : ByteSink {
    bool write(const uint8_t*, size_t) override { return true; }
  } sink;
  MavlinkEndpoint endpoint({1, kOnboardComputerComponent}, sink, [] { return uint64_t{0}; });
  BridgeCore core(BridgeParams(), 9.81, ValidationLimits(), endpoint, BridgeOptions{true, false});
  mavlink::FrameWriter autopilot(mavlink::Address{1, 1});
  mavlink::Odometry o;
  o.time_usec = 2'000'000;
  o.frame_id = o.child_frame_id = mavlink::mav_frame::kLocalNed;
  o.z = -1.5f;
  const double half = 15.0 * M_PI / 180.0;  // nose north, right wing 30 deg down
  o.q = {static_cast<float>(std::cos(half)), static_cast<float>(std::sin(half)), 0.0f, 0.0f};
  uint8_t bytes[mavlink::kMaxFrameSize];
  OutboxTo<NoObserver> bus{NoObserver{}};
  core.onBytes(bytes, autopilot.write(o, 0, bytes), true, bus);
  const std::string text = benchText(core);
  const size_t px4 = text.find("PX4 (NED/FRD)"), ours = text.find("sdlqr (z up)");
  ASSERT_NE(px4, std::string::npos) << text;
  ASSERT_NE(ours, std::string::npos) << text;
  const std::string px4_line = text.substr(px4, text.find('\n', px4) - px4);
  const std::string our_line = text.substr(ours, text.find('\n', ours) - ours);
  EXPECT_NE(px4_line.find("p [  0.000   0.000  -1.500] m  roll   30.0"), std::string::npos) << px4_line;
  EXPECT_NE(px4_line.find("yaw    0.0 deg"), std::string::npos) << px4_line;
  EXPECT_NE(our_line.find("p [  0.000   0.000   1.500] m  roll   30.0"), std::string::npos) << our_line;
  EXPECT_NE(our_line.find("yaw   90.0 deg"), std::string::npos) << our_line;  // north is the world's +y
}

}  // namespace
}  // namespace sdlqr::px4
