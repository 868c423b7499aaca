// Throw mode's detector (mission/throw_detector.hpp) on synthetic estimates at 250 Hz: a throw and
// a drop are confirmed a quarter second into free fall; a vehicle carried around, put down, or
// lifted fast by hand is not thrown.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/mission/throw_detector.hpp"

namespace sdlqr::mission {
namespace {

constexpr double kG = 9.81;
constexpr int64_t kPeriodUs = 4000;

struct Motion {
  Vec3 position;
  Vec3 velocity;
};

// Feeds estimates of motion(t) from 0 to `end` s; returns the detection time, if any.
std::optional<double> detect(const ThrowModeParams& params, double end, const std::function<Motion(double)>& motion) {
  ThrowDetector detector(params, kG);
  for (int64_t utime = 0; utime <= static_cast<int64_t>(end * 1e6); utime += kPeriodUs) {
    const double t = 1e-6 * static_cast<double>(utime);
    const Motion m = motion(t);
    StateEstimate e;
    e.utime = utime;
    e.status = EstimatorStatus::kOk;
    e.position = m.position;
    e.velocity = m.velocity;
    e.orientation = identityQuat();
    if (const auto d = detector.onEstimate(e)) return 1e-6 * static_cast<double>(d->utime);
  }
  return std::nullopt;
}

// Held at 1.2 m until 1 s, pushed to v_release over `push` s, then ballistic.
Motion thrown(double t, const Vec3& v_release, double push) {
  const Vec3 p0(0, 0, 1.2);
  if (t < 1.0) return {p0, Vec3::Zero()};
  const Vec3 a = push > 0 ? Vec3(v_release / push) : Vec3::Zero();
  const double tp = std::min(t - 1.0, push);
  const Vec3 p_release = p0 + 0.5 * push * push * a;
  if (t <= 1.0 + push) return {p0 + 0.5 * tp * tp * a, tp * a};
  const double tf = t - 1.0 - push;
  const Vec3 g(0, 0, -kG);
  return {p_release + tf * v_release + 0.5 * tf * tf * g, v_release + tf * g};
}

TEST(ThrowDetector, ThrowUpwardIsConfirmedAQuarterSecondIntoFreeFall) {
  ThrowModeParams params;
  const auto at = detect(params, 3.0, [](double t) { return thrown(t, Vec3(1, 0, 3), 0.3); });
  ASSERT_TRUE(at.has_value());
  // Released at 1.3 s; 2.5 m/s of velocity lost at g takes 0.255 s, plus the acceleration window.
  EXPECT_GT(*at, 1.3 + 0.25);
  EXPECT_LT(*at, 1.3 + 0.35);
}

TEST(ThrowDetector, DropIsConfirmedWhenTheTypeIsDrop) {
  ThrowModeParams params;
  params.type = ThrowType::kDrop;
  const auto drop = [](double t) { return thrown(t, Vec3::Zero(), 0.0); };
  const auto at = detect(params, 3.0, drop);
  ASSERT_TRUE(at.has_value());
  EXPECT_GT(*at, 1.25);
  EXPECT_LT(*at, 1.4);
  // A throw-type detector wants to see the vehicle climb: a drop is no throw for it.
  EXPECT_FALSE(detect(ThrowModeParams(), 3.0, drop).has_value());
}

// Negative: walking with the vehicle, bobbing it up and down, lifting it quickly by hand (the hand
// keeps pushing: specific force above 1 g) and setting it down are no throws.
TEST(ThrowDetector, CarryingLiftingAndSettingDownAreNoThrows) {
  const ThrowModeParams params;
  EXPECT_FALSE(detect(params, 10.0, [](double t) {
    const double w = 2.0 * M_PI * 1.5;  // 1.5 Hz steps, +-5 cm
    return Motion{Vec3(1.5 * t, 0, 1.2 + 0.05 * std::sin(w * t)), Vec3(1.5, 0, 0.05 * w * std::cos(w * t))};
  }).has_value());
  EXPECT_FALSE(detect(params, 3.0, [](double t) {
    // Lifted 1 m in 1 s with a cosine velocity profile: up to 2 m/s, the hand pushing with up to
    // 0.64 g and braking with up to 0.64 g (a hand under the vehicle cannot brake it faster than g:
    // that would be letting go, a throw).
    const double T = 1.0, s = std::clamp(t - 1.0, 0.0, T);
    const double vz = (1.0 - std::cos(2.0 * M_PI * s / T)) * (1.0 / T);
    return Motion{Vec3(0, 0, 1.0 + (s - T / (2.0 * M_PI) * std::sin(2.0 * M_PI * s / T)) / T), Vec3(0, 0, vz)};
  }).has_value());
  EXPECT_FALSE(detect(params, 3.0, [](double t) {
    const double s = std::clamp(t - 1.0, 0.0, 1.0);  // set down from 1.2 m at 1.2 m/s
    return Motion{Vec3(0, 0, 1.2 - 1.2 * s), Vec3(0, 0, t > 1.0 && t < 2.0 ? -1.2 : 0.0)};
  }).has_value());
}

TEST(ThrowDetector, DetectsOnceAndIgnoresUninitialisedAndRepeatedEstimates) {
  ThrowDetector detector(ThrowModeParams(), kG);
  StateEstimate e;
  e.status = EstimatorStatus::kInitializing;
  e.velocity = Vec3(0, 0, 3);
  EXPECT_FALSE(detector.onEstimate(e).has_value());
  int detections = 0;
  for (int64_t utime = 0; utime < 3000000; utime += kPeriodUs) {
    const Motion m = thrown(1e-6 * static_cast<double>(utime), Vec3(0, 0, 3), 0.3);
    e.utime = utime;
    e.status = EstimatorStatus::kOk;
    e.position = m.position;
    e.velocity = m.velocity;
    detections += detector.onEstimate(e).has_value() ? 1 : 0;
    detections += detector.onEstimate(e).has_value() ? 1 : 0;  // the same estimate again
  }
  EXPECT_EQ(detections, 1);
  EXPECT_TRUE(detector.detected());
}

}  // namespace
}  // namespace sdlqr::mission
