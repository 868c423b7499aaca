#include "sdlqr/controller/controller_params.hpp"

#include <array>

#include "sdlqr/math/in_flight.hpp"

namespace sdlqr::controller {

namespace {

// The hover LQR of the default lqr weights written as a cascade (control_family_test.cpp,
// Geometric.DefaultGainsAreTheHoverLqrsOwn, derives them): for small errors at hover the geometric
// law then commands what the LQR commands, and the two differ only where the paper says they do.
constexpr std::array<double, 3> kGeometricPositionGain = {5.61, 9.10, 29.7};
constexpr std::array<double, 3> kGeometricVelocityGain = {3.79, 5.14, 12.1};
constexpr std::array<double, 3> kGeometricAttitudeGain = {10.2, 7.53, 0.223};

}  // namespace

ControllerParams::ControllerParams() { declaration().setDefaults(*this); }

const ParamTable<ControllerParams>& ControllerParams::declaration() {
  static const ParamTable<ControllerParams> table = [] {
    using P = ControllerParams;
    ParamTable<P> t("100 Hz state-dependent LQR (sdlqr-controller)");
    t.number("rate_hz", &P::rate_hz, 100.0, "Hz", Range::closed(1.0, 1000.0), "control rate in simulation time (paper: 100 Hz)");
    t.number("max_prediction_s", &P::max_prediction_s, 0.005, "s", Range::closed(0.0, 0.02),
             "longest an estimate is carried forward to a tick (0: never)");
    t.number("gains_stale_s", &P::gains_stale_s, 0.3, "s", Range::above(0.0),
             "GAINS older than this are flagged stale (3 missed updates)");
    t.number("gains_fallback_s", &P::gains_fallback_s, 1.0, "s", Range::above(0.0),
             "GAINS older than this: switch to the precomputed hover K");
    t.number("max_position_error", &P::max_position_error, 1.0, "m", Range::above(0.0),
             "norm bound on p - p_ref fed to K (paper §IV-A)");
    t.number("max_velocity_error", &P::max_velocity_error, 2.0, "m/s", Range::above(0.0), "norm bound on v - v_ref fed to K");
    t.number("takeoff_speed", &P::takeoff_speed, 0.5, "m/s", Range::openClosed(0.0, 5.0), "climb rate of the take-off reference");
    t.number("landing_speed", &P::landing_speed, 0.4, "m/s", Range::openClosed(0.0, 2.0),
             "descent rate of the landing reference");
    t.number("landed_speed", &P::landed_speed, 0.1, "m/s", Range::above(0.0),
             "below this, near the ground, for landed_time: landed");
    t.number("landed_time", &P::landed_time, 1.0, "s", Range::atLeast(0.0), "how long landed_speed must hold");
    t.number("landing_undershoot", &P::landing_undershoot, 0.3, "m", Range::closed(0.0, 2.0),
             "the landing reference continues this far below the ground");
    t.number("rejoin_height", &P::rejoin_height, 0.2, "m", Range::openClosed(0.0, 10.0),
             "a restarted controller seeing the vehicle this high rejoins in a hold");
    t.number("recovery_tilt_deg", &P::recovery_tilt_deg, 10.0, "deg", Range::openClosed(0.0, 90.0),
             "a rejoin levels and stops the vehicle before it holds: tilted at most this ...");
    t.number("recovery_speed", &P::recovery_speed, 0.5, "m/s", Range::above(0.0),
             "... and moving at most this, the hold is set where the vehicle is");
    declareTracking(t, &P::tracking);  // in flight: every process that checks PARAMS knows it
    t.choice("trajectory_beyond_limits", &P::trajectory_beyond_limits, UploadBeyondLimits::kRefuse,
             {{"refuse", UploadBeyondLimits::kRefuse}, {"scale", UploadBeyondLimits::kScale}},
             "an uploaded TRAJECTORY beyond the limits: refused with the report, or flown time-scaled to its "
             "highest feasible speed (as a scenario's on_infeasible: scale)");
    t.section("guard", &P::guard);
    t.section("transition", &P::transition);
    t.number("switch_time_s", &P::switch_time_s, 0.5, "s", Range::closed(0.0, 5.0),
             "a law switch's command offset decays to zero over this time (0: the command jumps)");
    t.number("integral_limit", &P::integral_limit, 0.5, "m s", Range::above(0.0),
             "sdlqr_integral anti-windup: bound on the norm of the position-error integral");
    t.number("integral_zone", &P::integral_zone, 0.2, "m", Range::above(0.0),
             "sdlqr_integral anti-windup: integrates only within this distance of the reference (not during a jump)");
    t.number("thrust_gain_time_constant", &P::thrust_gain_time_constant, 1.0, "s", Range::closed(0.05, 100.0),
             "sdlqr_adaptive: time constant of the thrust gain estimate (produced over commanded thrust)");
    t.number("thrust_gain_min", &P::thrust_gain_min, 0.5, "-", Range::closed(0.1, 1.0),
             "sdlqr_adaptive: lower bound of the thrust gain estimate");
    t.number("thrust_gain_max", &P::thrust_gain_max, 1.5, "-", Range::closed(1.0, 10.0),
             "sdlqr_adaptive: upper bound of the thrust gain estimate");
    t.number("thrust_gain_zone", &P::thrust_gain_zone, 0.15, "m", Range::above(0.0),
             "sdlqr_adaptive: the thrust gain adapts only this close to the reference (not held or pushed away)");
    t.list<3>("geometric_position_gain", &P::geometric_position_gain, kGeometricPositionGain, "1/s^2", Range::above(0.0),
           "geometric kp x, y, z: the default hover LQR as a cascade");
    t.list<3>("geometric_velocity_gain", &P::geometric_velocity_gain, kGeometricVelocityGain, "1/s", Range::above(0.0),
           "geometric kd x, y, z: the default hover LQR as a cascade");
    t.list<3>("geometric_attitude_gain", &P::geometric_attitude_gain, kGeometricAttitudeGain, "1/s", Range::above(0.0),
           "geometric k_att roll, pitch, yaw: the default hover LQR's rate per attitude error");
    t.check("gains_fallback_s", [](const P& p) { return p.gains_fallback_s > p.gains_stale_s; }, "must be > gains_stale_s");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::controller
