#include "sdlqr/trajectory/transition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include <Eigen/LU>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/drag_feedforward.hpp"
#include "sdlqr/trajectory/polynomial.hpp"

#include "transition_rows.hpp"

namespace sdlqr::trajectory {

namespace {

using SepticCoefficients = Eigen::Matrix<double, 3, 8>;

// The first duration tried, its growth, and the bisection steps after one was found flyable
// (the duration to 0.1 %).
constexpr double kFirstDuration = 0.25;  // [s]
constexpr double kDurationStep = 1.25;   // each duration tried is this times the one before
constexpr int kBisections = 8;  // within a step of 1.25: the duration to 0.1 %
constexpr int kGridPoints = 200;

// The end conditions of s^4..s^7 at s = 1: value, first, second and third derivative.
const Eigen::Matrix4d& endMatrixInverse() {
  static const Eigen::Matrix4d inverse = [] {
    Eigen::Matrix4d m;
    m << 1, 1, 1, 1,  //
        4, 5, 6, 7,   //
        12, 20, 30, 42,  //
        24, 60, 120, 210;
    return Eigen::Matrix4d(m.inverse());
  }();
  return inverse;
}

// The same for s^4..s^6 at s = 1, first to third derivative: a stop whose end position is free
// (the natural condition of the least snap, the s^7 coefficient zero).
const Eigen::Matrix3d& stopMatrixInverse() {
  static const Eigen::Matrix3d inverse = [] {
    Eigen::Matrix3d m;
    m << 4, 5, 6,  //
        12, 20, 30,  //
        24, 60, 120;
    return Eigen::Matrix3d(m.inverse());
  }();
  return inverse;
}

double wrapTransitionAngle(double angle) { return std::remainder(angle, 2.0 * M_PI); }


}  // namespace

TransitionParams::TransitionParams() { declaration().setDefaults(*this); }

const ParamTable<TransitionParams>& TransitionParams::declaration() {
  static const ParamTable<TransitionParams> table = transitionParamsRows();
  return table;
}

FlatState flatStateOf(const State& x, const Input& u, double thrust_rate, double gravity) {
  const Quat q = orientation(x).normalized();
  const Mat3 r = quat::rotationMatrix(q);
  const double c = u[kThrust];
  const Vec3 omega = bodyRate(u);
  FlatState s;
  s.position = position(x);
  s.velocity = velocity(x);
  s.acceleration = c * r.col(2) - Vec3(0.0, 0.0, gravity);
  s.jerk = thrust_rate * r.col(2) + c * (omega.y() * r.col(0) - omega.x() * r.col(1));
  s.yaw = quat::yaw(q);
  return s;
}

FlatState flatStateAtStart(const Trajectory& trajectory, double gravity) {
  const auto& samples = trajectory.samples;
  double thrust_rate = 0.0;
  if (samples.size() >= 2 && samples[1].t > samples[0].t) {
    thrust_rate = (samples[1].u[kThrust] - samples[0].u[kThrust]) / (samples[1].t - samples[0].t);
  }
  return flatStateOf(samples.front().x, samples.front().u, thrust_rate, gravity);
}

void Transition::setStart(const FlatState& from, double duration) {
  duration_ = duration;
  const double T = duration;
  coefficients_.col(0) = from.position;
  coefficients_.col(1) = from.velocity * T;
  coefficients_.col(2) = from.acceleration * (T * T / 2.0);
  coefficients_.col(3) = from.jerk * (T * T * T / 6.0);
  yaw_start_ = from.yaw;
}

// What s^0..s^3 leave of the end's derivatives of `order`, in normalized time.
Vec3 Transition::startPart(int order) const {
  Vec3 reached = Vec3::Zero();
  for (int k = order; k < 4; ++k) reached += fallingFactorial(k, order) * coefficients_.col(k);
  return reached;
}

Transition Transition::between(const FlatState& from, const FlatState& to, double duration) {
  Transition out;
  out.setStart(from, duration);
  const double T = duration;
  Eigen::Matrix<double, 4, 3> rest;
  const Vec3 targets[4] = {to.position, to.velocity * T, to.acceleration * (T * T), to.jerk * (T * T * T)};
  for (int order = 0; order < 4; ++order) rest.row(order) = (targets[order] - out.startPart(order)).transpose();
  out.coefficients_.rightCols<4>() = (endMatrixInverse() * rest).transpose();
  out.yaw_change_ = wrapTransitionAngle(to.yaw - from.yaw);
  return out;
}

Transition Transition::stopping(const FlatState& from, double duration) {
  Transition out;
  out.setStart(from, duration);
  Eigen::Matrix<double, 3, 3> rest;
  for (int order = 1; order < 4; ++order) rest.row(order - 1) = -out.startPart(order).transpose();
  out.coefficients_.middleCols<3>(4) = (stopMatrixInverse() * rest).transpose();
  out.coefficients_.col(7).setZero();
  out.yaw_change_ = 0.0;
  return out;
}

FlatOutput Transition::at(double t) const {
  const double T = duration_;
  const double s = std::clamp(t / T, 0.0, 1.0);
  double power[8];
  power[0] = 1.0;
  for (int k = 1; k < 8; ++k) power[k] = power[k - 1] * s;
  Vec3 d[5] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (int order = 0; order < 5; ++order) {
    for (int k = order; k < 8; ++k) d[order] += fallingFactorial(k, order) * power[k - order] * coefficients_.col(k);
  }
  FlatOutput f;
  f.t = s * T;
  f.position = d[0];
  f.velocity = d[1] / T;
  f.acceleration = d[2] / (T * T);
  f.jerk = d[3] / (T * T * T);
  f.snap = d[4] / (T * T * T * T);
  const double blend = s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
  const double blend_rate = 30.0 * s * s * (1.0 - s) * (1.0 - s);
  f.yaw = yaw_start_ + yaw_change_ * blend;
  f.yaw_rate = yaw_change_ * blend_rate / T;
  return f;
}

namespace {

// Grid point i of a transition (kGridPoints + 1 of them, ends included) into the report's extremes.
void accountGridPoint(FeasibilityReport& report, const Transition& transition, int i, const FeasibilityLimits& limits,
                      double gravity) {
  const FlatOutput flat = transition.at(transition.duration() * static_cast<double>(i) / kGridPoints);
  const FlatReference ref = flatToReference(flat, gravity);
  accountSample(report, ref.x, ref.u, limits, gravity);
  if (ref.singular) report.min_thrust = std::min(report.min_thrust, 0.0);
}

}  // namespace

FeasibilityReport checkFeasibility(const Transition& transition, const FeasibilityLimits& limits, double gravity) {
  FeasibilityReport report;
  for (int i = 0; i <= kGridPoints; ++i) accountGridPoint(report, transition, i, limits, gravity);
  judgeReport(report, limits);
  return report;
}

namespace {

// The thrust and body rates a flat state asks for, flown against the model's rotor drag as the
// check judges every point (drag_feedforward.hpp flownInput; heading held).
Input inputsAt(const FlatState& s, double gravity, const RotorDrag& drag) {
  FlatOutput f;
  f.velocity = s.velocity;
  f.acceleration = s.acceleration;
  f.jerk = s.jerk;
  f.yaw = s.yaw;
  const FlatReference free = flatToReference(f, gravity);
  return flownInput(free.x, free.u, gravity, drag);
}

// The lqr limits, of which a transition uses only `fraction` of omega_max and c_max unless an end it
// joins needs more (a path flown at the limits); its speed within the faster of its ends' speeds,
// min_speed_limit and `speed_floor`, plus speed_margin.
FeasibilityLimits transitionLimits(const FlatState& from, const FlatState& to, const LqrParams& lqr,
                                   const TransitionParams& params, double fraction, double speed_floor) {
  const double faster = std::max({from.velocity.norm(), to.velocity.norm(), params.min_speed_limit, speed_floor});
  FeasibilityLimits limits = FeasibilityLimits::from(lqr, faster * (1.0 + params.speed_margin), 0.0);
  // Judged, like a path, on the inputs flown against the model's rotor drag (limits.drag).
  const Input a = inputsAt(from, lqr.gravity, limits.drag), b = inputsAt(to, lqr.gravity, limits.drag);
  constexpr double kEndSlack = 1.0 + 1e-9;  // an end exactly at the limit stays within it
  limits.omega_max = std::min(lqr.omega_max, kEndSlack * std::max({fraction * lqr.omega_max,
                                                                   bodyRate(a).norm(), bodyRate(b).norm()}));
  limits.c_max = std::min(lqr.c_max, kEndSlack * std::max({fraction * lqr.c_max, a[kThrust], b[kThrust]}));
  return limits;
}

// Whether every grid point of the transition is within the limits (checkFeasibility's verdict),
// stopping at the first that is not: most tries of a search fail, and nobody reads their report.
bool withinLimits(const Transition& transition, const FeasibilityLimits& limits, double gravity) {
  FeasibilityReport report;
  for (int i = 0; i <= kGridPoints; ++i) {
    accountGridPoint(report, transition, i, limits, gravity);
    judgeReport(report, limits);  // extremes only grow: once beyond a limit, the whole is
    if (!report.feasible()) return false;
  }
  return true;
}

// What a search is for: the shortest flyable transition and its report, or only whether one exists
// (the path check's stops from every sample: the stepping finds one, the bisection only shortens it).
enum class Want { kShortest, kExistence };

// The stepping-then-bisection search for the shortest flyable duration; `make(T)` is the
// transition of duration T. The plan's report is the full check of the transition found, or of
// the longest tried when none is (kShortest only).
template <class Make>
TransitionPlan search(const Make& make, const FeasibilityLimits& limits, const LqrParams& lqr,
                      const TransitionParams& params, Want want) {
  TransitionPlan plan;
  plan.limits = limits;
  // Too short asks for too much thrust or rate; too long, when the ends move, for too much speed:
  // the flyable durations are a window, stepped through finely enough not to jump over it.
  double low = 0.0, high = std::min(kFirstDuration, params.max_duration);
  plan.transition = make(high);
  while (!withinLimits(plan.transition, limits, lqr.gravity)) {
    if (high >= params.max_duration) {  // found stays false: the longest tried is reported
      if (want == Want::kShortest) plan.report = checkFeasibility(plan.transition, limits, lqr.gravity);
      return plan;
    }
    low = high;
    high = std::min(kDurationStep * high, params.max_duration);
    plan.transition = make(high);
  }
  plan.found = true;
  if (want == Want::kExistence) return plan;
  for (int i = 0; i < kBisections && low > 0.0; ++i) {
    const double middle = 0.5 * (low + high);
    const Transition trial = make(middle);
    if (withinLimits(trial, limits, lqr.gravity)) {
      high = middle;
      plan.transition = trial;
    } else {
      low = middle;
    }
  }
  plan.report = checkFeasibility(plan.transition, limits, lqr.gravity);
  return plan;
}

// Where a stop's limits are judged at its end: at rest where it starts, heading kept (its end
// position is free; only the speed and the inputs at rest matter to the limits).
FlatState restAt(const FlatState& from) { return {from.position, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), from.yaw}; }

// The searches in order of preference; the first that finds a transition is flown. Within
// gentle_fraction of omega_max and c_max, then input_fraction (the feedback keeps the most room),
// under the speed bound of the transition's ends. Where those find none: under the top speed of the
// path it joins or leaves (a stop from a slow sample where the path accelerates hard gains speed
// while its acceleration turns round: the paper's min-snap leaving a corner at 0.6 m/s and 3.5
// m/s^2), and, for an exit, last within the full limits the path itself was checked against (a stop
// from a sharp turn flown near them: the agile lemniscate at 9 m/s, 28 m/s^2 into the turn, needs 40
// of 45 m/s^2). A tier whose limits are an earlier one's is not searched again; none found: the
// widest's report.
template <class Make>
TransitionPlan preferredFirst(const Make& make, const FlatState& from, const FlatState& to, const LqrParams& lqr,
                              const TransitionParams& params, double path_speed, TransitionKind kind) {
  struct Tier {
    double fraction;
    double speed_floor;
  };
  const double gentle = std::min(params.gentle_fraction, params.input_fraction);
  const Tier tiers[] = {{gentle, 0.0}, {params.input_fraction, 0.0},  // the ends' speed
                        {gentle, path_speed}, {params.input_fraction, path_speed}, {1.0, path_speed}};
  const size_t searched = kind == TransitionKind::kExit ? std::size(tiers) : std::size(tiers) - 1;
  TransitionPlan plan;
  FeasibilityLimits tried[std::size(tiers)];
  int tried_count = 0;
  for (size_t i = 0; i < searched; ++i) {
    const Tier& tier = tiers[i];
    const FeasibilityLimits limits = transitionLimits(from, to, lqr, params, tier.fraction, tier.speed_floor);
    const auto same = [&](const FeasibilityLimits& l) {
      return l.omega_max == limits.omega_max && l.c_max == limits.c_max && l.v_max == limits.v_max;
    };
    if (std::any_of(tried, tried + tried_count, same)) continue;
    tried[tried_count++] = limits;
    plan = search(make, limits, lqr, params, Want::kShortest);
    if (plan.found) return plan;
  }
  return plan;
}

}  // namespace

TransitionPlan planTransition(const FlatState& from, const FlatState& to, const LqrParams& lqr,
                              const TransitionParams& params, double path_speed, TransitionKind kind) {
  return preferredFirst([&](double T) { return Transition::between(from, to, T); }, from, to, lqr, params, path_speed,
                        kind);
}

TransitionPlan planStop(const FlatState& from, const LqrParams& lqr, const TransitionParams& params,
                        double path_speed) {
  const FlatState rest = restAt(from);
  return preferredFirst([&](double T) { return Transition::stopping(from, T); }, from, rest, lqr, params, path_speed,
                        TransitionKind::kExit);
}

// Only the last tier's search: each tier's limits contain the ones before, and every search tries
// the same durations, so where an earlier tier finds a stop the last finds one too.
bool stopExists(const FlatState& from, const LqrParams& lqr, const TransitionParams& params, double path_speed,
                double& duration_hint) {
  const FlatState rest = restAt(from);
  const FeasibilityLimits widest = transitionLimits(from, rest, lqr, params, 1.0, path_speed);
  const auto make = [&](double T) { return Transition::stopping(from, T); };
  if (duration_hint > 0.0 && withinLimits(make(duration_hint), widest, lqr.gravity)) return true;
  const TransitionPlan plan = search(make, widest, lqr, params, Want::kExistence);
  if (plan.found) duration_hint = plan.transition.duration();
  return plan.found;
}

bool stopExists(const FlatState& from, const LqrParams& lqr, const TransitionParams& params, double path_speed) {
  double no_hint = 0.0;
  return stopExists(from, lqr, params, path_speed, no_hint);
}

bool closeEnough(const FlatState& from, const FlatState& to, const TransitionParams& params) {
  return (from.position - to.position).norm() <= params.position_tolerance &&
         (from.velocity - to.velocity).norm() <= params.velocity_tolerance &&
         (from.acceleration - to.acceleration).norm() <= params.acceleration_tolerance;
}

std::string describeTransition(const char* what, const TransitionPlan& plan) {
  const FeasibilityReport& r = plan.report;
  char text[256];
  if (plan.found) {
    std::snprintf(text, sizeof text, "%s %.3g s: thrust %.3g..%.3g m/s^2, max |omega| %.3g rad/s, max speed %.3g m/s",
                  what, plan.transition.duration(), r.min_thrust, r.max_thrust, r.max_body_rate, r.max_speed);
  } else {
    std::snprintf(text, sizeof text, "%s: none within %.3g s (at the longest: thrust %.3g..%.3g m/s^2, max |omega| %.3g rad/s, max speed %.3g > %.3g m/s)",
                  what, plan.transition.duration(), r.min_thrust, r.max_thrust, r.max_body_rate, r.max_speed,
                  plan.limits.v_max);
  }
  return text;
}

}  // namespace sdlqr::trajectory
