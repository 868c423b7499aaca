#pragma once
// PX4's proof of life for OFFBOARD (docs flight_modes/offboard.md): setpoints must be streaming at
// more than 2 Hz before the mode is asked for. This keeps the unbroken run of setpoints sent: a
// gap longer than one period of the least rate starts a new run. Pure.

namespace sdlqr::px4 {

class SetpointStream {
 public:
  explicit SetpointStream(double min_rate_hz) : max_gap_s_(1.0 / min_rate_hz) {}

  void note(double now_s) {
    if (now_s - last_s_ > max_gap_s_) run_start_s_ = now_s;
    last_s_ = now_s;
  }
  // [s] the run has lasted at `now_s`; 0 once it has broken off.
  double runningFor(double now_s) const { return now_s - last_s_ > max_gap_s_ ? 0.0 : now_s - run_start_s_; }

 private:
  double max_gap_s_;
  double last_s_ = -1e9;
  double run_start_s_ = -1e9;
};

}  // namespace sdlqr::px4
