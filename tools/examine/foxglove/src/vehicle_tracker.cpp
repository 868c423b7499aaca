#include "sdlqr/foxglove/vehicle_tracker.hpp"

#include "sdlqr/bus/decode.hpp"
#include "sdlqr/messages/channels.hpp"

namespace sdlqr::foxglove {

namespace {

// Decodes into the plain message of `slot` (replaced only by a whole message).
template <class Plain>
bool decodeInto(const void* data, std::size_t size, std::optional<Plain>* slot) {
  bus::LcmOf<Plain> message;
  if (size > UINT32_MAX || bus::decode(data, static_cast<uint32_t>(size), message) != RejectReason::kNone) return false;
  *slot = bus::fromLcm(message);
  return true;
}

}  // namespace

VehicleTracker::Update VehicleTracker::onMessage(std::string_view base, const void* data, std::size_t size) {
  if (base == channel::kSimTruth) {
    if (!decodeInto(data, size, &state_.truth)) return Update::kNone;
    state_.truth_trail.add(state_.truth->position);
    return Update::kTruth;
  }
  if (base == channel::kStateEstimate) {
    if (!decodeInto(data, size, &state_.estimate)) return Update::kNone;
    state_.estimate_trail.add(state_.estimate->position);
    return Update::kEstimate;
  }
  bool decoded = false;
  if (base == channel::kReference) decoded = decodeInto(data, size, &state_.reference);
  else if (base == channel::kTrajectory) decoded = decodeInto(data, size, &state_.trajectory);
  else if (base == channel::kRateCommand) decoded = decodeInto(data, size, &state_.command);
  return decoded ? Update::kOther : Update::kNone;
}

void VehicleTracker::clearTrails() {
  state_.truth_trail.clear();
  state_.estimate_trail.clear();
}

}  // namespace sdlqr::foxglove
