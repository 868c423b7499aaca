// The thrust mapping (px4/thrust_map.hpp): PX4's own law for a linear vehicle, the quadratic
// model's inverse, the clamps, and the hover throttle fitted back from a simulated hover.

#include <gtest/gtest.h>

#include <random>

#include "sdlqr/px4/thrust_map.hpp"

namespace sdlqr::px4 {
namespace {

constexpr double kG = 9.81;

TEST(ThrustMap, LinearMapIsPx4sOwnLaw) {
  ThrustMap map;
  map.hover_throttle = 0.4;
  map.curve = 0.0;
  EXPECT_NEAR(normalizedThrust(kG, map, kG), 0.4, 1e-12);        // hover thrust -> hover throttle
  EXPECT_NEAR(normalizedThrust(2.0 * kG, map, kG), 0.8, 1e-12);  // T = c h / g
  EXPECT_EQ(normalizedThrust(4.0 * kG, map, kG), 1.0);           // clamped
  EXPECT_EQ(normalizedThrust(-1.0, map, kG), 0.0);
  EXPECT_NEAR(massNormalizedThrust(0.8, map, kG), 2.0 * kG, 1e-12);
}

TEST(ThrustMap, QuadraticModelInvertsAndHoversAtTheHoverThrottle) {
  ThrustMap map;
  map.hover_throttle = 0.55;
  map.curve = 0.7;
  EXPECT_NEAR(normalizedThrust(kG, map, kG), 0.55, 1e-12);
  for (double c = 0.5; c < 15.0; c += 0.7) {
    EXPECT_NEAR(massNormalizedThrust(normalizedThrust(c, map, kG), map, kG), c, 1e-9) << c;
  }
  // f is convex with f(0) = 0: half the hover thrust needs more than half the hover throttle.
  EXPECT_GT(normalizedThrust(0.5 * kG, map, kG), 0.5 * 0.55);
}

TEST(ThrustMap, HoverThrottleFitsBackFromANoisyHover) {
  // The vehicle's true law: hover at 0.47; the bridge flew with 0.5: in steady hover it sends what
  // holds the vehicle (the controller closes the loop), the acceleration averages to zero.
  ThrustMap truth;
  truth.hover_throttle = 0.47;
  truth.curve = 0.3;
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.4), throttle(0.47, 0.02), tilt(0.0, 0.03);
  std::vector<HoverSample> samples;
  for (int i = 0; i < 2000; ++i) {
    HoverSample s;
    s.normalized_thrust = throttle(random);
    s.tilt = std::abs(tilt(random));
    s.vertical_acceleration = massNormalizedThrust(s.normalized_thrust, truth, kG) * std::cos(s.tilt) - kG + noise(random);
    samples.push_back(s);
  }
  const HoverFit fit = fitHoverThrottle(samples, truth.curve, kG);
  EXPECT_TRUE(fit.error.empty()) << fit.error;
  EXPECT_NEAR(fit.hover_throttle, 0.47, 0.002);
  EXPECT_NEAR(fit.residual_rms, 0.4, 0.05);
}

TEST(ThrustMap, NoFitWithoutSamples) {
  const HoverFit fit = fitHoverThrottle({}, 0.0, kG);
  EXPECT_TRUE(std::isnan(fit.hover_throttle));
  EXPECT_FALSE(fit.error.empty());
}

TEST(ThrustMap, DeclaredDefaultIsTheEmulatedQuad255sHover) {
  // mass 0.255 kg, 4 x 1.25 N rotors (config/quad255.yaml), g 9.81
  EXPECT_NEAR(ThrustMap().hover_throttle, 0.255 * 9.81 / 5.0, 1e-4);
}

}  // namespace
}  // namespace sdlqr::px4
