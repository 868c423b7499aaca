#include "sdlqr/math/lqr_params.hpp"

#include <string>
#include <utility>
#include <vector>

#include "sdlqr/math/in_flight.hpp"
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

namespace {

constexpr ControlLaw kLaws[] = {ControlLaw::kSdlqr, ControlLaw::kHoverLqr, ControlLaw::kGeometric,
                                ControlLaw::kSdlqrIntegral, ControlLaw::kSdlqrActuator, ControlLaw::kSdlqrAdaptive};

}  // namespace

const char* toString(ControlLaw law) {
  switch (law) {
    case ControlLaw::kSdlqr: return "sdlqr";
    case ControlLaw::kHoverLqr: return "hover_lqr";
    case ControlLaw::kGeometric: return "geometric";
    case ControlLaw::kSdlqrIntegral: return "sdlqr_integral";
    case ControlLaw::kSdlqrActuator: return "sdlqr_actuator";
    case ControlLaw::kSdlqrAdaptive: return "sdlqr_adaptive";
  }
  return "unknown";
}

bool parseControlLaw(const std::string& text, ControlLaw& out) {
  for (ControlLaw law : kLaws) {
    if (text == toString(law)) {
      out = law;
      return true;
    }
  }
  return false;
}

std::string controlLawNames() {
  std::string names;
  for (ControlLaw law : kLaws) names += (names.empty() ? "" : ", ") + std::string(toString(law));
  return names;
}

const std::vector<ControlLaw>& controlLaws() {
  static const std::vector<ControlLaw> laws(std::begin(kLaws), std::end(kLaws));
  return laws;
}

bool isControlLaw(ControlLaw law) {
  for (ControlLaw known : kLaws) {
    if (law == known) return true;
  }
  return false;
}

LqrParams::LqrParams() { declaration().setDefaults(*this); }

LqrParams LqrParams::loadWithVehicle(const ConfigReader& root) {
  LqrParams params = load(root.child("lqr"));
  params.vehicle_rotor_drag = VehicleParams::load(root.child("vehicle")).rotor_drag;
  return params;
}

RotorDrag LqrParams::rotorDrag() const {
  RotorDrag drag;
  if (model_rotor_drag) drag.coefficients = vehicle_rotor_drag;
  drag.gravity = gravity;
  return drag;
}

const ParamTable<LqrParams>& LqrParams::declaration() {
  static const ParamTable<LqrParams> table = [] {
    using P = LqrParams;
    ParamTable<P> t("weights and limits of the state-dependent LQR (paper §III-B)");
    t.list("q_diag", &P::q_diag, {100, 100, 100, 1, 1, 1, 1, 10, 10, 10}, "-", Range::atLeast(0.0),
           "state cost: p (m), q (-), v (m/s); >= 0 keeps Q positive semidefinite")
        .inFlight(ParamsUpdate::kWeights);
    t.list("r_diag", &P::r_diag, {1, 5, 5, 0.1}, "-", Range::above(0.0),
           "input cost: omega x, y, z (rad/s), thrust (m/s^2); > 0 keeps R positive definite")
        .inFlight(ParamsUpdate::kWeights);
    t.number("dt", &P::dt, 0.01, "s", Range::openClosed(0.0, 1.0), "LQR discretization step = control period (100 Hz)");
    t.number("omega_max", &P::omega_max, 2.0, "rad/s", Range::above(0.0),
             "||omega_des|| limit (at most validation.max_body_rate)")
        .inFlight(ParamsUpdate::kLimits);
    t.number("c_min", &P::c_min, 2.0, "m/s^2", Range::atLeast(0.0), "thrust lower limit").inFlight(ParamsUpdate::kLimits);
    t.number("c_max", &P::c_max, 18.0, "m/s^2", Range::finite(), "thrust upper limit").inFlight(ParamsUpdate::kLimits);
    t.number("gravity", &P::gravity, kDefaultGravity, "m/s^2", Range::above(0.0), "gravity of the model");
    t.choice("method", &P::method, LqrMethod::kTangent,
             {{toString(LqrMethod::kTangent), LqrMethod::kTangent}, {toString(LqrMethod::kIterative), LqrMethod::kIterative}},
             "tangent (9-state doubling) or iterative (paper, 10-state)");
    t.number("tolerance", &P::tolerance, 1e-12, "-", Range::open(0.0, 1.0), "relative convergence tolerance");
    t.integer("max_iterations", &P::max_iterations, 0, "-", Range::atLeast(0),
              "iteration cap; 0: the method's own (64 doublings, 100000 iterations)");
    std::vector<std::pair<std::string, ControlLaw>> laws;
    for (ControlLaw law : kLaws) laws.emplace_back(toString(law), law);
    t.choice("law", &P::law, ControlLaw::kSdlqr, laws,
             "controller: sdlqr (paper), hover_lqr (K solved once at hover), geometric (cascaded SE(3)), "
             "sdlqr_integral (ext. I), sdlqr_actuator (ext. II), sdlqr_adaptive (thrust gain estimated online); PARAMS law "
             "switches it in flight")
        .inFlight(ParamsUpdate::kLaw);
    // > 0: an integrator the cost does not see has no stabilizing Riccati solution.
    t.list("q_integral", &P::q_integral, {4, 4, 4}, "-", Range::above(0.0),
           "sdlqr_integral: cost on the integral of p - p_ref (m s)");
    t.number("q_thrust", &P::q_thrust, 0.01, "-", Range::atLeast(0.0),
             "sdlqr_actuator: cost on the thrust state's deviation (m/s^2)");
    // The plant's lag is vehicle.motor_time_constant; this is what the controller's model assumes.
    t.number("thrust_time_constant", &P::thrust_time_constant, 0.03, "s", Range::openClosed(0.0, 1.0),
             "sdlqr_actuator: the model's first-order collective-thrust lag (vehicle: motor_time_constant)");
    t.flag("model_rotor_drag", &P::model_rotor_drag, false,
           "the model includes vehicle.rotor_drag: the feed-forward thrust and attitude that fly the reference "
           "against it, and its terms in the linearization (off: the paper's drag-free model)");
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
  // The update is one change: a bad part the others' owners would refuse refuses it all here too.
  if (!checkInFlight(update).ok()) return ParamsOutcome::kInvalid;
  LqrParams next = params_;
  applyInFlight(LqrParams::declaration(), next, update);
  if (!next.valid()) return ParamsOutcome::kInvalid;
  params_ = next;
  utime_ = update.utime;
  seq_ = update.seq;
  return ParamsOutcome::kApplied;
}

}  // namespace sdlqr
