#pragma once
// Wall-clock pacing for a process that owns the simulation clock (the simulator): one step per
// wall period, the bus serviced between steps so that a message (MOTOR_CMD) reaches the next
// step. A step later than one period is a deadline miss (HEARTBEAT); after a long stall the
// schedule restarts from now instead of replaying every missed step at once (a burst of
// hundreds of IMU samples would be worse for the stack than a short slow-down).

#include <chrono>
#include <cstdint>
#include <functional>

#include "sdlqr/bus/node.hpp"

namespace sdlqr::bus {

struct PacingOptions {
  std::chrono::duration<double> wall_period{0.001};  // [s] per step
  int64_t max_steps = -1;                            // -1: until stopped
  int64_t max_catch_up_steps = 20;
};

// Calls step() until SIGINT/SIGTERM or max_steps; returns the number of deadline misses.
int64_t runPaced(Node& node, const PacingOptions& options, const std::function<void()>& step);

}  // namespace sdlqr::bus
