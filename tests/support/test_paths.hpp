#pragma once
// Where the tests find the repository (SDLQR_SOURCE_DIR, set for every test binary by
// tests/CMakeLists.txt), and where they write scratch files. A header, so the files of one test
// binary (one translation unit) share it.

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

namespace sdlqr::test {

inline const std::string kSourceDir = SDLQR_SOURCE_DIR;

// A scratch file of this process alone: ctest runs each test of a binary as its own process, two
// at a time, so a fixed name in the shared temporary folder is overwritten by the test beside it
// (CI: one test read the output another had just written over). The process id and a per-process
// count make each call's path its own; `name` keeps it readable.
inline std::string tempPath(const std::string& name) {
  static int count = 0;
  return ::testing::TempDir() + "sdlqr_" + std::to_string(::getpid()) + "_" + std::to_string(count++) + "_" + name;
}

}  // namespace sdlqr::test
