#include <gtest/gtest.h>

#include <sstream>

#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/trajectory/params.hpp"
#include "sdlqr/trajectory/trajectory_csv.hpp"
#include "sdlqr/trajectory/waypoint_file.hpp"

#include "config_errors.hpp"

namespace sdlqr::trajectory {
namespace {

TrajectoryParams loadText(const std::string& text) { return testing::loadSectionText<TrajectoryParams>(text, "trajectory"); }

TEST(TrajectoryParams, DefaultsAreThePapersAndValid) {
  const TrajectoryParams p;
  EXPECT_TRUE(p.valid()) << p.invalidReason();
  EXPECT_EQ(p.sample_dt, 0.1);
  EXPECT_EQ(p.fast_v_max, 3.0);
  EXPECT_EQ(p.slow_v_max, 1.0);
  EXPECT_EQ(p.ellipse_speed, 2.0);
  EXPECT_EQ(p.ellipse_samples, 36);
}

TEST(TrajectoryParams, LoadsEveryKey) {
  const TrajectoryParams p = loadText(
      "{sample_dt: 0.05, check_dt: 0.002, height_offset: 1.5, laps: 3, periodic: true, yaw: 0.3, fast_v_max: 2.5,"
      " slow_v_max: 0.8, ellipse_speed: 1.5, ellipse_samples: 72, max_position_jump: 0.4, accel_mismatch_max: 0.7}");
  EXPECT_EQ(p.sample_dt, 0.05);
  EXPECT_EQ(p.check_dt, 0.002);
  EXPECT_EQ(p.height_offset, 1.5);
  EXPECT_EQ(p.laps, 3);
  EXPECT_TRUE(p.periodic);
  EXPECT_EQ(p.yaw, 0.3);
  EXPECT_EQ(p.fast_v_max, 2.5);
  EXPECT_EQ(p.slow_v_max, 0.8);
  EXPECT_EQ(p.ellipse_speed, 1.5);
  EXPECT_EQ(p.ellipse_samples, 72);
  EXPECT_EQ(p.max_position_jump, 0.4);
  EXPECT_EQ(p.accel_mismatch_max, 0.7);
  EXPECT_EQ(p.sampleChecks().max_position_jump, 0.4);
}

TEST(TrajectoryParams, EveryInvalidFieldNamesItsKey) {
  testing::expectKeysBlamed(loadText, {
      {"{sample_dt: 0}", "trajectory.sample_dt"},
      {"{check_dt: 0.5}", "trajectory.check_dt"},  // coarser than the samples
      {"{laps: 0}", "trajectory.laps"},
      {"{laps: 1.5}", "trajectory.laps"},
      {"{periodic: 3}", "trajectory.periodic"},
      {"{fast_v_max: -3}", "trajectory.fast_v_max"},
      {"{slow_v_max: .nan}", "trajectory.slow_v_max"},
      {"{ellipse_speed: 0}", "trajectory.ellipse_speed"},
      {"{ellipse_samples: 2}", "trajectory.ellipse_samples"},
      {"{max_position_jump: 0}", "trajectory.max_position_jump"},
      {"{accel_mismatch_max: -1}", "trajectory.accel_mismatch_max"},
      {"{v_max: 3}", "trajectory.v_max"},  // unknown key
  });
}

TEST(TrajectoryParams, VehicleFileSectionLoads) {
  const ConfigReader root(loadYamlFile(std::string(SDLQR_SOURCE_DIR) + "/config/quad255.yaml"), "");
  const TrajectoryParams p = TrajectoryParams::load(root.child("trajectory"));
  EXPECT_TRUE(p.valid());
  EXPECT_EQ(p.sample_dt, 0.1);
  EXPECT_EQ(p.ellipse_samples, 36);
}

WaypointSpec waypointsFromYaml(const std::string& text) {
  const YAML::Node node = YAML::Load(text);
  return loadWaypointSpec(ConfigReader(node, ""), node);
}

TEST(WaypointFile, YamlWaypoints) {
  const WaypointSpec spec = waypointsFromYaml("{waypoints: [[0, 0, 1], [1, 2, 3.5], [2, 0, 1]], periodic: true, v_max: 2}");
  ASSERT_EQ(spec.waypoints.size(), 3u);
  EXPECT_EQ(spec.waypoints[1].position, Vec3(1, 2, 3.5));
  EXPECT_FALSE(spec.waypoints[1].has_yaw);
  EXPECT_TRUE(spec.periodic);
  EXPECT_EQ(spec.v_max, 2.0);
  const WaypointSpec with_yaw = waypointsFromYaml("{waypoints: [[0, 0, 1, 0.5], [1, 2, 3, -1]]}");
  EXPECT_TRUE(with_yaw.waypoints[1].has_yaw);
  EXPECT_EQ(with_yaw.waypoints[1].yaw, -1.0);
  EXPECT_EQ(with_yaw.v_max, 0.0);
}

TEST(WaypointFile, YamlErrorsNameTheKey) {
  testing::expectKeysBlamed(waypointsFromYaml, {
      {"{periodic: true}", "waypoints"},
      {"{waypoints: [[0, 0, 1]]}", "waypoints"},
      {"{waypoints: [[0, 0, 1], [1, 1]]}", "waypoints[1]"},
      {"{waypoints: [[0, 0, 1], [1, x, 1]]}", "waypoints[1][1]"},
      {"{waypoints: [[0, 0, 1], [1, .inf, 1]]}", "waypoints[1][1]"},
      {"{waypoints: [[0, 0, 1], [1, 1, 1, 0.3]]}", "waypoints[1]"},
      {"{waypoints: [[0, 0, 1], [1, 1, 1]], v_max: 0}", "v_max"},
      {"{waypoints: [[0, 0, 1], [1, 1, 1]], speed: 2}", "speed"},
  });
}

std::string waypointCsvError(const std::string& text) {
  return testing::messageThrownBy<TrajectoryFileError>([&] {
    std::istringstream in(text);
    parseWaypointCsv(in, "w.csv");
  });
}

TEST(WaypointFile, CsvWaypoints) {
  std::istringstream in("# corners\nx,y,z\n0,0,1\n\n1.5, 0, 1.5\n0,1.5,1\n");
  const std::vector<Waypoint> waypoints = parseWaypointCsv(in, "w.csv");
  ASSERT_EQ(waypoints.size(), 3u);
  EXPECT_EQ(waypoints[1].position, Vec3(1.5, 0, 1.5));
  EXPECT_EQ(waypointCsvError("0,0,1\n1,1\n"), "w.csv:2: expected x,y,z or x,y,z,yaw, got 2 columns");
  EXPECT_EQ(waypointCsvError("0,0,1\n1,b,1\n"), "w.csv:2: cannot parse 'b' as a finite number");
  EXPECT_EQ(waypointCsvError("0,0,1\n1,nan,1\n"), "w.csv:2: cannot parse 'nan' as a finite number");
  EXPECT_EQ(waypointCsvError("0,0,1\n1,1,1,0.2\n"), "w.csv:2: give yaw on every waypoint or on none");
  EXPECT_EQ(waypointCsvError("# only one\n0,0,1\n"), "w.csv:2: need at least 2 waypoints");
}

}  // namespace
}  // namespace sdlqr::trajectory
