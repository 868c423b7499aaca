#pragma once
// sdlqr-px4 --bench: what the bridge reads and would send, printed twice a second, for the
// props-off first-flight check (docs/px4.md): tilt the vehicle by hand and see PX4's roll/pitch/yaw
// (NED/FRD) beside sdlqr's (world z up), and the setpoint a RATE_CMD would become.

#include <ostream>
#include <string>

#include "sdlqr/px4/bridge_core.hpp"

namespace sdlqr::px4 {

// The lines for one display (pure: tests compare them).
std::string benchText(const BridgeCore& core);

class BenchDisplay {
 public:
  explicit BenchDisplay(std::ostream& out, double period_s = 0.5) : out_(out), period_s_(period_s) {}
  void show(const BridgeCore& core, double now_s) {
    if (now_s < next_s_) return;
    next_s_ = now_s + period_s_;
    out_ << benchText(core) << std::flush;
  }

 private:
  std::ostream& out_;
  double period_s_;
  double next_s_ = 0.0;
};

}  // namespace sdlqr::px4
