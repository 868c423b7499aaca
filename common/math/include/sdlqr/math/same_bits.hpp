#pragma once
// Arithmetic that returns exactly the bits of a C library call it stands for, without the call:
// the 1 kHz loops make these calls often enough that the call itself (and glibc's save and
// restore of the rounding mode) shows in a flight's CPU time. Where the shortcut cannot prove
// the result equal, it makes the library call.

#include <cmath>
#include <cstdint>
#include <cstring>

namespace sdlqr {

// std::llround(x) (nearest, halves away from zero) for every finite |x| < 2^52, the call
// beyond. Truncation to an integer and x minus it are exact in that range.
inline int64_t roundToInt64(double x) {
  constexpr double kExactLimit = 0x1p52;
  if (!(std::abs(x) < kExactLimit)) return static_cast<int64_t>(std::llround(x));
  const int64_t truncated = static_cast<int64_t>(x);
  const double fraction = x - static_cast<double>(truncated);
  if (fraction >= 0.5) return truncated + 1;
  if (fraction <= -0.5) return truncated - 1;
  return truncated;
}

// base * base - RN(base * base), exactly (Dekker's product; an FMA where the target has one). For
// |base| in [2^-450, 2^450].
inline double squareResidual(double base, double square) {
#ifdef __FMA__
  return std::fma(base, base, -square);
#else
  constexpr double kSplitter = 0x1p27 + 1.0;
  const double scaled = kSplitter * base;
  const double high = scaled - (scaled - base);
  const double low = base - high;
  return ((high * high - square) + 2.0 * high * low) + low * low;
#endif
}

// std::pow(base, exponent), with exponent 2 as base * base where that is provably what glibc's
// pow (2.28 on: worst-case error 0.54 ulp, its source says) returns: base^2 lies within 0.4 ulp of
// base * base, so both neighbours are at least 0.6 ulp away. Squares at the edge of their binade
// (mantissa all zeros or all ones, where a neighbour's ulp differs) take the call.
inline double powSameBits(double base, double exponent) {
  // What the compiler knows of the exponent must not reach the call: it folds pow(x, 2.0) into x * x.
  const auto call = [base](volatile double hidden_exponent) { return std::pow(base, hidden_exponent); };
  if (exponent != 2.0) return call(exponent);
  const double square = base * base;
  if (!(square >= 0x1p-900 && square <= 0x1p900)) return call(exponent);
  uint64_t bits;
  std::memcpy(&bits, &square, sizeof bits);
  constexpr uint64_t kMantissa = (uint64_t{1} << 52) - 1;
  if ((bits & kMantissa) == 0 || (bits & kMantissa) == kMantissa) return call(exponent);
  const uint64_t ulp_bits = ((bits >> 52) - 52) << 52;  // 2^(exponent of square - 52)
  double ulp;
  std::memcpy(&ulp, &ulp_bits, sizeof ulp);
  if (std::abs(squareResidual(base, square)) <= 0.4 * ulp) return square;
  return call(exponent);
}

}  // namespace sdlqr
