#pragma once
// A scenario of config/scenarios by name; a header, so the files of one test binary (one translation unit) share it.

#include <string>
#include "sdlqr/mission/scenario.hpp"
#include "test_paths.hpp"

namespace sdlqr::test {

inline mission::Scenario scenarioNamed(const std::string& name) {
  return mission::Scenario::load(kSourceDir + "/config/scenarios/" + name + ".yaml");
}

}  // namespace sdlqr::test
