#pragma once
// External wrenches scheduled on the vehicle: the paper's "pull" (a constant force in the world
// frame and torque in the body frame) and MODE_HOLD (a spring-damper towards an anchor, as a
// hand holding the vehicle back). A fixed number can be pending at once; none allocates.

#include <array>
#include <cstdint>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/sim/rigid_body.hpp"

namespace sdlqr::sim {

class DisturbanceSet {
 public:
  static constexpr int kCapacity = 8;

  // Schedules d over [max(start_utime, now_utime), that + duration). Returns false when
  // kCapacity disturbances are already pending (the request is then ignored).
  bool add(const Disturbance& d, int64_t now_utime);
  // Forgets disturbances that ended at or before utime.
  void expire(int64_t utime);
  // Sum of the wrenches active at utime on a body in state s (spring and damper use s).
  Wrench wrenchAt(int64_t utime, const BodyState& s) const;
  int pending() const { return count_; }

 private:
  struct Scheduled {
    int64_t start_utime = 0;
    int64_t end_utime = 0;
    Vec3 force = Vec3::Zero();
    Vec3 torque = Vec3::Zero();
    bool hold = false;
    Vec3 hold_position = Vec3::Zero();
    double hold_stiffness = 0.0;
    double hold_damping = 0.0;
  };
  std::array<Scheduled, kCapacity> scheduled_{};
  int count_ = 0;
};

}  // namespace sdlqr::sim
