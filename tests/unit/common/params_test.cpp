#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sdlqr/math/lqr_params.hpp"

namespace sdlqr {
namespace {

LqrParams loadText(const std::string& text) {
  return LqrParams::load(ConfigReader(YAML::Load(text), "lqr"));
}

std::string errorKeyOf(const std::string& text) {
  try {
    loadText(text);
  } catch (const ConfigError& e) {
    return e.key();
  }
  return "<no error>";
}

TEST(LqrParams, DefaultsAreThePapersAndValid) {
  const LqrParams p;
  EXPECT_TRUE(p.valid()) << p.invalidReason();
  EXPECT_EQ(p.q_diag[0], 100.0);
  EXPECT_EQ(p.q_diag[3], 1.0);
  EXPECT_EQ(p.q_diag[9], 10.0);
  EXPECT_EQ(p.r_diag[3], 0.1);
  EXPECT_EQ(p.omega_max, 2.0);
  EXPECT_EQ(p.c_min, 2.0);
  EXPECT_EQ(p.c_max, 18.0);
  EXPECT_EQ(p.dt, 0.01);
}

TEST(LqrParams, LoadsEveryKey) {
  const LqrParams p = loadText(
      "{q_diag: [1,2,3,4,5,6,7,8,9,10], r_diag: [1,2,3,4], dt: 0.02, omega_max: 3, c_min: 1, c_max: 20,"
      " gravity: 9.8, method: iterative, tolerance: 1e-10, max_iterations: 50}");
  EXPECT_EQ(p.q_diag[9], 10.0);
  EXPECT_EQ(p.r_diag[2], 3.0);
  EXPECT_EQ(p.dt, 0.02);
  EXPECT_EQ(p.method, LqrMethod::kIterative);
  EXPECT_EQ(p.max_iterations, 50);
}

TEST(LqrParams, EveryInvalidFieldNamesItsKey) {
  EXPECT_EQ(errorKeyOf("{r_diag: [1, 0, 1, 1]}"), "lqr.r_diag[1]");
  EXPECT_EQ(errorKeyOf("{r_diag: [1, -5, 1, 1]}"), "lqr.r_diag[1]");
  EXPECT_EQ(errorKeyOf("{r_diag: [1, 1, 1]}"), "lqr.r_diag");
  EXPECT_EQ(errorKeyOf("{q_diag: [1,1,1,1,1,1,1,1,1,-1]}"), "lqr.q_diag[9]");
  EXPECT_EQ(errorKeyOf("{q_diag: [1,1,1,1,1,1,1,1,1,.nan]}"), "lqr.q_diag[9]");
  EXPECT_EQ(errorKeyOf("{dt: 0}"), "lqr.dt");
  EXPECT_EQ(errorKeyOf("{dt: fast}"), "lqr.dt");
  EXPECT_EQ(errorKeyOf("{c_min: 10, c_max: 5}"), "lqr.c_max");
  EXPECT_EQ(errorKeyOf("{omega_max: -1}"), "lqr.omega_max");
  EXPECT_EQ(errorKeyOf("{method: newton}"), "lqr.method");
  EXPECT_EQ(errorKeyOf("{q_diagg: [1]}"), "lqr.q_diagg");
  EXPECT_EQ(errorKeyOf("{tolerance: 2}"), "lqr.tolerance");
}

TEST(LqrParams, InvalidReasonCatchesProgrammaticChanges) {
  LqrParams p;
  p.r_diag[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(p.valid());
  p = LqrParams();
  p.gravity = 0.0;
  EXPECT_FALSE(p.valid());
}

}  // namespace
}  // namespace sdlqr
