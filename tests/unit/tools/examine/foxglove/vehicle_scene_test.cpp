// The vehicle in Foxglove's schemas: poses with Foxglove's quaternion order, frames per vehicle
// prefix, the scene's entities, bounded trails; each message valid under Foxglove's own schema.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "json_schema_check.hpp"
#include "sdlqr/foxglove/foxglove_schemas.hpp"
#include "sdlqr/foxglove/vehicle_scene.hpp"
#include "sdlqr/foxglove/vehicle_tracker.hpp"
#include "sdlqr/bus/convert.hpp"

namespace sdlqr::foxglove {
namespace {

SimTruth truthState() {
  SimTruth t;
  t.utime = 2'500'000;
  t.position = Vec3(1.0, -2.0, 0.5);
  t.orientation = Quat(std::cos(0.3), 0.0, 0.0, std::sin(0.3));  // w, x, y, z: yawed 0.6 rad
  t.external_force = Vec3(0.0, 2.0, 0.0);
  return t;
}

TEST(VehicleScene, TopicsAndFramesFollowTheVehiclePrefix) {
  EXPECT_EQ(foxgloveTopic("", "scene"), "foxglove/scene");
  EXPECT_EQ(foxgloveTopic("QUAD1", "truth_tf"), "QUAD1/foxglove/truth_tf");
  EXPECT_EQ(bodyFrame(""), "body");
  EXPECT_EQ(bodyFrame("QUAD1"), "QUAD1/body");
  EXPECT_EQ(estimateFrame("QUAD1"), "QUAD1/body_estimate");
}

TEST(VehicleScene, TransformCarriesThePoseInFoxglovesQuaternionOrder) {
  const Json tf = truthTransform(truthState(), "QUAD1", 1'700'000'000'123'456'789);
  EXPECT_EQ(tf["parent_frame_id"], "world");
  EXPECT_EQ(tf["child_frame_id"], "QUAD1/body");
  EXPECT_EQ(tf["translation"], Json({{"x", 1.0}, {"y", -2.0}, {"z", 0.5}}));
  EXPECT_EQ(tf["rotation"]["w"], std::cos(0.3));
  EXPECT_EQ(tf["rotation"]["z"], std::sin(0.3));
  EXPECT_EQ(tf["timestamp"], Json({{"sec", 1'700'000'000}, {"nsec", 123'456'789}}));
  EXPECT_EQ(testing::violation(tf, Json::parse(kFrameTransformSchema)), "");
}

TEST(VehicleScene, EstimateAsTransformAndPose) {
  StateEstimate e;
  e.position = Vec3(0.1, 0.2, 0.3);
  const Json pose = estimatePose(e, 5);
  EXPECT_EQ(pose["frame_id"], "world");
  EXPECT_EQ(pose["pose"]["orientation"]["w"], 1.0);
  EXPECT_EQ(testing::violation(pose, Json::parse(kPoseInFrameSchema)), "");
  EXPECT_EQ(testing::violation(estimateTransform(e, "", 5), Json::parse(kFrameTransformSchema)), "");
}

TEST(VehicleScene, SceneHoldsTheVehicleItsGhostAndTheWorldOverlays) {
  VehicleTracker tracker;
  auto feed = [&](std::string_view base, const auto& plain) {
    const auto lcm = bus::toLcm(plain);
    std::string bytes(static_cast<std::size_t>(lcm.getEncodedSize()), '\0');
    lcm.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    return tracker.onMessage(base, bytes.data(), bytes.size());
  };
  EXPECT_EQ(feed("SIM_TRUTH", truthState()), VehicleTracker::Update::kTruth);
  EXPECT_EQ(feed("STATE_EST", StateEstimate{}), VehicleTracker::Update::kEstimate);
  RateCommand command;
  command.thrust = 9.81;
  EXPECT_EQ(feed("RATE_CMD", command), VehicleTracker::Update::kOther);
  EXPECT_EQ(tracker.onMessage("IMU", "x", 1), VehicleTracker::Update::kNone);
  EXPECT_EQ(tracker.onMessage("SIM_TRUTH", "x", 1), VehicleTracker::Update::kNone);  // not one whole message
  const Json scene = sceneUpdate(tracker.state(), "QUAD1", VehicleGeometry{}, 7);
  EXPECT_EQ(testing::violation(scene, Json::parse(kSceneUpdateSchema)), "");
  ASSERT_EQ(scene["entities"].size(), 3u);
  const Json& vehicle = scene["entities"][0];
  EXPECT_EQ(vehicle["frame_id"], "QUAD1/body");
  EXPECT_EQ(vehicle["cubes"].size(), 2u);      // two crossed arms
  EXPECT_EQ(vehicle["cylinders"].size(), 4u);  // four rotors
  EXPECT_EQ(vehicle["arrows"].size(), 4u);     // three body axes and the thrust
  // The thrust arrow points along body z: +x (an arrow's direction) turned by its orientation.
  const Json& q = vehicle["arrows"][3]["pose"]["orientation"];
  const Eigen::Quaterniond thrust(q["w"].get<double>(), q["x"].get<double>(), q["y"].get<double>(), q["z"].get<double>());
  EXPECT_NEAR((thrust * Vec3::UnitX() - Vec3::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_EQ(scene["entities"][1]["frame_id"], "QUAD1/body_estimate");
  const Json& world = scene["entities"][2];
  EXPECT_EQ(world["frame_id"], "world");
  EXPECT_EQ(world["arrows"].size(), 1u);  // the disturbance force
  EXPECT_EQ(world["lines"][0]["points"].size(), 1u);  // the truth trail so far
}

TEST(VehicleScene, TrailsKeepPointsApartAndBounded) {
  Trail trail(5, 0.01);
  trail.add(Vec3::Zero());
  trail.add(Vec3(0.005, 0, 0));  // under 1 cm from the last: not kept
  EXPECT_EQ(trail.points().size(), 1u);
  for (int i = 1; i <= 10; ++i) trail.add(Vec3(0.1 * i, 0, 0));
  EXPECT_EQ(trail.points().size(), 5u);
  EXPECT_EQ(trail.points().back().x(), 1.0);
  trail.add(Vec3(std::nan(""), 0, 0));
  EXPECT_EQ(trail.points().size(), 5u);
}

}  // namespace
}  // namespace sdlqr::foxglove
