#pragma once
// A test whose prerequisite (a tool, a kernel feature) is missing: skipped, and said so, on a
// developer's machine; failed in CI (CI=true), where `./sdlqr setup` has installed every
// prerequisite and the tests run as root: a skip there would pass a test that never ran.
// Shell tests use tests/support/prerequisite.sh, which does the same.

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

namespace sdlqr::testing {

inline bool runningInCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::strcmp(ci, "true") == 0;
}

}  // namespace sdlqr::testing

// In a void function or test body: returns from it when the prerequisite is missing.
#define SDLQR_REQUIRE_PREREQUISITE(available, what)                                                   \
  do {                                                                                                \
    if (!(available)) {                                                                               \
      if (::sdlqr::testing::runningInCi()) FAIL() << "missing prerequisite with CI=true: " << what;   \
      GTEST_SKIP() << "missing prerequisite (fails with CI=true): " << what;                         \
    }                                                                                                 \
  } while (0)
