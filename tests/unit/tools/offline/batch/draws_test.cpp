// Flight draws: a function of (seed, flight) alone, within their distributions, grids as a product.
#include <gtest/gtest.h>

#include <set>

#include "sdlqr/batch/draws.hpp"
#include "batch_test_dir.hpp"

namespace sdlqr::batch {
namespace {

using test::kDir;


TEST(Draws, SameFlightSameDrawWhateverOrder) {
  const BatchSpec spec = BatchSpec::load(kDir + "/small_batch.yaml");
  const closedloop::StackConfig config;
  const FlightDraw late = drawFlight(spec, config, sim::SimStress(), 17);
  for (int k = 0; k < 17; ++k) drawFlight(spec, config, sim::SimStress(), k);
  const FlightDraw again = drawFlight(spec, config, sim::SimStress(), 17);
  EXPECT_EQ(late.seed, again.seed);
  EXPECT_EQ(late.values, again.values);
  EXPECT_NE(drawFlight(spec, config, sim::SimStress(), 16).values, late.values);
  BatchSpec reseeded = spec;
  reseeded.seed = 12;
  EXPECT_NE(drawFlight(reseeded, config, sim::SimStress(), 17).values, late.values);
}

TEST(Draws, ValuesFollowTheirDistributions) {
  const BatchSpec spec = BatchSpec::load(kDir + "/small_batch.yaml");
  const closedloop::StackConfig config;
  std::set<long long> seeds;
  std::set<double> grid;
  double inertia_sum = 0.0;
  const int n = 400;
  for (int k = 0; k < n; ++k) {
    const FlightDraw d = drawFlight(spec, config, sim::SimStress(), k);
    seeds.insert(d.seed);
    EXPECT_GE(d.seed, 0);
    EXPECT_GE(d.values[0], 0.25);  // vehicle.mass uniform [0.25, 0.26]
    EXPECT_LT(d.values[0], 0.26);
    EXPECT_GT(d.values[1], 0.0);  // relative whole list: the factor
    inertia_sum += d.values[1];
    grid.insert(d.values[2]);
    EXPECT_DOUBLE_EQ(d.values[2], k % 2 == 0 ? 0.025 : 0.035);  // the only grid: alternates
    EXPECT_GE(d.values[4], 0.8 * config.sim.imu.gyro_noise_density);  // relative number: applied
    EXPECT_LT(d.values[4], 1.2 * config.sim.imu.gyro_noise_density);
  }
  EXPECT_EQ(seeds.size(), static_cast<size_t>(n));
  EXPECT_EQ(grid.size(), 2u);
  EXPECT_NEAR(inertia_sum / n, 1.0, 4.0 * 0.05 / std::sqrt(n));
}

TEST(Draws, ShardsPartitionTheFlights) {
  for (int k = 0; k < 50; ++k) {
    int owners = 0;
    for (int i = 1; i <= 4; ++i) owners += inShard(k, i, 4) ? 1 : 0;
    EXPECT_EQ(owners, 1) << k;
  }
}

}  // namespace
}  // namespace sdlqr::batch
