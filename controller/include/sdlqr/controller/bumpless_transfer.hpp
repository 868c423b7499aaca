#pragma once
// Bumpless transfer between control laws. When the controller changes its law (a PARAMS law
// switch, or an extension whose first K arrives), the new law's command differs from the one
// published a tick before by some d. The transfer keeps that difference as an offset and lets it
// decay linearly to zero over N ticks (N = controller.switch_time_s x controller.rate_hz):
//
//   u[k] = limits(u_new[k] + (1 - k / N) d),   d = u[0] - u_new[1],  k = 1 .. N.
//
// Bound: on top of the new law's own change from tick to tick, the switch moves the command by
// |d| / N per tick. The limits keep ||omega|| <= omega_max and c in [c_min, c_max] for both laws,
// so |d_omega| <= 2 omega_max, and the limits (a projection onto a convex set) never enlarge a
// change: the switch adds at most 2 omega_max / N [rad/s] to any tick's body-rate change
// (0.08 rad/s with the defaults, omega_max 2 rad/s and N 50) and (c_max - c_min) / N to the thrust.
// N = 0 switches at once (the jump this avoids).

#include "sdlqr/math/types.hpp"

namespace sdlqr::controller {

class BumplessTransfer {
 public:
  // previous: the command published last; law_output: the new law's (limited) command this tick.
  void start(const Input& previous, const Input& law_output, int ticks) {
    offset_ = previous - law_output;
    ticks_ = ticks;
    tick_ = 0;
  }
  bool active() const { return tick_ < ticks_; }
  // The command for this tick before the limits; moves on by one tick.
  Input apply(const Input& law_output) {
    if (!active()) return law_output;
    ++tick_;
    const double weight = 1.0 - static_cast<double>(tick_) / static_cast<double>(ticks_);
    return law_output + weight * offset_;
  }
  const Input& offset() const { return offset_; }

 private:
  Input offset_ = Input::Zero();
  int ticks_ = 0;
  int tick_ = 0;
};

}  // namespace sdlqr::controller
