// The scenario keys of the stressors: `sim:`, `throw_mode:` and the speed paths of a trajectory
// event. A bad value is one ConfigError naming the key.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "sdlqr/mission/scenario.hpp"
#include "test_paths.hpp"

namespace sdlqr::mission {
namespace {

std::string errorOf(const std::string& yaml) {
  const std::string path = sdlqr::test::tempPath("stress_scenario.yaml");
  std::ofstream(path) << yaml;
  try {
    Scenario::load(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StressScenario, SimAndThrowModeKeysAreRead) {
  const std::string path = sdlqr::test::tempPath("stress_ok.yaml");
  std::ofstream(path) << "sim: {plant: {mass_scale: 1.2}, wind: {steady: [1, 0, 0]}}\nthrow_mode: {at: 1.0, type: drop}\n";
  const Scenario s = Scenario::load(path);
  EXPECT_EQ(s.sim.plant.mass_scale, 1.2);
  EXPECT_EQ(s.sim.wind.steady, Vec3(1, 0, 0));
  EXPECT_TRUE(s.throw_mode.enabled());
  EXPECT_EQ(s.throw_mode.type, ThrowType::kDrop);
}

// The simulator reads the scenario's world itself (sdlqr-sim --scenario), not through the mission.
TEST(StressScenario, TheSimulatorReadsTheWorldTheScenarioDeclares) {
  const std::string path = sdlqr::test::tempPath("stress_sim.yaml");
  std::ofstream(path) << "sim: {plant: {mass_scale: 1.2}, wind: {steady: [1, 0, 0]}}\nevents: []\n";
  const sim::SimStress world = sim::SimStress::loadFromScenario(path);
  EXPECT_EQ(world.plant.mass_scale, Scenario::load(path).sim.plant.mass_scale);
  EXPECT_EQ(world.wind.steady, Vec3(1, 0, 0));
  std::ofstream(path) << "sim: {plant: {mass_scale: 0.1}}\n";
  try {
    sim::SimStress::loadFromScenario(path);
    ADD_FAILURE() << "a bad mass_scale was read";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("sim.plant.mass_scale"), std::string::npos) << e.what();
  }
}

TEST(StressScenario, BadValuesNameTheirKey) {
  EXPECT_NE(errorOf("sim: {plant: {mass_scale: 0.1}}").find("sim.plant.mass_scale"), std::string::npos);
  EXPECT_NE(errorOf("sim: {wnd: {}}").find("sim.wnd"), std::string::npos);
  EXPECT_NE(errorOf("throw_mode: {type: catapult}").find("throw_mode.type"), std::string::npos);
  const std::string head = "events:\n  - {at: 1.0, trajectory: ";
  EXPECT_NE(errorOf(head + "{generator: circle}}").find("events[0].trajectory.speed"), std::string::npos);
  EXPECT_NE(errorOf(head + "{generator: circle, speed: -2}}").find("events[0].trajectory.speed"), std::string::npos);
  EXPECT_NE(errorOf(head + "{generator: circle, speed: 2, on_infeasible: maybe}}").find("on_infeasible"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "{generator: waypoints, speed: 2}}").find("events[0].trajectory.waypoints"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "{generator: minsnap_fast, speed: 2}}").find("events[0].trajectory.speed"),
            std::string::npos);
  EXPECT_EQ(errorOf(head + "{generator: lemniscate, speed: 2, size: 1.5, on_infeasible: scale}}"), "no error");
  EXPECT_EQ(errorOf(head + "{generator: ellipse, on_infeasible: fly}}"), "no error") << "every generator";
  EXPECT_NE(errorOf("sim: {payload_drop: {mass_scale: 0.1}}").find("sim.payload_drop.mass_scale"), std::string::npos);
}

}  // namespace
}  // namespace sdlqr::mission
