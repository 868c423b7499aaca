#include "sdlqr/controller/transition_reference.hpp"

namespace sdlqr::controller {

bool TransitionReference::start(const trajectory::FlatState& from, const trajectory::FlatState* to, double start_s,
                                double path_speed, trajectory::TransitionKind kind) {
  const trajectory::TransitionPlan plan = to ? trajectory::planTransition(from, *to, lqr_, params_, path_speed, kind)
                                             : trajectory::planStop(from, lqr_, params_, path_speed);
  if (!plan.found) return false;
  plan_ = plan;
  start_s_ = start_s;
  const trajectory::FlatOutput end = plan_.transition.at(plan_.transition.duration());
  end_position_ = end.position;
  end_yaw_ = end.yaw;
  return true;
}

void TransitionReference::reference(double now_s, State& x, Input& u) const {
  const trajectory::FlatReference ref = trajectory::flatToReference(plan_.transition.at(now_s - start_s_), lqr_.gravity);
  x = ref.x;
  u = ref.u;
}

}  // namespace sdlqr::controller
