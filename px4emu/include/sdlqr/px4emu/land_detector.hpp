#pragma once
// The emulated PX4's land detector (PX4's MulticopterLandDetector in spirit: a landed state with
// hysteresis, what EXTENDED_SYS_STATE reports and what disarming checks). Its evidence is the
// bodyrate loop's: disarmed or idle, or "maybe landed" (at rest on the IMU with a command below
// hover: lowlevel/bodyrate_loop.hpp). Landed once that held for kLandTime; airborne once it failed
// for kTakeoffTime. The hover-to-descent step briefly looks like rest to an IMU: a landed state
// on one sample would disarm a flying vehicle. Pure.

namespace sdlqr::px4emu {

class LandDetector {
 public:
  static constexpr double kLandTime = 0.5;     // [s] (the bodyrate loop itself disarms after 1 s)
  static constexpr double kTakeoffTime = 0.2;  // [s]

  // One step of `dt` [s] with the evidence of that step; returns landed().
  bool update(bool ground_evidence, double dt) {
    if (ground_evidence == landed_) {
      against_s_ = 0.0;
      return landed_;
    }
    against_s_ += dt;
    if (against_s_ >= (landed_ ? kTakeoffTime : kLandTime)) {
      landed_ = ground_evidence;
      against_s_ = 0.0;
    }
    return landed_;
  }
  bool landed() const { return landed_; }

 private:
  bool landed_ = true;  // a vehicle starts on the ground
  double against_s_ = 0.0;  // [s] the evidence has disagreed with the state this long
};

}  // namespace sdlqr::px4emu
