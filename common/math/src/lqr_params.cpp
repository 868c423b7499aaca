#include "sdlqr/math/lqr_params.hpp"

#include <string>

#include "sdlqr/math/vehicle.hpp"

namespace sdlqr {

const char* toString(LqrMethod method) { return method == LqrMethod::kTangent ? "tangent" : "iterative"; }

bool parseLqrMethod(const std::string& text, LqrMethod& out) {
  for (LqrMethod method : {LqrMethod::kTangent, LqrMethod::kIterative}) {
    if (text == toString(method)) {
      out = method;
      return true;
    }
  }
  return false;
}

LqrParams::LqrParams() { declaration().setDefaults(*this); }

const ParamTable<LqrParams>& LqrParams::declaration() {
  static const ParamTable<LqrParams> table = [] {
    using P = LqrParams;
    ParamTable<P> t("weights and limits of the state-dependent LQR (paper §III-B)");
    t.list("q_diag", &P::q_diag, {100, 100, 100, 1, 1, 1, 1, 10, 10, 10}, "-", Range::atLeast(0.0),
           "state cost: p (m), q (-), v (m/s); >= 0 keeps Q positive semidefinite");
    t.list("r_diag", &P::r_diag, {1, 5, 5, 0.1}, "-", Range::above(0.0),
           "input cost: omega x, y, z (rad/s), thrust (m/s^2); > 0 keeps R positive definite");
    t.number("dt", &P::dt, 0.01, "s", Range::openClosed(0.0, 1.0), "LQR discretization step = control period (100 Hz)");
    t.number("omega_max", &P::omega_max, 2.0, "rad/s", Range::above(0.0),
             "||omega_des|| limit (at most validation.max_body_rate)");
    t.number("c_min", &P::c_min, 2.0, "m/s^2", Range::atLeast(0.0), "thrust lower limit");
    t.number("c_max", &P::c_max, 18.0, "m/s^2", Range::finite(), "thrust upper limit");
    t.number("gravity", &P::gravity, kDefaultGravity, "m/s^2", Range::above(0.0), "gravity of the model");
    t.choice("method", &P::method, LqrMethod::kTangent,
             {{toString(LqrMethod::kTangent), LqrMethod::kTangent}, {toString(LqrMethod::kIterative), LqrMethod::kIterative}},
             "tangent (9-state doubling) or iterative (paper, 10-state)");
    t.number("tolerance", &P::tolerance, 1e-12, "-", Range::open(0.0, 1.0), "relative convergence tolerance");
    t.integer("max_iterations", &P::max_iterations, 0, "-", Range::atLeast(0),
              "iteration cap; 0: the method's own (64 doublings, 100000 iterations)");
    t.check("c_max", [](const P& p) { return p.c_max > p.c_min; }, "must be > c_min");
    return t;
  }();
  return table;
}

const char* toString(ParamsOutcome outcome) {
  switch (outcome) {
    case ParamsOutcome::kApplied: return "applied";
    case ParamsOutcome::kNotNewer: return "not_newer";
    case ParamsOutcome::kInvalid: return "invalid";
  }
  return "unknown";
}

ParamsOutcome RuntimeLqrParams::apply(const ParamsUpdate& update) {
  if (update.utime < utime_ || (update.utime == utime_ && update.seq <= seq_)) return ParamsOutcome::kNotNewer;
  constexpr int32_t kKnown = ParamsUpdate::kWeights | ParamsUpdate::kLimits | ParamsUpdate::kMass | ParamsUpdate::kTracking;
  if ((update.field_mask & ~kKnown) != 0) return ParamsOutcome::kInvalid;
  // The update is one change: a bad part the others' owners would refuse refuses it all here too.
  if ((update.field_mask & ParamsUpdate::kMass) && !kMassRange.contains(update.mass)) return ParamsOutcome::kInvalid;
  if ((update.field_mask & ParamsUpdate::kTracking) && update.tracking != ReferenceMode::kSpatial &&
      update.tracking != ReferenceMode::kTemporal) {
    return ParamsOutcome::kInvalid;
  }
  LqrParams next = params_;
  if (update.field_mask & ParamsUpdate::kWeights) {
    next.q_diag = update.q_diag;
    next.r_diag = update.r_diag;
  }
  if (update.field_mask & ParamsUpdate::kLimits) {
    next.omega_max = update.omega_max;
    next.c_min = update.c_min;
    next.c_max = update.c_max;
  }
  if (!next.valid()) return ParamsOutcome::kInvalid;
  params_ = next;
  utime_ = update.utime;
  seq_ = update.seq;
  return ParamsOutcome::kApplied;
}

}  // namespace sdlqr
