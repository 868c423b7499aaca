#pragma once
// Weights and limits of the state-dependent LQR (paper §III-B defaults), loaded from the
// `lqr:` section of a vehicle file and changeable at run time through PARAMS (RuntimeLqrParams).

#include <cstdint>
#include <string>
#include <vector>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/math/types.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr {

enum class LqrMethod { kTangent, kIterative };

// The control laws of the controller process (params_t LAW_*): the name in a vehicle file or a
// scenario, and back. parseControlLaw returns false for an unknown name.
const char* toString(ControlLaw law);
bool parseControlLaw(const std::string& text, ControlLaw& out);
// The names accepted, "sdlqr, hover_lqr, ...", for error messages.
std::string controlLawNames();
// Every law, in the order of their names.
const std::vector<ControlLaw>& controlLaws();
// True for a value of the enum (a PARAMS law field is an int8 from the wire).
bool isControlLaw(ControlLaw law);

// Each member is declared once (key, unit, default, range, help, whether PARAMS changes it in
// flight) in common/math/params/lqr_params.yaml (rules and the rows built in code: lqr_params.cpp);
// the default constructor takes the defaults from there.
struct LqrParams : DeclaredParams<LqrParams> {
  State q_diag;
  Input r_diag;
  double dt;
  double omega_max;
  double c_min;
  double c_max;
  double gravity;
  LqrMethod method;
  double tolerance;
  int max_iterations;
  // The law the controller runs and the model the gain solver solves for it (lqr_extensions.hpp).
  ControlLaw law;
  Vec3 q_integral;              // cost on the integral of the position error (sdlqr_integral) [1/(m s)^2]
  double q_thrust;              // cost on the thrust state's deviation (sdlqr_actuator) [1/(m/s^2)^2]
  double thrust_time_constant;  // [s] the model's collective-thrust lag (sdlqr_actuator)
  bool model_rotor_drag;        // the model's feed-forward and linearization include vehicle.rotor_drag
  // Not a key: vehicle.rotor_drag, copied by loadWithVehicle() (used only when model_rotor_drag).
  Vec3 vehicle_rotor_drag = Vec3::Zero();

  LqrParams();
  static const ParamTable<LqrParams>& declaration();
  // The `lqr` section of a vehicle file's root, with the airframe's rotor drag from its `vehicle`.
  static LqrParams loadWithVehicle(const ConfigReader& root);
  // The rotor drag of the controllers' model: the vehicle's when model_rotor_drag, else none.
  RotorDrag rotorDrag() const;
};

const char* toString(LqrMethod method);
bool parseLqrMethod(const std::string& text, LqrMethod& out);

// What became of a PARAMS update offered to RuntimeLqrParams::apply().
enum class ParamsOutcome {
  kApplied,   // adopted (also an update whose bits are all other components')
  kNotNewer,  // not after the last applied update in (utime, seq) order: a re-send or a replay
  kInvalid,   // an unknown field bit, or values the LQR parameters refuse
};
const char* toString(ParamsOutcome outcome);

// The LQR parameters of a running gain solver or controller: those loaded, changed by PARAMS under
// one rule for both (and for their replay):
//   - an update not after the last applied one in (utime, seq) order is kNotNewer;
//   - an update checkInFlight() refuses is kInvalid (any part of it: the mass and the tracking
//     mode belong to the bodyrate loop and the reference generator, but the update is one change);
//   - the keys LqrParams declares in flight take the update's values for the groups it names
//     (FIELD_WEIGHTS q_diag and r_diag, FIELD_LIMITS omega_max, c_min and c_max, FIELD_LAW law);
//   - the result must pass LqrParams::invalidReason(), else kInvalid;
//   - anything but kApplied leaves everything unchanged; kApplied moves seq() to the update's.
class RuntimeLqrParams {
 public:
  explicit RuntimeLqrParams(const LqrParams& loaded) : params_(loaded) {}

  ParamsOutcome apply(const ParamsUpdate& update);

  const LqrParams& params() const { return params_; }
  // seq of the last applied update (the params_seq GAINS and REFERENCE name), -1 before any.
  int64_t seq() const { return seq_; }

 private:
  LqrParams params_;
  int64_t utime_ = -1;
  int64_t seq_ = -1;
};

}  // namespace sdlqr
