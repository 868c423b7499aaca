#pragma once
// The name a report gives a solve's outcome (GAINS status, gains_t.lcm STATUS_*).

#include "sdlqr/messages/messages.hpp"

namespace sdlqr {

inline const char* toString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kOk: return "ok";
    case SolveStatus::kNotConverged: return "not_converged";
    case SolveStatus::kNumericalFailure: return "numerical_failure";
    case SolveStatus::kInvalidInput: return "invalid_input";
  }
  return "unknown";
}

}  // namespace sdlqr
