#pragma once
// The px4-emulated stack in one process, for unit tests: the mission, gain solver and controller
// cores on an in-process bus, the bridge's core, two MAVLink endpoints joined by byte queues, and
// the emulated PX4's core — the same cores the processes run, the same bytes on the link, stepped
// on simulation time (deterministic, far faster than real time). Every bus message is recorded
// into a FlightLog, so the flight analysis and the hover fit read it as they read a log.

#include <deque>
#include <vector>

#include "sdlqr/controller/controller_core.hpp"
#include "sdlqr/gains/gains_core.hpp"
#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/mission/mission_core.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/params/vehicle_file.hpp"
#include "sdlqr/px4/bridge_core.hpp"
#include "sdlqr/px4emu/emulator_core.hpp"

namespace sdlqr::px4emu::test {

// Bytes written by one end, read by the other on the next delivery.
class ByteQueue : public px4::ByteSink {
 public:
  bool write(const uint8_t* data, size_t size) override {
    if (down) return true;  // the link is cut: gone
    frames.emplace_back(data, data + size);
    return true;
  }
  std::deque<std::vector<uint8_t>> frames;
  bool down = false;
};

struct LoopOptions {
  double controller_dies_at_s = -1.0;  // the controller stops hearing the bus (killed)
  double link_down_at_s = -1.0;        // both directions cut for link_down_for_s
  double link_down_for_s = 0.0;
  bool stream_setpoints = true;        // false: the bridge never gets a RATE_CMD
};

class Px4Loop {
 public:
  Px4Loop(const params::VehicleFile& config, const mission::Scenario& scenario, LoopOptions options = {});
  bool step();  // false once the scenario's duration has passed
  void run() {
    while (step()) {
    }
  }

  const EmulatorCore& emulator() const { return emulator_; }
  const px4::BridgeCore& bridge() const { return bridge_; }
  const logger::FlightLog& log() const { return log_; }
  double seconds() const { return 1e-6 * static_cast<double>(emulator_.utime()); }

  // The in-process bus: each message to the cores that subscribe to its channel.
  template <class Message>
  void publish(const Message& m);

 private:
  template <class Message>
  static void record(logger::Series<Message>& series, const Message& m) {
    series.messages.push_back(m);
    series.receive_utime.push_back(m.utime);
  }
  void deliver();

  struct Bus {
    Px4Loop* loop;
    template <class Message>
    void operator()(const Message& m) const {
      loop->publish(m);
    }
  };

  LoopOptions options_;
  mission::Scenario scenario_;  // the mission core keeps a reference
  double duration_s_;
  ByteQueue to_bridge_, to_emulator_;
  px4::MavlinkEndpoint companion_end_, autopilot_end_;
  OutboxTo<Bus> bus_;
  controller::ControllerCore controller_;
  gains::GainsCore gains_;
  mission::MissionCore mission_;
  px4::BridgeCore bridge_;
  EmulatorCore emulator_;
  logger::FlightLog log_;
};

}  // namespace sdlqr::px4emu::test
