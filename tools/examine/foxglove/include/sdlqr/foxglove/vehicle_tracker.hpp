#pragma once
// The newest messages of one vehicle that its Foxglove scene draws (vehicle_scene.hpp), fed the
// raw bytes of its channels as they arrive: SIM_TRUTH, STATE_EST, REFERENCE, TRAJECTORY and
// RATE_CMD are decoded (the bus's size walk first), the others ignored; the trails grow with the
// truth and the estimate. Used by sdlqr-view live and on a log, and by the MCAP export.

#include <cstddef>
#include <string_view>

#include "sdlqr/foxglove/vehicle_scene.hpp"

namespace sdlqr::foxglove {

class VehicleTracker {
 public:
  enum class Update { kNone, kTruth, kEstimate, kOther };

  // `base` is the channel name without the vehicle prefix. kNone: not a channel the scene draws,
  // or bytes that are not one whole message of its type (nothing changes).
  Update onMessage(std::string_view base, const void* data, std::size_t size);
  const VehicleState& state() const { return state_; }
  // A log seeked: the trails restart, the newest messages stay until replaced.
  void clearTrails();

 private:
  VehicleState state_;
};

}  // namespace sdlqr::foxglove
