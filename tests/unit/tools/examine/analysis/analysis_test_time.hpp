#pragma once
// Seconds as a bus utime [us]; a header, so the files of one test binary (one translation unit) share it.

#include <cmath>
#include <cstdint>

namespace sdlqr::test {

inline int64_t micros(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e6)); }

}  // namespace sdlqr::test
