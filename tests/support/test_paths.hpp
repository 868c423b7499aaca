#pragma once
// Where the tests find the repository (SDLQR_SOURCE_DIR, set for every test binary by
// tests/CMakeLists.txt). A header, so the files of one test binary (one translation unit) share it.

#include <string>

namespace sdlqr::test {

inline const std::string kSourceDir = SDLQR_SOURCE_DIR;

}  // namespace sdlqr::test
