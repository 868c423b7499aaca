#include "sdlqr/foxglove/vehicle_scene.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace sdlqr::foxglove {

namespace {

constexpr double kGravity = 9.81;  // [m/s^2] thrust arrow: hover thrust draws arm_length long

Json vector3(const Vec3& v) { return {{"x", v.x()}, {"y", v.y()}, {"z", v.z()}}; }
// Foxglove quaternions are x, y, z, w; ours are stored w, x, y, z (docs/architecture.md §3).
Json quaternion(const Quat& q) { return {{"x", q[1]}, {"y", q[2]}, {"z", q[3]}, {"w", q[0]}}; }
Json pose(const Vec3& p, const Quat& q) { return {{"position", vector3(p)}, {"orientation", quaternion(q)}}; }
Json color(double r, double g, double b, double a) { return {{"r", r}, {"g", g}, {"b", b}, {"a", a}}; }
Quat quatWxyz(double w, double x, double y, double z) { return Quat(w, x, y, z); }

// The rotation taking +x (the direction of a Foxglove arrow) onto `direction`.
Quat rotationFromX(const Vec3& direction) {
  const Vec3 d = direction.normalized();
  const Vec3 axis = Vec3::UnitX().cross(d);
  const double w = 1.0 + d.x();
  if (w < 1e-9) return quatWxyz(0.0, 0.0, 0.0, 1.0);  // opposite: half a turn about z
  const Quat q = quatWxyz(w, axis.x(), axis.y(), axis.z());
  return q / q.norm();
}

Json arrow(const Vec3& origin, const Vec3& vector, double diameter, const Json& rgba) {
  const double length = vector.norm();
  const double head = std::min(0.3 * length, 0.05);
  return {{"pose", pose(origin, rotationFromX(vector))},
          {"shaft_length", std::max(0.0, length - head)},
          {"shaft_diameter", diameter},
          {"head_length", head},
          {"head_diameter", 2.5 * diameter},
          {"color", rgba}};
}

Json lineStrip(const std::deque<Vec3>& points, const Json& rgba, double thickness) {
  Json array = Json::array();
  for (const Vec3& p : points) array.push_back(vector3(p));
  return {{"type", 0},  // LINE_STRIP
          {"pose", pose(Vec3::Zero(), identityQuat())},
          {"thickness", thickness},
          {"scale_invariant", true},
          {"points", array},
          {"color", rgba},
          {"colors", Json::array()},
          {"indices", Json::array()}};
}

Json entity(std::string id, std::string frame, bool frame_locked, int64_t stamp_ns) {
  Json e = {{"timestamp", foxgloveTime(stamp_ns)}, {"frame_id", std::move(frame)}, {"id", std::move(id)},
            {"lifetime", foxgloveTime(0)}, {"frame_locked", frame_locked}, {"metadata", Json::array()}};
  for (const char* kind : {"arrows", "cubes", "spheres", "cylinders", "lines", "triangles", "texts", "models"}) {
    e[kind] = Json::array();
  }
  return e;
}

// Two crossed arms (the X layout), four rotor discs and the body axes, in `frame`.
Json vehicleModel(std::string id, std::string frame, const VehicleGeometry& g, double alpha, int64_t stamp_ns) {
  Json e = entity(std::move(id), std::move(frame), true, stamp_ns);
  const double s = std::sqrt(0.5);
  const Json arm_color = color(0.15, 0.15, 0.18, alpha);
  for (double yaw : {M_PI / 4, -M_PI / 4}) {
    const Quat q = quatWxyz(std::cos(yaw / 2), 0.0, 0.0, std::sin(yaw / 2));
    e["cubes"].push_back({{"pose", pose(Vec3::Zero(), q)},
                          {"size", vector3(Vec3(2 * g.arm_length, 0.012, 0.008))},
                          {"color", arm_color}});
  }
  for (const auto& [x, y] : {std::pair{1.0, -1.0}, std::pair{-1.0, 1.0}, std::pair{1.0, 1.0}, std::pair{-1.0, -1.0}}) {  // FR, BL, FL, BR
    const Vec3 at(s * g.arm_length * x, s * g.arm_length * y, 0.01);
    const Json rgba = x > 0 ? color(0.95, 0.45, 0.1, 0.6 * alpha) : color(0.3, 0.3, 0.35, 0.6 * alpha);
    e["cylinders"].push_back({{"pose", pose(at, identityQuat())},
                              {"size", vector3(Vec3(2 * g.rotor_radius, 2 * g.rotor_radius, 0.004))},
                              {"bottom_scale", 1.0}, {"top_scale", 1.0}, {"color", rgba}});
  }
  e["arrows"].push_back(arrow(Vec3::Zero(), g.axis_length * Vec3::UnitX(), 0.006, color(0.9, 0.1, 0.1, alpha)));
  e["arrows"].push_back(arrow(Vec3::Zero(), g.axis_length * Vec3::UnitY(), 0.006, color(0.1, 0.8, 0.1, alpha)));
  e["arrows"].push_back(arrow(Vec3::Zero(), g.axis_length * Vec3::UnitZ(), 0.006, color(0.1, 0.3, 0.9, alpha)));
  return e;
}

// Reference point, trajectory, trails and the disturbance force, in the world frame.
Json worldEntity(const VehicleState& v, int64_t stamp_ns) {
  Json e = entity("world_overlays", std::string(kWorldFrame), false, stamp_ns);
  e["lines"].push_back(lineStrip(v.truth_trail.points(), color(0.95, 0.45, 0.1, 1.0), 2.0));
  e["lines"].push_back(lineStrip(v.estimate_trail.points(), color(0.2, 0.5, 1.0, 0.7), 2.0));
  if (v.trajectory && !v.trajectory->samples.empty()) {
    std::deque<Vec3> path;
    for (const TrajectorySample& s : v.trajectory->samples) path.push_back(s.x.head<3>());
    e["lines"].push_back(lineStrip(path, color(0.6, 0.6, 0.6, 0.8), 1.5));
  }
  if (v.reference) {
    e["spheres"].push_back({{"pose", pose(v.reference->x.head<3>(), identityQuat())},
                            {"size", vector3(Vec3::Constant(0.04))},
                            {"color", color(0.1, 0.8, 0.3, 0.9)}});
  }
  if (v.truth && v.truth->external_force.norm() > 1e-6) {
    // 1 N drawn 0.5 m long.
    e["arrows"].push_back(arrow(v.truth->position, 0.5 * v.truth->external_force, 0.01, color(0.8, 0.1, 0.8, 1.0)));
  }
  return e;
}

}  // namespace

void Trail::add(const Vec3& position) {
  if (!position.allFinite()) return;
  if (!points_.empty() && (position - points_.back()).norm() < spacing_) return;
  points_.push_back(position);
  while (points_.size() > capacity_) points_.pop_front();
}

std::string foxgloveTopic(std::string_view vehicle, std::string_view name) {
  std::string topic(vehicle);
  if (!topic.empty()) topic += '/';
  return topic + "foxglove/" + std::string(name);
}

std::string bodyFrame(std::string_view vehicle) { return vehicle.empty() ? "body" : std::string(vehicle) + "/body"; }
std::string estimateFrame(std::string_view vehicle) { return bodyFrame(vehicle) + "_estimate"; }

Json foxgloveTime(int64_t ns) {
  const int64_t t = std::max<int64_t>(0, ns);
  return {{"sec", t / 1'000'000'000}, {"nsec", t % 1'000'000'000}};
}

Json truthTransform(const SimTruth& truth, std::string_view vehicle, int64_t stamp_ns) {
  return {{"timestamp", foxgloveTime(stamp_ns)}, {"parent_frame_id", kWorldFrame}, {"child_frame_id", bodyFrame(vehicle)},
          {"translation", vector3(truth.position)}, {"rotation", quaternion(truth.orientation)}};
}

Json estimateTransform(const StateEstimate& estimate, std::string_view vehicle, int64_t stamp_ns) {
  return {{"timestamp", foxgloveTime(stamp_ns)}, {"parent_frame_id", kWorldFrame},
          {"child_frame_id", estimateFrame(vehicle)}, {"translation", vector3(estimate.position)},
          {"rotation", quaternion(estimate.orientation)}};
}

Json estimatePose(const StateEstimate& estimate, int64_t stamp_ns) {
  return {{"timestamp", foxgloveTime(stamp_ns)}, {"frame_id", kWorldFrame},
          {"pose", pose(estimate.position, estimate.orientation)}};
}

Json sceneUpdate(const VehicleState& v, std::string_view vehicle, const VehicleGeometry& geometry, int64_t stamp_ns) {
  Json entities = Json::array();
  if (v.truth) {
    Json model = vehicleModel("vehicle", bodyFrame(vehicle), geometry, 1.0, stamp_ns);
    if (v.command) {  // collective thrust along body z: hover thrust draws one arm length
      const double length = geometry.arm_length * std::max(0.0, v.command->thrust) / kGravity;
      if (length > 1e-4) model["arrows"].push_back(arrow(Vec3::Zero(), length * Vec3::UnitZ(), 0.008, color(1.0, 0.8, 0.0, 1.0)));
    }
    entities.push_back(model);
  }
  if (v.estimate) entities.push_back(vehicleModel("vehicle_estimate", estimateFrame(vehicle), geometry, 0.35, stamp_ns));
  entities.push_back(worldEntity(v, stamp_ns));
  return {{"deletions", Json::array()}, {"entities", entities}};
}

}  // namespace sdlqr::foxglove
