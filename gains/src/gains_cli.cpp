#include "sdlqr/gains/gains_cli.hpp"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sdlqr/math/solve_status.hpp"

namespace sdlqr::gains {

namespace {

std::vector<double> parseNumberList(const std::string& text, const std::string& option, size_t expected) {
  std::vector<double> values;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || errno != 0 || !std::isfinite(value)) {
      throw std::invalid_argument(option + ": expected " + std::to_string(expected) +
                                  " comma-separated finite numbers, got '" + item + "' in '" + text + "'");
    }
    values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() != expected) {
    throw std::invalid_argument(option + ": expected " + std::to_string(expected) + " numbers, got " +
                                std::to_string(values.size()));
  }
  return values;
}

// A non-finite number is written as null (nlohmann-json's dump does so).
template <typename Derived>
nlohmann::ordered_json array(const Eigen::MatrixBase<Derived>& v) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(static_cast<double>(v(i)));
  return out;
}

}  // namespace

State parseStateList(const std::string& text, const std::string& option) {
  const std::vector<double> values = parseNumberList(text, option, kStateDim);
  const State x = Eigen::Map<const State>(values.data());
  if (orientation(x).norm() < 1e-9) throw std::invalid_argument(option + ": the quaternion qw,qx,qy,qz is zero");
  return x;
}

Input parseInputList(const std::string& text, const std::string& option) {
  const std::vector<double> values = parseNumberList(text, option, kInputDim);
  return Eigen::Map<const Input>(values.data());
}

std::string formatGainsJson(const State& x_lin, const Input& u_lin, const LqrParams& params, const LqrResult& result,
                            double solve_us) {
  nlohmann::ordered_json K = nlohmann::ordered_json::array();
  for (int row = 0; row < kInputDim; ++row) K.push_back(array(result.K.row(row)));
  nlohmann::ordered_json json;
  json["status"] = toString(result.status);
  if (result.status != SolveStatus::kOk) json["reason"] = std::string(result.reason);
  json["method"] = toString(params.method);
  json["K"] = std::move(K);
  json["dt"] = params.dt;
  json["iterations"] = result.iterations;
  json["solve_us"] = solve_us;
  json["residual"] = result.residual;
  json["x_lin"] = array(x_lin);
  json["u_lin"] = array(u_lin);
  return json.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

void addOnceOptions(ArgParser& parser, OnceOptions* o) {
  parser.addFlag("--once", &o->once, "solve once at --state/--input, print one JSON object and exit\n"
                 "                          (without it: solve at 10 Hz on the bus and publish GAINS)");
  parser.addOption("--state", &o->state_text, "P3,Q4,V3", "linearization state px,py,pz,qw,qx,qy,qz,vx,vy,vz");
  parser.addOption("--input", &o->input_text, "W3,C", "linearization input wx,wy,wz,c (rad/s, m/s^2)");
  parser.addOption("--method", &o->method_text, "NAME", "tangent or iterative (default: lqr.method of --config)");
}

const char* const kOnceEpilog =
    "example: sdlqr-gains --once --state 0,0,1,1,0,0,0,0,0,0 --input 0,0,0,9.81\n"
    "output:  {\"status\", \"method\", \"K\" (4x10, u = u0 + K (x - x0)), \"dt\", \"iterations\",\n"
    "          \"solve_us\", \"residual\", \"x_lin\" (quaternion normalized), \"u_lin\"}\n"
    "exit codes: 0 solved, 1 solver failure (JSON still printed), 2 bad input or config";

LqrParams lqrParamsWithMethod(const ConfigReader& root, const OnceOptions& options) {
  LqrParams params = LqrParams::loadWithVehicle(root);
  if (!options.method_text.empty() && !parseLqrMethod(options.method_text, params.method)) {
    throw std::invalid_argument("--method: expected tangent or iterative, got '" + options.method_text + "'");
  }
  return params;
}

void requireBusMode(const OnceOptions& options) {
  if (!options.state_text.empty() || !options.input_text.empty()) {
    throw std::invalid_argument("--state and --input need --once");
  }
}

int solveOnce(const OnceOptions& options, const LqrParams& params, std::ostream& out) {
  if (options.state_text.empty() || options.input_text.empty()) {
    throw std::invalid_argument("--once needs --state and --input");
  }
  State x = parseStateList(options.state_text, "--state");
  const Input u = parseInputList(options.input_text, "--input");
  const auto start = std::chrono::steady_clock::now();
  const LqrResult result = solveLqr(x, u, params);
  const auto stop = std::chrono::steady_clock::now();
  orientation(x).normalize();
  const double solve_us = std::chrono::duration<double, std::micro>(stop - start).count();
  out << formatGainsJson(x, u, params, result, solve_us) << "\n";
  return result.status == SolveStatus::kOk ? 0 : 1;
}

}  // namespace sdlqr::gains
