// The files of `./sdlqr compare --bus`: per law and experiment a vehicle file flying that law and
// the experiment pointing at it, loadable as the processes load them; a plan line per flight.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "compare_test_dir.hpp"
#include "sdlqr/compare/bus_flights.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/params/vehicle_file.hpp"

namespace sdlqr::compare {
namespace {

namespace fs = std::filesystem;

TEST(BusFlights, EachLawGetsItsVehicleFileAndTheExperimentPointingAtIt) {
  const fs::path dir = fs::temp_directory_path() / ("sdlqr_bus_flights_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  Benchmark benchmark = Benchmark::load(test::kDir + "/small_benchmark.yaml");
  selectScenarios(benchmark, "short_hover");
  benchmark.seed = 11;
  EXPECT_EQ(writeBusFlights(benchmark, dir.string()), 2);
  for (const char* law : {"sdlqr", "geometric"}) {
    const fs::path folder = dir / law / "short_hover";
    const mission::Scenario scenario = mission::Scenario::load((folder / "scenario.yaml").string());
    EXPECT_EQ(fs::path(scenario.vehicle_path), fs::absolute(folder / "vehicle.yaml")) << law;
    EXPECT_EQ(scenario.seed, 11) << law;
    const params::VehicleFile vehicle = params::VehicleFile::load(scenario.vehicle_path);
    ControlLaw expected;
    ASSERT_TRUE(parseControlLaw(law, expected));
    EXPECT_EQ(vehicle.lqr.law, expected) << law;
  }
  std::ifstream plan(dir / "plan.txt");
  std::string controller, experiment, folder;
  ASSERT_TRUE(plan >> controller >> experiment >> folder);
  EXPECT_EQ(controller + " " + experiment, "sdlqr short_hover");
  ASSERT_TRUE(plan >> controller >> experiment >> folder);
  EXPECT_EQ(controller, "geometric");
  EXPECT_FALSE(plan >> controller);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sdlqr::compare
