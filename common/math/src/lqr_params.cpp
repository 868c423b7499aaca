#include "sdlqr/math/lqr_params.hpp"

#include <string>
#include <utility>
#include <vector>

#include "sdlqr/math/in_flight.hpp"
#include "sdlqr/math/vehicle.hpp"

#include "lqr_params_rows.hpp"

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

namespace {

// The rows of params/lqr_params.yaml built in code: their words are toString's.
void addMethodRow(ParamTable<LqrParams>& t) {
  t.choice("method", &LqrParams::method, LqrMethod::kTangent,
           {{toString(LqrMethod::kTangent), LqrMethod::kTangent}, {toString(LqrMethod::kIterative), LqrMethod::kIterative}},
           "tangent (9-state doubling) or iterative (paper, 10-state)");
}

void addLawRow(ParamTable<LqrParams>& t) {
  std::vector<std::pair<std::string, ControlLaw>> laws;
  for (ControlLaw law : kLaws) laws.emplace_back(toString(law), law);
  t.choice("law", &LqrParams::law, ControlLaw::kSdlqr, laws,
           "controller: sdlqr (paper), hover_lqr (K solved once at hover), geometric (cascaded SE(3)), "
           "sdlqr_integral (ext. I), sdlqr_actuator (ext. II), sdlqr_adaptive (thrust gain estimated online); PARAMS law "
           "switches it in flight")
      .inFlight(ParamsUpdate::kLaw);
}

}  // namespace

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
    ParamTable<P> t = lqrParamsRows();
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
