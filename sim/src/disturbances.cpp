#include "sdlqr/sim/disturbances.hpp"

#include <algorithm>
#include <cmath>

namespace sdlqr::sim {

bool DisturbanceSet::add(const Disturbance& d, int64_t now_utime) {
  if (count_ >= kCapacity) return false;
  Scheduled& s = scheduled_[static_cast<size_t>(count_)];
  s.start_utime = std::max(d.start_utime, now_utime);
  s.end_utime = s.start_utime + std::llround(d.duration * 1e6);
  s.force = d.force;
  s.torque = d.torque;
  s.hold = d.mode == DisturbanceMode::kHold;
  s.hold_position = d.hold_position;
  s.hold_stiffness = d.hold_stiffness;
  s.hold_damping = d.hold_damping;
  ++count_;
  return true;
}

void DisturbanceSet::expire(int64_t utime) {
  int kept = 0;
  for (int i = 0; i < count_; ++i) {
    if (scheduled_[static_cast<size_t>(i)].end_utime > utime) {
      scheduled_[static_cast<size_t>(kept++)] = scheduled_[static_cast<size_t>(i)];
    }
  }
  count_ = kept;
}

Wrench DisturbanceSet::wrenchAt(int64_t utime, const BodyState& s) const {
  Wrench w;
  for (int i = 0; i < count_; ++i) {
    const Scheduled& d = scheduled_[static_cast<size_t>(i)];
    if (utime < d.start_utime || utime >= d.end_utime) continue;
    w.force_world += d.force;
    w.torque_body += d.torque;
    if (d.hold) w.force_world -= d.hold_stiffness * (s.position - d.hold_position) + d.hold_damping * s.velocity;
  }
  return w;
}

}  // namespace sdlqr::sim
