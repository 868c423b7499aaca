#include "sdlqr/gains/gains_cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <vector>

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

std::string number(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  return buffer;
}

template <typename Derived>
std::string array(const Eigen::MatrixBase<Derived>& v) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + number(v(i));
  return out + "]";
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

const char* toString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kOk: return "ok";
    case SolveStatus::kNotConverged: return "not_converged";
    case SolveStatus::kNumericalFailure: return "numerical_failure";
    case SolveStatus::kInvalidInput: return "invalid_input";
  }
  return "unknown";
}

std::string formatGainsJson(const State& x_lin, const Input& u_lin, const LqrParams& params, const LqrResult& result,
                            double solve_us) {
  std::string K = "[";
  for (int row = 0; row < kInputDim; ++row) K += (row ? ", " : "") + array(result.K.row(row));
  K += "]";
  std::string json = "{";
  json += "\"status\": \"" + std::string(toString(result.status)) + "\"";
  if (result.status != SolveStatus::kOk) json += ", \"reason\": \"" + std::string(result.reason) + "\"";
  json += ", \"method\": \"" + std::string(toString(params.method)) + "\"";
  json += ", \"K\": " + K;
  json += ", \"dt\": " + number(params.dt);
  json += ", \"iterations\": " + std::to_string(result.iterations);
  json += ", \"solve_us\": " + number(solve_us);
  json += ", \"residual\": " + number(result.residual);
  json += ", \"x_lin\": " + array(x_lin);
  json += ", \"u_lin\": " + array(u_lin);
  return json + "}";
}

}  // namespace sdlqr::gains
