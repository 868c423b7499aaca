#pragma once
// The directory of this binary's test data; a header, so its files (one translation unit) share it.

#include <string>

namespace sdlqr::compare::test {

inline const std::string kDir = SDLQR_SOURCE_DIR "/tests/unit/tools/offline/compare";

}  // namespace sdlqr::compare::test
