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
      controller_(config.lqr, config.controller, config.faults, config.validation),
      gains_(config.lqr, config.gains, config.faults, config.validation),
      mission_(scenario_, config.trajectory, {config.lqr, config.controller.guard, config.controller.transition},
               mission::MissionOptions{}),
      bridge_(config.px4, config.lqr.gravity, config.validation, companion_end_),
      emulator_(emulatorConfig(config, scenario), scenario.sim, autopilot_end_) {}

bool Px4Loop::step() {
  if (seconds() >= duration_s_) return false;
  const double now = seconds();
  const bool cut = options_.link_down_at_s >= 0 && now >= options_.link_down_at_s &&
                   now < options_.link_down_at_s + options_.link_down_for_s;
  to_bridge_.down = to_emulator_.down = cut;
  if (options_.controller_dies_at_s >= 0 && now >= options_.controller_dies_at_s) killable_controller_.kill();
  bridge_.onWallTime(now);
  controller_.onWallTime(now);
  gains_.onWallTime(now);
  emulator_.step(wiring_.outboxOf<EmulatorCore>());
  deliver();
  return true;
}

void Px4Loop::deliver() {
  while (!to_bridge_.frames.empty()) {
    const std::vector<uint8_t> bytes = std::move(to_bridge_.frames.front());
    to_bridge_.frames.pop_front();
    bridge_.onBytes(bytes.data(), bytes.size(), true, wiring_.outboxOf<px4::BridgeCore>());
  }
  while (!to_emulator_.frames.empty()) {
    const std::vector<uint8_t> bytes = std::move(to_emulator_.frames.front());
    to_emulator_.frames.pop_front();
    emulator_.onBytes(bytes.data(), bytes.size(), true);
  }
}

}  // namespace sdlqr::px4emu::test
