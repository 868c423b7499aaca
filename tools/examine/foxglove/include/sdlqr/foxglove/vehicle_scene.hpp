#pragma once
// A vehicle in Foxglove's own schemas (FrameTransform, PoseInFrame, SceneUpdate; the JSON Schemas
// vendored in tools/examine/foxglove/schemas/), so Foxglove's 3D panel draws it without
// configuration:
//   <V>/foxglove/truth_tf       FrameTransform world -> <V>/body, from SIM_TRUTH
//   <V>/foxglove/estimate_tf    FrameTransform world -> <V>/body_estimate, from STATE_EST
//   <V>/foxglove/estimate_pose  PoseInFrame in world, from STATE_EST
//   <V>/foxglove/scene          SceneUpdate: the vehicle (arms, rotors, body axes, thrust arrow)
//                               in its body frame, its ghost at the estimate, the trails, the
//                               reference, the uploaded trajectory and the disturbance force
// <V> is the channel prefix ("" for none: "foxglove/truth_tf", frame "body"). World z is up.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>

#include "sdlqr/foxglove/lcm_json.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::foxglove {

// What is drawn: the X layout of config/quad255.yaml (vehicle.arm_length 0.125 m).
struct VehicleGeometry {
  double arm_length = 0.125;   // [m] centre to rotor axis
  double rotor_radius = 0.064; // [m] a 5-inch propeller
  double axis_length = 0.15;   // [m] body axes drawn
};

// A position history for a trail: a point is kept once it is min_spacing from the last one, the
// oldest dropped past `capacity` (bounded memory for any flight length).
class Trail {
 public:
  explicit Trail(std::size_t capacity = 1000, double min_spacing = 0.01) : capacity_(capacity), spacing_(min_spacing) {}
  void add(const Vec3& position);
  void clear() { points_.clear(); }
  const std::deque<Vec3>& points() const { return points_; }

 private:
  std::size_t capacity_;
  double spacing_;
  std::deque<Vec3> points_;
};

// The newest messages of one vehicle and its trails; a member absent until first heard.
struct VehicleState {
  std::optional<SimTruth> truth;
  std::optional<StateEstimate> estimate;
  std::optional<Reference> reference;
  std::optional<Trajectory> trajectory;
  std::optional<RateCommand> command;
  Trail truth_trail;
  Trail estimate_trail;
};

// Topic names and frames of a vehicle prefix.
std::string foxgloveTopic(std::string_view vehicle, std::string_view name);  // ("QUAD1", "scene") -> "QUAD1/foxglove/scene"
std::string bodyFrame(std::string_view vehicle);                            // "QUAD1/body", or "body"
std::string estimateFrame(std::string_view vehicle);                        // "QUAD1/body_estimate"
inline constexpr std::string_view kWorldFrame = "world";

// {sec, nsec} of a time in nanoseconds (negative times clamp to 0).
Json foxgloveTime(int64_t ns);

Json truthTransform(const SimTruth& truth, std::string_view vehicle, int64_t stamp_ns);
Json estimateTransform(const StateEstimate& estimate, std::string_view vehicle, int64_t stamp_ns);
Json estimatePose(const StateEstimate& estimate, int64_t stamp_ns);
Json sceneUpdate(const VehicleState& vehicle_state, std::string_view vehicle, const VehicleGeometry& geometry,
                 int64_t stamp_ns);

}  // namespace sdlqr::foxglove
