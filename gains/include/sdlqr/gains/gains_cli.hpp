#pragma once
// The one-shot mode of sdlqr-gains: parse a linearization point from the command line, and
// format one solve as a single JSON object. Kept out of main so that it is testable.

#include <ostream>
#include <string>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::gains {

// "px,py,pz,qw,qx,qy,qz,vx,vy,vz": exactly 10 finite numbers and a non-zero quaternion.
// Throws std::invalid_argument with a one-line message naming `option`.
State parseStateList(const std::string& text, const std::string& option);
// "wx,wy,wz,c": exactly 4 finite numbers.
Input parseInputList(const std::string& text, const std::string& option);

// {"status", "method", "K" (4 rows of 10), "dt", "iterations", "solve_us", "residual", "x_lin",
// "u_lin"}; doubles with 17 significant digits (they round-trip), non-finite numbers as null.
std::string formatGainsJson(const State& x_lin, const Input& u_lin, const LqrParams& params, const LqrResult& result,
                            double solve_us);

// The one-shot options (--once, --state, --input, --method) of the command line.
struct OnceOptions {
  bool once = false;
  std::string state_text, input_text, method_text;
};
void addOnceOptions(ArgParser& parser, OnceOptions* options);
extern const char* const kOnceEpilog;
// lqr: of the vehicle file whose root is given (with vehicle.rotor_drag for its model), with
// --method if given (std::invalid_argument on a bad name).
LqrParams lqrParamsWithMethod(const ConfigReader& root, const OnceOptions& options);
// --state and --input belong to --once (std::invalid_argument otherwise).
void requireBusMode(const OnceOptions& options);
// Solves at --state/--input, prints the JSON line; returns the exit code (0 solved, 1 failed).
int solveOnce(const OnceOptions& options, const LqrParams& params, std::ostream& out);

}  // namespace sdlqr::gains
