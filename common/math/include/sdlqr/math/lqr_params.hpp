#pragma once
// Weights and limits of the state-dependent LQR (paper §III-B defaults), loaded from the
// `lqr:` section of a vehicle file and changeable at run time through PARAMS.

#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr {

enum class LqrMethod { kTangent, kIterative };

struct LqrParams {
  // Q = diag(100,100,100, 1,1,1,1, 10,10,10), R = diag(1,5,5,0.1) as flown in the paper.
  State q_diag = (State() << 100, 100, 100, 1, 1, 1, 1, 10, 10, 10).finished();
  Input r_diag = (Input() << 1, 5, 5, 0.1).finished();
  double dt = 0.01;              // [s] discretization step: the 100 Hz control period
  double omega_max = 2.0;        // [rad/s] bound on ||omega_des||
  double c_min = 2.0;            // [m/s^2] lower thrust bound
  double c_max = 18.0;           // [m/s^2] upper thrust bound
  double gravity = kDefaultGravity;  // [m/s^2]
  LqrMethod method = LqrMethod::kTangent;
  double tolerance = 1e-12;      // relative convergence tolerance of the chosen method
  int max_iterations = 0;        // 0: the method's own default (64 doublings, 100000 iterations)

  // Reads the given `lqr` mapping; throws ConfigError naming the key on a wrong type or value.
  static LqrParams load(const ConfigReader& lqr);
  // Empty when valid, else "key: reason" for the first violation found.
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

const char* toString(LqrMethod method);
bool parseLqrMethod(const std::string& text, LqrMethod& out);

}  // namespace sdlqr
