// The latency of sdlqr-px4 (docs/px4.md, bench/px4_latency): this probe plays both of the
// bridge's neighbours in one process and one clock — PX4 on the UDP side (HEARTBEAT, landed on the
// ground, every command acknowledged, ODOMETRY at 250 Hz) and the controller on the bus (a
// RATE_CMD at 100 Hz for the newest estimate) — and times each message through the real process:
//   ODOMETRY written to the socket -> its STATE_EST received on the bus     (matched by time)
//   RATE_CMD published on the bus  -> its SET_ATTITUDE_TARGET on the socket (matched by time_boot_ms)
// Prints the count, median, p99 and max of both, in microseconds of the steady clock.
//   px4_latency_probe --seconds S [--mavlink URL] [--lcm-url URL]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <vector>

#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/mavlink/dispatch.hpp"
#include "sdlqr/px4/link_binding.hpp"
#include "sdlqr/px4/px4_cli.hpp"
#include "sdlqr/px4/px4_modes.hpp"

using namespace sdlqr;
using Clock = std::chrono::steady_clock;

namespace {

double microseconds(Clock::duration d) { return std::chrono::duration<double, std::micro>(d).count(); }

// `sent` messages went in; samples holds the latency of each that came out (matched).
void report(const char* what, int64_t sent, std::vector<double> samples) {
  if (samples.empty()) {
    std::printf("%-44s %lld sent, none came out\n", what, static_cast<long long>(sent));
    return;
  }
  std::sort(samples.begin(), samples.end());
  const auto at = [&](double q) { return samples[static_cast<size_t>(q * static_cast<double>(samples.size() - 1))]; };
  std::printf("%-44s %6zu of %6lld  median %7.1f us  p99 %7.1f us  max %8.1f us\n", what, samples.size(),
              static_cast<long long>(sent), at(0.5), at(0.99), samples.back());
}

// PX4's side of the link, as little as the bridge needs.
struct FakePx4 {
  px4::MavlinkEndpoint& link;
  std::map<uint32_t, Clock::time_point>& setpoint_sent;  // RATE_CMD time_boot_ms -> publish time
  std::vector<double>& outbound;
  template <class M>
  void operator()(const M&) {}
  void operator()(const mavlink::CommandLong& c) {
    mavlink::CommandAck ack;
    ack.command = c.command;
    ack.result = mavlink::mav_result::kAccepted;
    link.send(ack);
  }
  void operator()(const mavlink::SetAttitudeTarget& s) {
    const auto it = setpoint_sent.find(s.time_boot_ms);
    if (it == setpoint_sent.end()) return;  // a zero-thrust setpoint of the bridge's own
    outbound.push_back(microseconds(Clock::now() - it->second));
    setpoint_sent.erase(it);
  }
};

}  // namespace

int main(int argc, char** argv) {
  return runMain("px4_latency_probe", [&] {
    ProcessOptions options;
    std::string url = "udpout://127.0.0.1:14540:14580";
    double seconds = 10.0;
    ArgParser parser("px4_latency_probe", "Times ODOMETRY -> STATE_EST and RATE_CMD -> SET_ATTITUDE_TARGET through sdlqr-px4.");
    addProcessOptions(parser, &options);
    parser.addOption("--mavlink", &url, "URL", "where sdlqr-px4 listens (default udpout://127.0.0.1:14540:14580)");
    parser.addOption("--seconds", &seconds, "S", "measuring time, wall seconds (default 10)");
    parser.parseOrExit(argc, argv);
    const auto io = px4::LinkIo::open(url);
    // Signed as the bridge is when SDLQR_MAVLINK_KEY names a key (bench/px4_latency --signed).
    px4::MavlinkEndpoint link({1, px4::kAutopilotComponent}, *io, &px4::wallSigningTime, px4::loadLinkKey({}));
    bus::Node node("px4_latency_probe", options);
    std::map<int64_t, Clock::time_point> odometry_sent;       // time_usec -> write time
    std::map<uint32_t, Clock::time_point> setpoint_sent;
    std::vector<double> inbound, outbound;
    int64_t newest_estimate = -1;
    node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t& e) {
      const auto it = odometry_sent.find(e.utime);
      if (it == odometry_sent.end()) return;
      inbound.push_back(microseconds(Clock::now() - it->second));
      odometry_sent.erase(odometry_sent.begin(), std::next(it));
      newest_estimate = e.utime;
    }, 16);
    FakePx4 px4{link, setpoint_sent, outbound};
    px4::bindLink(node, *io, link, [&](const uint8_t* data, size_t size, bool datagram) {
      link.receive(data, size, datagram, [&](const mavlink::Frame& f) { mavlink::dispatch(f, px4); });
    });
    const auto start = Clock::now();
    auto next_odometry = start, next_command = start, next_heartbeat = start;
    int64_t utime = 1'000'000, command_seq = 0, commanded_estimate = -1;
    while (node.running() && Clock::now() - start < std::chrono::duration<double>(seconds)) {
      const auto now = Clock::now();
      if (now >= next_heartbeat) {
        mavlink::Heartbeat h;
        h.type = mavlink::mav_type::kQuadrotor;
        h.autopilot = mavlink::mav_autopilot::kPx4;
        h.base_mode = mavlink::mav_mode_flag::kCustomModeEnabled;
        h.custom_mode = px4::customModeOf(px4::kOffboardMode);
        link.send(h);
        mavlink::ExtendedSysState landed;
        landed.landed_state = mavlink::mav_landed_state::kInAir;  // no zero-thrust stream to tell apart
        link.send(landed);
        next_heartbeat += std::chrono::seconds(1);
      }
      if (now >= next_odometry) {
        mavlink::Odometry o;
        utime += 4000;
        o.time_usec = static_cast<uint64_t>(utime);
        o.frame_id = o.child_frame_id = mavlink::mav_frame::kLocalNed;
        o.q = {1.0f, 0.0f, 0.0f, 0.0f};
        odometry_sent[utime] = Clock::now();
        link.send(o);
        next_odometry += std::chrono::microseconds(4000);
      }
      // One command per estimate (the controller's own rule): each SET_ATTITUDE_TARGET then matches one.
      if (now >= next_command && newest_estimate > commanded_estimate) {
        commanded_estimate = newest_estimate;
        RateCommand r;
        r.utime = newest_estimate;
        r.seq = command_seq++;
        r.thrust = 9.81;
        setpoint_sent[static_cast<uint32_t>(r.utime / 1000)] = Clock::now();
        node.publish(channel::kRateCommand, bus::toLcm(r));
        next_command += std::chrono::microseconds(10000);
      }
      const auto wake = std::min({next_heartbeat, next_odometry, next_command});
      node.spin(std::max(0, static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(wake - Clock::now()).count())));
    }
    report("ODOMETRY on the wire -> STATE_EST on the bus", (utime - 1'000'000) / 4000, inbound);
    report("RATE_CMD on the bus -> SET_ATTITUDE_TARGET on the wire", command_seq, outbound);
    node.shutdown();
    return inbound.empty() || outbound.empty() ? 1 : 0;
  });
}
