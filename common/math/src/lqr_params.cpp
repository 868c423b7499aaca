#include "sdlqr/math/lqr_params.hpp"

#include <cmath>
#include <string>

namespace sdlqr {

const char* toString(LqrMethod method) { return method == LqrMethod::kTangent ? "tangent" : "iterative"; }

bool parseLqrMethod(const std::string& text, LqrMethod& out) {
  if (text == "tangent") {
    out = LqrMethod::kTangent;
    return true;
  }
  if (text == "iterative") {
    out = LqrMethod::kIterative;
    return true;
  }
  return false;
}

LqrParams LqrParams::load(const ConfigReader& lqr) {
  lqr.allowOnly({"q_diag", "r_diag", "dt", "omega_max", "c_min", "c_max", "gravity", "method", "tolerance",
                 "max_iterations"});
  LqrParams p;
  lqr.read("q_diag", p.q_diag);
  lqr.read("r_diag", p.r_diag);
  lqr.read("dt", p.dt);
  lqr.read("omega_max", p.omega_max);
  lqr.read("c_min", p.c_min);
  lqr.read("c_max", p.c_max);
  lqr.read("gravity", p.gravity);
  std::string method = toString(p.method);
  lqr.read("method", method);
  if (!parseLqrMethod(method, p.method)) throw ConfigError(lqr.keyPath("method"), "expected tangent or iterative");
  lqr.read("tolerance", p.tolerance);
  lqr.read("max_iterations", p.max_iterations);
  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(lqr.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string LqrParams::invalidReason() const {
  // Called by every solveLqr: no stream is built unless there is a message to format (an
  // ostringstream per call cost about 0.2 us and pulled the locale code into every cold solve).
  for (int i = 0; i < kStateDim; ++i) {
    if (!std::isfinite(q_diag[i]) || q_diag[i] < 0.0) {
      return "q_diag[" + std::to_string(i) + "]: must be finite and >= 0 (Q positive semidefinite)";
    }
  }
  for (int i = 0; i < kInputDim; ++i) {
    if (!std::isfinite(r_diag[i]) || r_diag[i] <= 0.0) {
      return "r_diag[" + std::to_string(i) + "]: must be finite and > 0 (R positive definite)";
    }
  }
  if (!std::isfinite(dt) || dt <= 0.0 || dt > 1.0) return "dt: must be in (0, 1] s";
  if (!std::isfinite(omega_max) || omega_max <= 0.0) return "omega_max: must be > 0";
  if (!std::isfinite(c_min) || c_min < 0.0) return "c_min: must be finite and >= 0";
  if (!std::isfinite(c_max) || c_max <= c_min) return "c_max: must be finite and > c_min";
  if (!std::isfinite(gravity) || gravity <= 0.0) return "gravity: must be > 0";
  if (!std::isfinite(tolerance) || tolerance <= 0.0 || tolerance >= 1.0) return "tolerance: must be in (0, 1)";
  if (max_iterations < 0) return "max_iterations: must be >= 0";
  return {};
}

}  // namespace sdlqr
