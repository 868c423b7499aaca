// Why a 2 N / 0.5 s shove (hover_jumps' pull until it became a hand's hold-and-release) came back
// ~60 % past its setpoint where the paper's Fig. 4 shows very little overshoot: the shove is flown
// with one suspect changed at a time — the 2 m/s velocity-error bound, the 1 m position-error
// bound, the 2 rad/s body-rate limit, the gain rate, Q, the pull's size and shape — and the return
// overshoot (fraction of the largest deviation, PullWindow::return_overshoot) measured for each.
// The figures are printed; the assertions pin down the cause they show: holding 0.8 g of side
// force tilts the vehicle ~50 degrees, and after release that tilt unwinds at no more than
// omega_max = 2 rad/s while the thrust keeps accelerating the vehicle back through the setpoint.

#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/closedloop/closed_loop.hpp"
#include "test_paths.hpp"

namespace sdlqr {
namespace {

using ::sdlqr::test::kSourceDir;

struct PullResult {
  double deviation = 0.0;  // [m]
  double overshoot = 0.0;  // [-]
  double return_time = 0.0;  // [s]
  bool overshoot_check_passes = false;  // hover_jumps' pull_return_overshoot criterion
};

using Edit = void (*)(closedloop::StackConfig&, Disturbance&);

PullResult flyPull(Edit edit) {
  mission::Scenario scenario = mission::Scenario::load(kSourceDir + "/config/scenarios/hover_jumps.yaml");
  closedloop::StackConfig config = closedloop::StackConfig::load(scenario.vehicle_path);
  for (mission::ScenarioEvent& e : scenario.events) {
    if (e.kind != mission::ScenarioEvent::Kind::kDisturbance) continue;
    e.disturbance.mode = DisturbanceMode::kForce;  // the shove: 2 N along +y for 0.5 s
    e.disturbance.force = Vec3(0.0, 2.0, 0.0);
    e.disturbance.duration = 0.5;
    edit(config, e.disturbance);
  }
  closedloop::ClosedLoop loop(config, scenario);
  loop.run();
  const analysis::FlightReport report = analysis::analyzeFlight(loop.log(), scenario);
  EXPECT_EQ(report.pulls.size(), 1u);
  if (report.pulls.empty()) return {};
  PullResult result{report.pulls[0].max_deviation, report.pulls[0].return_overshoot, report.pulls[0].return_time};
  for (const analysis::Check& check : report.checks) {
    if (check.key == "pull_return_overshoot") result.overshoot_check_passes = check.pass;
  }
  return result;
}

PullResult report(const char* what, Edit edit) {
  const PullResult r = flyPull(edit);
  std::printf("  %-52s pushed %.2f m, back %4.0f %% past the setpoint, within 10 cm after %.2f s\n", what, r.deviation,
              100.0 * r.overshoot, r.return_time);
  return r;
}

TEST(PullOvershoot, TheBodyRateLimitNotTheErrorBoundsOrGainRateMakesAShoveOvershoot) {
  std::cout << "hover_jumps with a 2 N / 0.5 s shove along +y, one change at a time:\n";
  const PullResult as_flown = report("as flown (2 N for 0.5 s)", [](closedloop::StackConfig&, Disturbance&) {});
  const PullResult no_velocity_bound = report("velocity-error bound 2 -> 100 m/s", [](closedloop::StackConfig& c, Disturbance&) {
    c.controller.max_velocity_error = 100.0;
  });
  const PullResult no_position_bound = report("position-error bound 1 -> 100 m", [](closedloop::StackConfig& c, Disturbance&) {
    c.controller.max_position_error = 100.0;
  });
  const PullResult faster_rates = report("omega_max 2 -> 6 rad/s", [](closedloop::StackConfig& c, Disturbance&) {
    c.lqr.omega_max = 6.0;
  });
  const PullResult faster_gains = report("GAINS 10 -> 100 Hz", [](closedloop::StackConfig& c, Disturbance&) {
    c.gains.rate_hz = 100.0;
  });
  const PullResult smaller = report("pull 2 N -> 0.5 N", [](closedloop::StackConfig&, Disturbance& d) {
    d.force *= 0.25;
  });
  const PullResult more_damping = report("velocity weight 10 -> 40 (Q)", [](closedloop::StackConfig& c, Disturbance&) {
    c.lqr.q_diag.segment<3>(kVel).setConstant(40.0);
  });
  // A human pull: the vehicle held on a spring at 0.6 m and let go nearly at rest.
  const PullResult held = report("held 0.65 m aside (40 N/m) for 2 s, let go at rest", [](closedloop::StackConfig&, Disturbance& d) {
    d.mode = DisturbanceMode::kHold;
    d.force.setZero();
    d.duration = 2.0;
    d.hold_position = Vec3(0.0, 0.65, 1.0);
    d.hold_stiffness = 40.0;
    d.hold_damping = 4.0;
  });

  EXPECT_GT(as_flown.overshoot, 0.4) << "the overshoot this test explains";
  // Not the error bounds (never reached: the overshoot does not move), not the gain rate.
  EXPECT_NEAR(no_velocity_bound.overshoot, as_flown.overshoot, 0.03);
  EXPECT_NEAR(no_position_bound.overshoot, as_flown.overshoot, 0.03);
  EXPECT_NEAR(faster_gains.overshoot, as_flown.overshoot, 0.05);
  // More velocity weight helps a little; the rate limit is what decides.
  EXPECT_GT(more_damping.overshoot, 0.3);
  EXPECT_LT(faster_rates.overshoot, 0.1) << "omega_max 6 rad/s: the tilt unwinds in time";
  EXPECT_LT(smaller.overshoot, 0.15) << "a quarter of the force needs a quarter of the tilt";
  EXPECT_LT(held.overshoot, 0.1) << "a pull released at rest (a hand's) comes back like a reference jump";
  // The criterion (hover_jumps: <= 10 %) fails the shove and passes the hand's pull.
  EXPECT_FALSE(as_flown.overshoot_check_passes);
  EXPECT_TRUE(held.overshoot_check_passes);
}

}  // namespace
}  // namespace sdlqr
