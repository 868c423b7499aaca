// sdlqr-gains: the state-dependent LQR gain solver. For now only its one-shot mode: solve once
// at the given linearization point and print one JSON object.

#include <chrono>
#include <iostream>
#include <stdexcept>

#include "sdlqr/common/cli.hpp"
#include "sdlqr/common/config.hpp"
#include "sdlqr/common/lqr.hpp"
#include "sdlqr/common/params.hpp"
#include "sdlqr/controller/gains_cli.hpp"

int main(int argc, char** argv) {
  using namespace sdlqr;
  return runMain("sdlqr-gains", [&] {
    bool once = false;
    std::string state_text, input_text, method_text;
    ProcessOptions options;
    ArgParser parser("sdlqr-gains", "State-dependent LQR gain solver (paper §II-C, II-D).");
    parser.addFlag("--once", &once, "solve once at --state/--input, print one JSON object and exit");
    parser.addOption("--state", &state_text, "P3,Q4,V3", "linearization state px,py,pz,qw,qx,qy,qz,vx,vy,vz");
    parser.addOption("--input", &input_text, "W3,C", "linearization input wx,wy,wz,c (rad/s, m/s^2)");
    parser.addOption("--method", &method_text, "NAME", "tangent or iterative (default: lqr.method of --config)");
    addProcessOptions(parser, &options);
    parser.setEpilog(
        "example: sdlqr-gains --once --state 0,0,1,1,0,0,0,0,0,0 --input 0,0,0,9.81\n"
        "output:  {\"status\", \"method\", \"K\" (4x10, u = u0 + K (x - x0)), \"dt\", \"iterations\",\n"
        "          \"solve_us\", \"residual\", \"x_lin\" (quaternion normalized), \"u_lin\"}\n"
        "exit codes: 0 solved, 1 solver failure (JSON still printed), 2 bad input or config");
    parser.parseOrExit(argc, argv);
    if (!once) {
      std::cerr << "sdlqr-gains: the 10 Hz bus mode is not built yet; use --once\n";
      return 2;
    }
    if (state_text.empty() || input_text.empty()) throw std::invalid_argument("--once needs --state and --input");

    LqrParams params;
    if (!options.config_path.empty()) {
      params = LqrParams::load(ConfigReader(loadYamlFile(options.config_path), "").child("lqr"));
    }
    if (!method_text.empty() && !parseLqrMethod(method_text, params.method)) {
      throw std::invalid_argument("--method: expected tangent or iterative, got '" + method_text + "'");
    }
    State x = controller::parseStateList(state_text, "--state");
    const Input u = controller::parseInputList(input_text, "--input");

    const auto start = std::chrono::steady_clock::now();
    const LqrResult result = solveLqr(x, u, params);
    const auto stop = std::chrono::steady_clock::now();
    orientation(x).normalize();
    const double solve_us = std::chrono::duration<double, std::micro>(stop - start).count();
    std::cout << controller::formatGainsJson(x, u, params, result, solve_us) << "\n";
    return result.status == SolveStatus::kOk ? 0 : 1;
  });
}
