#pragma once
// A scripted PX4 for the bridge's unit tests: frames PX4 would send (system 1, component 1), and
// the frames the bridge sent, parsed back.

#include <vector>

#include "sdlqr/mavlink/dispatch.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/px4/bridge_core.hpp"
#include "sdlqr/px4/px4_modes.hpp"

namespace sdlqr::px4::test {

// Keeps every frame written to it.
class CaptureSink : public ByteSink {
 public:
  bool write(const uint8_t* data, size_t size) override {
    frames.emplace_back(data, data + size);
    return true;
  }
  std::vector<std::vector<uint8_t>> frames;
};

// The bridge's frames since the last take(), decoded.
struct Sent {
  std::vector<mavlink::SetAttitudeTarget> setpoints;
  std::vector<mavlink::CommandLong> commands;
  std::vector<mavlink::Heartbeat> heartbeats;
};

inline Sent take(CaptureSink& sink) {
  Sent sent;
  mavlink::Parser parser;
  for (const auto& bytes : sink.frames) {
    parser.feed(bytes.data(), bytes.size(), 0, [&](const mavlink::Frame& f) {
      mavlink::dispatch(f, [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, mavlink::SetAttitudeTarget>) sent.setpoints.push_back(m);
        if constexpr (std::is_same_v<M, mavlink::CommandLong>) sent.commands.push_back(m);
        if constexpr (std::is_same_v<M, mavlink::Heartbeat>) sent.heartbeats.push_back(m);
      });
    });
  }
  sink.frames.clear();
  return sent;
}

// What the bridge published on the bus.
struct BusCapture {
  std::vector<StateEstimate> estimates;
  std::vector<SimClockTick> clock;
  std::vector<ImuSample> imu;
};
inline auto busSink(BusCapture& capture) {
  return [&capture](const auto& m) {
    using M = std::decay_t<decltype(m)>;
    if constexpr (std::is_same_v<M, StateEstimate>) capture.estimates.push_back(m);
    if constexpr (std::is_same_v<M, SimClockTick>) capture.clock.push_back(m);
    if constexpr (std::is_same_v<M, ImuSample>) capture.imu.push_back(m);
  };
}

// PX4's side of the link.
class ScriptedPx4 {
 public:
  explicit ScriptedPx4(BridgeCore& bridge, Outbox& bus) : bridge_(bridge), bus_(bus) {}

  template <class Message>
  void send(const Message& m) {
    uint8_t buffer[mavlink::kMaxFrameSize];
    const size_t size = writer_.write(m, 0, buffer);
    bridge_.onBytes(buffer, size, true, bus_);
  }
  void heartbeat(bool armed, FlightMode mode) {
    mavlink::Heartbeat h;
    h.type = mavlink::mav_type::kQuadrotor;
    h.autopilot = mavlink::mav_autopilot::kPx4;
    h.base_mode = static_cast<uint8_t>(mavlink::mav_mode_flag::kCustomModeEnabled |
                                       (armed ? mavlink::mav_mode_flag::kSafetyArmed : 0));
    h.custom_mode = customModeOf(mode);
    send(h);
  }
  void landed(uint8_t state) {
    mavlink::ExtendedSysState s;
    s.landed_state = state;
    send(s);
  }
  void odometry(int64_t utime, double height = 0.0) {
    mavlink::Odometry o;
    o.time_usec = static_cast<uint64_t>(utime);
    o.frame_id = mavlink::mav_frame::kLocalNed;
    o.child_frame_id = mavlink::mav_frame::kLocalNed;
    o.z = static_cast<float>(-height);
    o.q = {1.0f, 0.0f, 0.0f, 0.0f};
    send(o);
  }
  void ack(uint16_t command, uint8_t result) {
    mavlink::CommandAck a;
    a.command = command;
    a.result = result;
    send(a);
  }

 private:
  BridgeCore& bridge_;
  Outbox& bus_;
  mavlink::FrameWriter writer_{mavlink::Address{1, 1}};
};

}  // namespace sdlqr::px4::test
