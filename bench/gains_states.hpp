#pragma once
// The linearization points of tests/fixtures/lqr_reference.yaml (hover, 60 deg tilt, yaw 180,
// 5 m/s, body rates up to 10 rad/s, thrust at 2 and 18 m/s^2, combinations), shared by the
// benchmarks and the SciPy comparison so that all time the same problems.

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sdlqr/math/types.hpp"

namespace sdlqr::bench {

struct GainsCase {
  std::string name;
  State x;
  Input u;
  double dt;
};

inline std::vector<GainsCase> loadGainsCases() {
  const YAML::Node root = YAML::LoadFile(std::string(SDLQR_SOURCE_DIR) + "/tests/fixtures/lqr_reference.yaml");
  std::vector<GainsCase> cases;
  for (const YAML::Node& c : root["cases"]) {
    GainsCase gc;
    gc.name = c["name"].as<std::string>();
    for (int i = 0; i < kStateDim; ++i) gc.x[i] = c["x"][i].as<double>();
    for (int i = 0; i < kInputDim; ++i) gc.u[i] = c["u"][i].as<double>();
    gc.dt = c["dt"].as<double>();
    cases.push_back(gc);
  }
  return cases;
}

}  // namespace sdlqr::bench
