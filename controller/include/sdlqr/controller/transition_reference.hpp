#pragma once
// The transition the reference generator flies into a trajectory (entry) or out of one to a hover
// (exit: a GOTO or LAND while tracking, or the end of an open path still moving), planned within
// the lqr limits (trajectory/transition.hpp) and flown by the clock. Allocation-free: planned
// inside a controller tick.

#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::controller {

class TransitionReference {
 public:
  TransitionReference(const trajectory::TransitionParams& params, const LqrParams& lqr)
      : params_(params), lqr_(lqr) {}

  void setLimits(const LqrParams& lqr) { lqr_ = lqr; }
  const trajectory::TransitionParams& params() const { return params_; }

  // Plans from `from` to `to` (nullptr: a stop, at rest ahead of `from`), flown from `start_s` [s]
  // of simulation time; `path_speed` [m/s] the top speed of the path joined or left, `kind` which
  // (planTransition). False when none is found within max_duration (nothing changes then).
  bool start(const trajectory::FlatState& from, const trajectory::FlatState* to, double start_s, double path_speed,
             trajectory::TransitionKind kind);
  bool finished(double now_s) const { return now_s - start_s_ >= plan_.transition.duration(); }
  // The reference state and feed-forward input at `now_s` (the flat map of the polynomial).
  void reference(double now_s, State& x, Input& u) const;
  // Where it ends, at rest (an exit) or in the path's first sample (an entry).
  const Vec3& endPosition() const { return end_position_; }
  double endYaw() const { return end_yaw_; }
  const trajectory::TransitionPlan& plan() const { return plan_; }

 private:
  trajectory::TransitionParams params_;
  LqrParams lqr_;
  trajectory::TransitionPlan plan_;
  double start_s_ = 0.0;
  Vec3 end_position_ = Vec3::Zero();
  double end_yaw_ = 0.0;
};

}  // namespace sdlqr::controller
