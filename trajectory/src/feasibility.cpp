#include "sdlqr/trajectory/feasibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/drag_feedforward.hpp"

namespace sdlqr::trajectory {

namespace {

// The time scaling puts the top speed at v_max to rounding: do not fail on the last bits.
constexpr double kRelativeSlack = 1e-9;

}  // namespace

void accountSample(FeasibilityReport& report, const State& x, const Input& given, const FeasibilityLimits& limits,
                   double gravity) {
  const Input u = flownInput(x, given, gravity, limits.drag);
  report.max_speed = std::max(report.max_speed, velocity(x).norm());
  report.max_thrust = std::max(report.max_thrust, u[kThrust]);
  report.min_thrust = std::min(report.min_thrust, u[kThrust]);
  report.max_body_rate = std::max(report.max_body_rate, bodyRate(u).norm());
  ++report.points;
}

void judgeReport(FeasibilityReport& report, const FeasibilityLimits& limits) {
  report.speed_ok = report.max_speed <= limits.v_max * (1.0 + kRelativeSlack);
  report.max_thrust_ok = report.max_thrust <= limits.c_max;
  report.min_thrust_ok = report.min_thrust >= limits.c_min;
  report.body_rate_ok = report.max_body_rate <= limits.omega_max;
  report.consistency_ok = !(report.max_accel_mismatch > limits.accel_mismatch_max);
}

FeasibilityLimits FeasibilityLimits::from(const LqrParams& lqr, double v_max, double accel_mismatch_max) {
  FeasibilityLimits limits;
  limits.v_max = v_max;
  limits.c_min = lqr.c_min;
  limits.c_max = lqr.c_max;
  limits.omega_max = lqr.omega_max;
  limits.accel_mismatch_max = accel_mismatch_max;
  limits.drag = lqr.rotorDrag();
  return limits;
}

FeasibilityReport checkFeasibility(const MinSnapTrajectory& polynomial, const FeasibilityLimits& limits,
                                   double gravity, double grid_dt) {
  if (!std::isfinite(grid_dt) || grid_dt <= 0.0) throw std::invalid_argument("feasibility grid step must be > 0");
  FeasibilityReport report;
  const double duration = polynomial.duration();
  const long steps = std::max(1L, static_cast<long>(std::ceil(duration / grid_dt)));
  for (long i = 0; i <= steps; ++i) {
    const FlatOutput flat = polynomial.evaluate(duration * static_cast<double>(i) / static_cast<double>(steps));
    const FlatReference ref = flatToReference(flat, gravity);
    accountSample(report, ref.x, ref.u, limits, gravity);
    if (ref.singular) report.min_thrust = std::min(report.min_thrust, 0.0);
  }
  // The grid can miss the top speed by a hair; the refined search does not.
  report.max_speed = std::max(report.max_speed, maxSpeed(polynomial, grid_dt));
  judgeReport(report, limits);
  return report;
}

FeasibilityReport checkFeasibility(const Trajectory& trajectory, const FeasibilityLimits& limits, double gravity) {
  FeasibilityReport report;
  const auto& samples = trajectory.samples;
  auto modelAcceleration = [gravity](const TrajectorySample& s) {
    return Vec3(s.u[kThrust] * quat::bodyZ(orientation(s.x).normalized()) - Vec3(0.0, 0.0, gravity));
  };
  for (std::size_t k = 0; k < samples.size(); ++k) {
    accountSample(report, samples[k].x, samples[k].u, limits, gravity);
    if (k == 0) continue;
    const double dt = samples[k].t - samples[k - 1].t;
    if (!(dt > 0.0)) continue;
    const Vec3 demanded = (velocity(samples[k].x) - velocity(samples[k - 1].x)) / dt;
    const Vec3 produced = 0.5 * (modelAcceleration(samples[k]) + modelAcceleration(samples[k - 1]));
    const double mismatch = (demanded - produced).norm();
    report.max_accel_mismatch = k == 1 ? mismatch : std::max(report.max_accel_mismatch, mismatch);
  }
  judgeReport(report, limits);
  return report;
}

std::string describeViolations(const FeasibilityReport& r, const FeasibilityLimits& limits) {
  std::string text;
  char part[128];
  const auto fail = [&](bool ok, const char* what, double value, const char* relation, double limit, const char* unit) {
    if (ok) return;
    std::snprintf(part, sizeof part, " %s %.3g %s %.3g %s;", what, value, relation, limit, unit);
    text += part;
  };
  fail(r.speed_ok, "max speed", r.max_speed, ">", limits.v_max, "m/s");
  fail(r.max_thrust_ok, "max thrust", r.max_thrust, ">", limits.c_max, "m/s^2");
  fail(r.min_thrust_ok, "min thrust", r.min_thrust, "<", limits.c_min, "m/s^2");
  fail(r.body_rate_ok, "max |omega|", r.max_body_rate, ">", limits.omega_max, "rad/s");
  fail(r.consistency_ok, "accel mismatch", r.max_accel_mismatch, ">", limits.accel_mismatch_max, "m/s^2");
  return text;
}

std::string formatReport(const FeasibilityReport& report, const FeasibilityLimits& limits) {
  std::string text;
  char line[128];
  auto row = [&](const char* what, double value, const char* relation, double limit, const char* unit, bool ok) {
    std::snprintf(line, sizeof(line), "  %-18s %9.4f %-7s %2s %8.4f  %s\n", what, value, unit, relation, limit,
                  ok ? "pass" : "FAIL");
    text += line;
  };
  std::snprintf(line, sizeof(line), "feasibility (%ld points): %s\n", report.points,
                report.feasible() ? "feasible" : "NOT feasible");
  text += line;
  row("max speed", report.max_speed, "<=", limits.v_max, "m/s", report.speed_ok);
  row("max thrust c", report.max_thrust, "<=", limits.c_max, "m/s^2", report.max_thrust_ok);
  row("min thrust c", report.min_thrust, ">=", limits.c_min, "m/s^2", report.min_thrust_ok);
  row("max |omega|", report.max_body_rate, "<=", limits.omega_max, "rad/s", report.body_rate_ok);
  if (!std::isnan(report.max_accel_mismatch)) {
    row("accel mismatch", report.max_accel_mismatch, "<=", limits.accel_mismatch_max, "m/s^2", report.consistency_ok);
  }
  return text;
}

}  // namespace sdlqr::trajectory
