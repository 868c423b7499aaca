// The same-bits shortcuts give exactly what the library calls they stand for give: compared bit
// for bit on the edges of their reasoning and on many values, the battery's range included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "sdlqr/math/same_bits.hpp"

namespace sdlqr {
namespace {

// The library's pow, unseen by the compiler: it folds pow(x, 2.0) into x * x.
double libraryPow(double base, double exponent) {
  volatile double hidden = exponent;
  return std::pow(base, hidden);
}

uint64_t bitsOf(double x) {
  uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

TEST(SameBits, RoundToInt64IsLlroundOnHalvesAndEdges) {
  const double cases[] = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
                          0x1p52 - 0.5, -(0x1p52 - 0.5), 0x1p52, 0x1p53 + 2.0, -0x1p62, 4503599627370495.5,
                          123456.49999999999, 1e15 + 0.5, std::numeric_limits<double>::denorm_min()};
  for (const double x : cases) EXPECT_EQ(roundToInt64(x), std::llround(x)) << x;
}

TEST(SameBits, RoundToInt64IsLlroundOnManyValues) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-20.0, 50.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = unit(rng) * std::exp2(exponent(rng));
    ASSERT_EQ(roundToInt64(x), std::llround(x)) << x;
    const double half = std::floor(x) + 0.5;  // exact halves
    ASSERT_EQ(roundToInt64(half), std::llround(half)) << half;
  }
}

TEST(SameBits, SquareIsPowWhereverTheShortcutAnswers) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> voltage_ratio(0.6, 1.4);  // the battery's thrust scale
  std::uniform_real_distribution<double> exponent(-400.0, 400.0);
  std::uniform_real_distribution<double> unit(0.5, 1.0);
  int shortcuts = 0, squares_unlike_pow = 0;
  for (int i = 0; i < 1000000; ++i) {
    const double x = i % 2 == 0 ? voltage_ratio(rng) : unit(rng) * std::exp2(exponent(rng));
    for (const double base : {x, -x}) {
      ASSERT_EQ(bitsOf(powSameBits(base, 2.0)), bitsOf(libraryPow(base, 2.0))) << base;
      if (bitsOf(base * base) != bitsOf(libraryPow(base, 2.0))) ++squares_unlike_pow;
      if (std::abs(squareResidual(base, base * base)) < 0.2 * base * base * 0x1p-52) ++shortcuts;  // surely taken
    }
  }
  EXPECT_GT(shortcuts, 500000);  // the shortcut is tested, not only the call
  EXPECT_GT(squares_unlike_pow, 100);  // and base * base alone would have failed this test
  for (const double base : {0.0, 1.0, 0x1p-600, 0x1p600, std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(bitsOf(powSameBits(base, 2.0)), bitsOf(libraryPow(base, 2.0))) << base;
  }
  EXPECT_TRUE(std::isnan(powSameBits(std::nan(""), 2.0)));
  EXPECT_EQ(powSameBits(1.1, 1.7), libraryPow(1.1, 1.7));  // other exponents: the call
}

TEST(SameBits, SquareResidualIsExact) {
  // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: the last term is what rounding drops.
  const double base = 1.0 + 0x1p-30;
  EXPECT_EQ(squareResidual(base, base * base), 0x1p-60);
}

}  // namespace
}  // namespace sdlqr
