#pragma once
// The px4-emulated stack in one process, for unit tests: the mission, gain solver and controller
// cores on an in-process bus, the bridge's core, two MAVLink endpoints joined by byte queues, and
// the emulated PX4's core — the same cores the processes run, the same bytes on the link, stepped
// on simulation time (deterministic, far faster than real time), wired by their declared ports
// (InProcessWiring). Every bus message is recorded into a FlightLog, so the flight analysis and the hover fit read it as they read a log.

#include <deque>
#include <tuple>
#include <type_traits>
#include <vector>

#include "sdlqr/controller/controller_core.hpp"
#include "sdlqr/gains/gains_core.hpp"
#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/messages/ports.hpp"
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
};

// A core as a process that can be killed: its own ports, each message delivered only while it
// lives (what it publishes is the core's, through its Outputs).
template <class Core>
class Killable {
 public:
  explicit Killable(Core& core) : core_(core) {}
  template <class Msg>
  void on(const Msg& m, Outbox& out) {
    if (alive_) ports::deliver(core_, m, out);
  }
  static constexpr auto inputs() {
    return std::apply([](const auto&... port) { return std::tuple{ports::Input{&Killable::on<PortMsg<decltype(port)>>}...}; },
                      Core::inputs());
  }
  using Outputs = typename Core::Outputs;
  void kill() { alive_ = false; }

 private:
  template <class Port>
  using PortMsg = typename std::decay_t<Port>::Msg;
  Core& core_;
  bool alive_ = true;
};

class Px4Loop {
 public:
  Px4Loop(const params::VehicleFile& config, const mission::Scenario& scenario, LoopOptions options = {});
  Px4Loop(const Px4Loop&) = delete;
  Px4Loop& operator=(const Px4Loop&) = delete;
  bool step();  // false once the scenario's duration has passed
  void run() {
    while (step()) {
    }
  }

  const EmulatorCore& emulator() const { return emulator_; }
  const px4::BridgeCore& bridge() const { return bridge_; }
  const logger::FlightLog& log() const { return recorder_.log; }
  double seconds() const { return 1e-6 * static_cast<double>(emulator_.utime()); }

 private:
  // Every bus message into its series of the log, as the recorder would on the bus.
  struct Recorder {
    logger::FlightLog log;
    template <class Msg>
    void operator()(const Msg& m) {
      if constexpr (logger::kFlightLogRecords<Msg>) {
        logger::Series<Msg>& series = log.series<Msg>();
        series.messages.push_back(m);
        series.receive_utime.push_back(m.utime);
      }
    }
  };
  void deliver();

  LoopOptions options_;
  mission::Scenario scenario_;  // the mission core keeps a reference
  double duration_s_;
  ByteQueue to_bridge_, to_emulator_;
  px4::MavlinkEndpoint companion_end_, autopilot_end_;
  Recorder recorder_;
  controller::ControllerCore controller_;
  Killable<controller::ControllerCore> killable_controller_{controller_};
  gains::GainsCore gains_;
  mission::MissionCore mission_;
  px4::BridgeCore bridge_;
  EmulatorCore emulator_;
  // The bus, in process: each message to the cores whose ports take it. The solver gets an
  // estimate before the controller (as ClosedLoop orders them); the bridge and the emulated PX4
  // take RATE_CMD, COMMAND and DISTURBANCE, which no other core of the companion's takes first.
  InProcessWiring<Recorder, gains::GainsCore, Killable<controller::ControllerCore>, mission::MissionCore,
                  px4::BridgeCore, EmulatorCore>
      wiring_{recorder_, gains_, killable_controller_, mission_, bridge_, emulator_};
};

}  // namespace sdlqr::px4emu::test
