#include "px4_loop.hpp"

namespace sdlqr::px4emu::test {

namespace {

EmulatorConfig emulatorConfig(const params::VehicleFile& c, const mission::Scenario& scenario) {
  EmulatorConfig e{c.vehicle, c.sim, c.estimator, c.lowlevel, c.lqr, c.faults, c.validation, c.px4_emulator};
  e.sim.seed = scenario.seed;
  return e;
}

uint64_t noSigningClock() { return 0; }

}  // namespace

Px4Loop::Px4Loop(const params::VehicleFile& config, const mission::Scenario& scenario, LoopOptions options)
    : options_(options),
      scenario_(scenario),
      duration_s_(scenario.duration),
      companion_end_({1, px4::kOnboardComputerComponent}, to_emulator_, &noSigningClock),
      autopilot_end_({1, px4::kAutopilotComponent}, to_bridge_, &noSigningClock),
      bus_(Bus{this}),
      controller_(config.lqr, config.controller, config.faults, config.validation),
      gains_(config.lqr, config.gains, config.faults, config.validation),
      mission_(scenario_, config.trajectory, config.lqr, mission::MissionOptions{}),
      bridge_(config.px4, config.lqr.gravity, config.validation, companion_end_),
      emulator_(emulatorConfig(config, scenario), scenario.sim, autopilot_end_) {}

bool Px4Loop::step() {
  if (seconds() >= duration_s_) return false;
  const double now = seconds();
  const bool cut = options_.link_down_at_s >= 0 && now >= options_.link_down_at_s &&
                   now < options_.link_down_at_s + options_.link_down_for_s;
  to_bridge_.down = to_emulator_.down = cut;
  bridge_.onWallTime(now);
  controller_.onWallTime(now);
  gains_.onWallTime(now);
  emulator_.step(bus_);
  deliver();
  return true;
}

void Px4Loop::deliver() {
  while (!to_bridge_.frames.empty()) {
    const std::vector<uint8_t> bytes = std::move(to_bridge_.frames.front());
    to_bridge_.frames.pop_front();
    bridge_.onBytes(bytes.data(), bytes.size(), true, bus_);
  }
  while (!to_emulator_.frames.empty()) {
    const std::vector<uint8_t> bytes = std::move(to_emulator_.frames.front());
    to_emulator_.frames.pop_front();
    emulator_.onBytes(bytes.data(), bytes.size(), true);
  }
}

template <class Message>
void Px4Loop::publish(const Message& m) {
  const bool controller_alive = options_.controller_dies_at_s < 0 || seconds() < options_.controller_dies_at_s;
  if constexpr (std::is_same_v<Message, StateEstimate>) {
    record(log_.state_estimate, m);
    gains_.onStateEstimate(m, bus_);
    if (controller_alive) controller_.onStateEstimate(m, bus_);
    mission_.onStateEstimate(m, bus_);
  } else if constexpr (std::is_same_v<Message, RateCommand>) {
    record(log_.rate_command, m);
    if (options_.stream_setpoints) bridge_.onRateCommand(m);
  } else if constexpr (std::is_same_v<Message, GainSet>) {
    record(log_.gains, m);
    if (controller_alive) controller_.onGains(m);
  } else if constexpr (std::is_same_v<Message, Reference>) {
    record(log_.reference, m);
    gains_.onReference(m);
  } else if constexpr (std::is_same_v<Message, Command>) {
    record(log_.command, m);
    if (controller_alive) controller_.onCommand(m);
    bridge_.onCommand(m);
  } else if constexpr (std::is_same_v<Message, SimClockTick>) {
    record(log_.sim_clock, m);
    mission_.onClock(m.utime, bus_);
  } else if constexpr (std::is_same_v<Message, Disturbance>) {
    record(log_.disturbance, m);
    emulator_.onDisturbance(m);
  } else if constexpr (std::is_same_v<Message, SimTruth>) {
    record(log_.sim_truth, m);
  } else if constexpr (std::is_same_v<Message, MotorCommand>) {
    record(log_.motor_command, m);
  } else if constexpr (std::is_same_v<Message, ImuSample>) {
    record(log_.imu, m);
  } else if constexpr (std::is_same_v<Message, Trajectory>) {
    record(log_.trajectory, m);
    if (controller_alive) controller_.onTrajectory(m);
  } else if constexpr (std::is_same_v<Message, ParamsUpdate>) {
    record(log_.params, m);
    gains_.onParams(m);
    if (controller_alive) controller_.onParams(m);
  }
}

}  // namespace sdlqr::px4emu::test
