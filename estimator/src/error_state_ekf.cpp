#include "sdlqr/estimator/error_state_ekf.hpp"

#include <Eigen/Cholesky>
#include <array>
#include <cstring>
#include <utility>

#include "sdlqr/math/kernel_isa.hpp"
#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator {

namespace {

Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v[2], v[1],
       v[2], 0.0, -v[0],
       -v[1], v[0], 0.0;
  return m;
}

}  // namespace

ImuDeltaSplit split(const ImuDelta& delta, double fraction) {
  ImuDeltaSplit out;
  out.first.dt = fraction * delta.dt;
  out.first.delta_angle = fraction * delta.delta_angle;
  out.first.delta_velocity = fraction * delta.delta_velocity;
  out.rest.dt = delta.dt - out.first.dt;
  out.rest.delta_angle = delta.delta_angle - out.first.delta_angle;
  out.first.accel_clipped = fraction * delta.accel_clipped;
  out.rest.accel_clipped = delta.accel_clipped - out.first.accel_clipped;
  // The rest starts where the body has already turned by the first part's angle.
  out.rest.delta_velocity =
      quat::rotationMatrix(quat::exp(out.first.delta_angle)).transpose() * ((1.0 - fraction) * delta.delta_velocity);
  return out;
}

ProcessNoise ProcessNoise::from(const EstimatorParams& params) {
  ProcessNoise n;
  n.gyro_var = params.gyro_noise_density * params.gyro_noise_density;
  n.accel_var = params.accel_noise_density * params.accel_noise_density;
  n.gyro_bias_var = params.gyro_bias_random_walk * params.gyro_bias_random_walk;
  n.accel_bias_var = params.accel_bias_random_walk * params.accel_bias_random_walk;
  n.clip_velocity_var = params.clip_velocity_std * params.clip_velocity_std;
  n.gravity = Vec3(0.0, 0.0, -params.gravity);
  return n;
}

void propagateNominal(NavState& state, const ImuDelta& delta, const Vec3& gravity) {
  const double dt = delta.dt;
  const Vec3 dtheta = delta.delta_angle - state.gyro_bias * dt;
  const Vec3 dvel_world = quat::rotate(state.orientation, delta.delta_velocity - state.accel_bias * dt);
  // Constant acceleration over the interval: p gains v dt + a dt^2 / 2 with a = dvel_world / dt + g.
  state.position += state.velocity * dt + 0.5 * dt * dvel_world + 0.5 * dt * dt * gravity;
  state.velocity += dvel_world + gravity * dt;
  state.orientation = quat::multiply(state.orientation, quat::exp(dtheta)).normalized();
}

namespace {

ErrorTransition transitionAt(const NavState& state, const ImuDelta& delta, const Mat3& rot) {
  const double dt = delta.dt;
  const Vec3 dtheta = delta.delta_angle - state.gyro_bias * dt;
  const Vec3 dvel = delta.delta_velocity - state.accel_bias * dt;
  // Order [dp, dv, dtheta, dbg, dba]. With R_true = R Exp(dtheta), the world velocity increment
  // R_true (dvel - dba dt) = R dvel - R [dvel]x dtheta - R dt dba; the local attitude error is
  // carried back through the turn, and a gyro bias error acts on the turn through the right
  // Jacobian of Exp (first order: I - [dtheta]x / 2).
  ErrorTransition f;
  const Mat3 rot_dvel_skew = rot * skew(dvel);
  f.pos_vel = dt * Mat3::Identity();
  f.pos_rot = -0.5 * dt * rot_dvel_skew;
  f.pos_accel_bias = -0.5 * dt * dt * rot;
  f.vel_rot = -rot_dvel_skew;
  f.vel_accel_bias = -dt * rot;
  f.rot_rot = quat::rotationMatrix(quat::exp(dtheta)).transpose();
  f.rot_gyro_bias = -dt * (Mat3::Identity() - 0.5 * skew(dtheta));
  return f;
}

}  // namespace

ErrorCovariance ErrorTransition::dense() const {
  ErrorCovariance f = ErrorCovariance::Identity();
  f.block<3, 3>(kErrPos, kErrVel) = pos_vel;
  f.block<3, 3>(kErrPos, kErrRot) = pos_rot;
  f.block<3, 3>(kErrPos, kErrAccelBias) = pos_accel_bias;
  f.block<3, 3>(kErrVel, kErrRot) = vel_rot;
  f.block<3, 3>(kErrVel, kErrAccelBias) = vel_accel_bias;
  f.block<3, 3>(kErrRot, kErrRot) = rot_rot;
  f.block<3, 3>(kErrRot, kErrGyroBias) = rot_gyro_bias;
  return f;
}

ErrorTransition errorTransition(const NavState& state, const ImuDelta& delta) {
  return transitionAt(state, delta, quat::rotationMatrix(state.orientation));
}

namespace {

// Two doubles in one SSE2 register (GCC/Clang vector extension; each lane plain IEEE arithmetic).
using Pair = double __attribute__((vector_size(16)));
Pair load2(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
void store2(double* p, Pair v) { std::memcpy(p, &v, sizeof v); }
Pair splat(double x) { return Pair{x, x}; }

// One 3x3 factor of a block product and where its 3-wide operand starts (a row of P in the first
// half, a column of F P in the second).
struct Term {
  const Mat3* f;
  int from;
};

// F P F^T is sums of three products per term. They are added exactly as Eigen's lazy product
// added them when this was Eigen expressions (the commit before issue 26): two rows at a time in
// order, ((x0 + x1) + x2), and a block's odd row out as x0 + (x1 + x2); the terms then one after
// the other onto the identity part. So every covariance, and so every flight, is the same bit for
// bit (unit test ErrorStateEkf.TheCovarianceTransformAddsAsTheEigenExpressionItReplaced).
double oddRowOut(const Mat3& f, int row, double b0, double b1, double b2) {
  return f(row, 0) * b0 + (f(row, 1) * b1 + f(row, 2) * b2);
}

// Rows [to, to + 3) of F P: P's own rows (kIdentity: F's diagonal block there is the identity) plus each term's F block times rows
// [from, from + 3) of P.
template <bool kIdentity, int kTerms>
void rowsOfFP(const ErrorCovariance& p, int to, const Term (&terms)[kTerms], ErrorCovariance& fp, int first_column = 0) {
  for (int j = first_column; j < kErrorDim; ++j) {
    const double* p_col = p.data() + kErrorDim * j;
    Pair rows01 = kIdentity ? load2(p_col + to) : Pair{0.0, 0.0};
    double row2 = kIdentity ? p_col[to + 2] : 0.0;
    for (int t = 0; t < kTerms; ++t) {
      const double* f = terms[t].f->data();  // column-major: rows 0 and 1 of column k at 3 k
      const double b0 = p_col[terms[t].from], b1 = p_col[terms[t].from + 1], b2 = p_col[terms[t].from + 2];
      const Pair sum = (load2(f) * splat(b0) + load2(f + 3) * splat(b1)) + load2(f + 6) * splat(b2);
      const double odd = oddRowOut(*terms[t].f, 2, b0, b1, b2);
      rows01 = (kIdentity || t > 0) ? rows01 + sum : sum;
      row2 = (kIdentity || t > 0) ? row2 + odd : odd;
    }
    double* fp_col = fp.data() + kErrorDim * j;
    store2(fp_col + to, rows01);
    fp_col[to + 2] = row2;
  }
}

// Columns [to, to + 3) of F P F^T: F P's own columns (kIdentity) plus each term's columns
// [from, from + 3) of F P times its F block transposed.
template <bool kIdentity, int kTerms>
void colsOfFPFt(const ErrorCovariance& fp, int to, const Term (&terms)[kTerms], ErrorCovariance& out) {
  for (int c = 0; c < 3; ++c) {
    const double* own = fp.data() + kErrorDim * (to + c);
    double* out_col = out.data() + kErrorDim * (to + c);
    for (int i = 0; i + 1 < kErrorDim; i += 2) {
      Pair sum_all = kIdentity ? load2(own + i) : Pair{0.0, 0.0};
      for (int t = 0; t < kTerms; ++t) {
        const double* a = fp.data() + kErrorDim * terms[t].from + i;
        const Mat3& f = *terms[t].f;
        const Pair sum = (load2(a) * splat(f(c, 0)) + load2(a + kErrorDim) * splat(f(c, 1))) +
                         load2(a + 2 * kErrorDim) * splat(f(c, 2));
        sum_all = (kIdentity || t > 0) ? sum_all + sum : sum;
      }
      store2(out_col + i, sum_all);
    }
    constexpr int kLast = kErrorDim - 1;
    double last = kIdentity ? own[kLast] : 0.0;
    for (int t = 0; t < kTerms; ++t) {
      const double* a = fp.data() + kErrorDim * terms[t].from + kLast;
      const double odd = oddRowOut(*terms[t].f, c, a[0], a[kErrorDim], a[2 * kErrorDim]);
      last = (kIdentity || t > 0) ? last + odd : odd;
    }
    out_col[kLast] = last;
  }
}

#if defined(__x86_64__)
// rowsOfFP on two columns at a time where the CPU has AVX: rows 0 and 1 of both in one vector,
// row 2 of both in a pair; each lane adds exactly as rowsOfFP does.
template <bool kIdentity, int kTerms>
__attribute__((target("avx"))) void rowsOfFPAvx(const ErrorCovariance& p, int to, const Term (&terms)[kTerms],
                                                ErrorCovariance& fp) {
  using Quad = double __attribute__((vector_size(32)));
  constexpr int kPairedColumns = kErrorDim - 1;  // columns 0..13 two at a time, 14 alone
  for (int j = 0; j < kPairedColumns; j += 2) {
    const double* c0 = p.data() + kErrorDim * j;
    const double* c1 = c0 + kErrorDim;
    Quad rows01 = kIdentity ? Quad{c0[to], c0[to + 1], c1[to], c1[to + 1]} : Quad{0.0, 0.0, 0.0, 0.0};
    Pair row2 = kIdentity ? Pair{c0[to + 2], c1[to + 2]} : Pair{0.0, 0.0};
    for (int t = 0; t < kTerms; ++t) {
      const Mat3& f = *terms[t].f;
      const int s = terms[t].from;
      // No lambdas here: they would not inherit target("avx") and so could not return a Quad.
      const Quad f0 = {f(0, 0), f(1, 0), f(0, 0), f(1, 0)}, p0 = {c0[s], c0[s], c1[s], c1[s]};
      const Quad f1 = {f(0, 1), f(1, 1), f(0, 1), f(1, 1)}, p1 = {c0[s + 1], c0[s + 1], c1[s + 1], c1[s + 1]};
      const Quad f2 = {f(0, 2), f(1, 2), f(0, 2), f(1, 2)}, p2 = {c0[s + 2], c0[s + 2], c1[s + 2], c1[s + 2]};
      const Quad sum = (f0 * p0 + f1 * p1) + f2 * p2;
      const Pair odd = splat(f(2, 0)) * Pair{c0[s], c1[s]} +
                       (splat(f(2, 1)) * Pair{c0[s + 1], c1[s + 1]} + splat(f(2, 2)) * Pair{c0[s + 2], c1[s + 2]});
      rows01 = (kIdentity || t > 0) ? rows01 + sum : sum;
      row2 = (kIdentity || t > 0) ? row2 + odd : odd;
    }
    double* out0 = fp.data() + kErrorDim * j;
    double* out1 = out0 + kErrorDim;
    out0[to] = rows01[0];
    out0[to + 1] = rows01[1];
    out1[to] = rows01[2];
    out1[to + 1] = rows01[3];
    out0[to + 2] = row2[0];
    out1[to + 2] = row2[1];
  }
  rowsOfFP<kIdentity>(p, to, terms, fp, kPairedColumns);
}

// colsOfFPFt on four rows at a time where the CPU has AVX (each lane adds exactly as above: the
// association is per element, not per vector). AVX only, never FMA: a fused multiply-add rounds
// once where the sums above round twice.
template <bool kIdentity, int kTerms>
__attribute__((target("avx"))) void colsOfFPFtAvx(const ErrorCovariance& fp, int to, const Term (&terms)[kTerms],
                                                  ErrorCovariance& out) {
  using Quad = double __attribute__((vector_size(32)));
  constexpr int kQuadRows = 12;  // rows 0..11 by four, 12 and 13 as a pair, 14 alone
  for (int c = 0; c < 3; ++c) {
    const double* own = fp.data() + kErrorDim * (to + c);
    double* out_col = out.data() + kErrorDim * (to + c);
    for (int i = 0; i < kQuadRows; i += 4) {
      Quad sum_all{0.0, 0.0, 0.0, 0.0};
      if (kIdentity) std::memcpy(&sum_all, own + i, sizeof sum_all);
      for (int t = 0; t < kTerms; ++t) {
        const double* a = fp.data() + kErrorDim * terms[t].from + i;
        const Mat3& f = *terms[t].f;
        Quad a0, a1, a2;
        std::memcpy(&a0, a, sizeof a0);
        std::memcpy(&a1, a + kErrorDim, sizeof a1);
        std::memcpy(&a2, a + 2 * kErrorDim, sizeof a2);
        const Quad sum = (a0 * f(c, 0) + a1 * f(c, 1)) + a2 * f(c, 2);
        sum_all = (kIdentity || t > 0) ? sum_all + sum : sum;
      }
      std::memcpy(out_col + i, &sum_all, sizeof sum_all);
    }
    Pair pair = kIdentity ? load2(own + kQuadRows) : Pair{0.0, 0.0};
    double last = kIdentity ? own[kErrorDim - 1] : 0.0;
    for (int t = 0; t < kTerms; ++t) {
      const double* a = fp.data() + kErrorDim * terms[t].from + kQuadRows;
      const Mat3& f = *terms[t].f;
      const Pair sum = (load2(a) * splat(f(c, 0)) + load2(a + kErrorDim) * splat(f(c, 1))) +
                       load2(a + 2 * kErrorDim) * splat(f(c, 2));
      const double odd = oddRowOut(f, c, a[2], a[kErrorDim + 2], a[2 * kErrorDim + 2]);
      pair = (kIdentity || t > 0) ? pair + sum : sum;
      last = (kIdentity || t > 0) ? last + odd : odd;
    }
    store2(out_col + kQuadRows, pair);
    out_col[kErrorDim - 1] = last;
  }
}
#endif

// Rows [to, to + 3) of F P and columns [to, to + 3) of F P F^T on the widest vectors the CPU
// offers, the same sums either way.
template <bool kIdentity, int kTerms>
void rowsOfFPOnVectors(const ErrorCovariance& p, int to, const Term (&terms)[kTerms], ErrorCovariance& fp) {
#if defined(__x86_64__)
  if (activeKernelIsa() != KernelIsa::kBaseline) return rowsOfFPAvx<kIdentity>(p, to, terms, fp);
#endif
  rowsOfFP<kIdentity>(p, to, terms, fp);
}
template <bool kIdentity, int kTerms>
void colsOfFPFtOnVectors(const ErrorCovariance& fp, int to, const Term (&terms)[kTerms], ErrorCovariance& out) {
#if defined(__x86_64__)
  if (activeKernelIsa() != KernelIsa::kBaseline) return colsOfFPFtAvx<kIdentity>(fp, to, terms, out);
#endif
  colsOfFPFt<kIdentity>(fp, to, terms, out);
}

}  // namespace

// F's 3x3 blocks make F P F^T 3x3-by-3x15 products, a quarter of the dense work (Eigen sent the
// dense 15x15 product to its GEMM kernel: a third of a batch flight's CPU), fused here so that each
// output is written once.
ErrorCovariance transformedCovariance(const ErrorTransition& f, const ErrorCovariance& p) {
  ErrorCovariance fp;
  rowsOfFPOnVectors<true>(p, kErrPos, {{&f.pos_vel, kErrVel}, {&f.pos_rot, kErrRot}, {&f.pos_accel_bias, kErrAccelBias}}, fp);
  rowsOfFPOnVectors<true>(p, kErrVel, {{&f.vel_rot, kErrRot}, {&f.vel_accel_bias, kErrAccelBias}}, fp);
  rowsOfFPOnVectors<false>(p, kErrRot, {{&f.rot_rot, kErrRot}, {&f.rot_gyro_bias, kErrGyroBias}}, fp);
  fp.middleRows<6>(kErrGyroBias) = p.middleRows<6>(kErrGyroBias);
  ErrorCovariance out;
  colsOfFPFtOnVectors<true>(fp, kErrPos, {{&f.pos_vel, kErrVel}, {&f.pos_rot, kErrRot}, {&f.pos_accel_bias, kErrAccelBias}}, out);
  colsOfFPFtOnVectors<true>(fp, kErrVel, {{&f.vel_rot, kErrRot}, {&f.vel_accel_bias, kErrAccelBias}}, out);
  colsOfFPFtOnVectors<false>(fp, kErrRot, {{&f.rot_rot, kErrRot}, {&f.rot_gyro_bias, kErrGyroBias}}, out);
  out.middleCols<6>(kErrGyroBias) = fp.middleCols<6>(kErrGyroBias);
  return out;
}

void propagate(NavState& state, ErrorCovariance& covariance, const ImuDelta& delta, const ProcessNoise& noise) {
  propagate(state, covariance, delta, noise, state, covariance);
}

void propagate(const NavState& state, const ErrorCovariance& covariance, const ImuDelta& delta, const ProcessNoise& noise,
               NavState& state_out, ErrorCovariance& covariance_out) {
  const double dt = delta.dt;
  if (!(dt > 0.0)) {
    state_out = state;
    covariance_out = covariance;
    return;
  }
  const Mat3 rot = quat::rotationMatrix(state.orientation);
  const ErrorTransition f = transitionAt(state, delta, rot);
  ErrorCovariance propagated = transformedCovariance(f, covariance);
  state_out = state;
  propagateNominal(state_out, delta, noise.gravity);

  // White accelerometer noise integrated once (velocity) and twice (position); isotropic, so the
  // rotation to the world frame leaves it unchanged.
  const Mat3 eye = Mat3::Identity();
  propagated.block<3, 3>(kErrPos, kErrPos) += (noise.accel_var * dt * dt * dt / 3.0) * eye;
  propagated.block<3, 3>(kErrPos, kErrVel) += (noise.accel_var * dt * dt / 2.0) * eye;
  propagated.block<3, 3>(kErrVel, kErrPos) += (noise.accel_var * dt * dt / 2.0) * eye;
  propagated.block<3, 3>(kErrVel, kErrVel) += (noise.accel_var * dt) * eye;
  propagated.block<3, 3>(kErrRot, kErrRot) += (noise.gyro_var * dt) * eye;
  propagated.block<3, 3>(kErrGyroBias, kErrGyroBias) += (noise.gyro_bias_var * dt) * eye;
  propagated.block<3, 3>(kErrAccelBias, kErrAccelBias) += (noise.accel_bias_var * dt) * eye;
  if (!delta.accel_clipped.isZero()) {
    // What a saturated accelerometer missed is unknown in size but confined to the clipped axes;
    // taken as one impulse mid-interval, it moves the position by dt/2 times the velocity.
    const Vec3 missed_var_body = noise.clip_velocity_var * delta.accel_clipped;
    const Mat3 missed = rot * missed_var_body.asDiagonal() * rot.transpose();
    propagated.block<3, 3>(kErrPos, kErrPos) += (0.25 * dt * dt) * missed;
    propagated.block<3, 3>(kErrPos, kErrVel) += (0.5 * dt) * missed;
    propagated.block<3, 3>(kErrVel, kErrPos) += (0.5 * dt) * missed;
    propagated.block<3, 3>(kErrVel, kErrVel) += missed;
  }
  covariance_out = 0.5 * (propagated + propagated.transpose());
}

namespace {

// The error-state components a pose measures (H selects them): position and attitude.
constexpr int kMeasuredCount = 6;
constexpr int kMeasured[kMeasuredCount] = {kErrPos, kErrPos + 1, kErrPos + 2, kErrRot, kErrRot + 1, kErrRot + 2};
constexpr bool measured(int k) { return (k >= kErrPos && k < kErrPos + 3) || (k >= kErrRot && k < kErrRot + 3); }

// A lazy product's odd row out, summed as Eigen's unrolled reduction sums it (halves, the odd
// element on the right: x0 + (x1 + x2) for three).
template <int kLength>
double unrolledSum(const double* x) {
  if constexpr (kLength == 1) {
    return x[0];
  } else {
    constexpr int kHalf = kLength / 2;
    return unrolledSum<kHalf>(x) + unrolledSum<kLength - kHalf>(x + kHalf);
  }
}

// The Joseph form's 15x15 products add as Eigen's lazy products added them into a 15x15 matrix
// on a 16-byte boundary (the commit before issue 26): its slice-vectorised assignment takes each
// column's rows in pairs, from row 0 in even columns and from row 1 in odd ones (columns are 120
// bytes apart), summing a pair's terms in order; the row left over (14 or 0) is a reduction
// (unrolledSum). Unit test ErrorStateEkf.ThePoseUpdateAddsAsTheEigenExpressionsItReplaced.
int firstPairedRow(int column) { return column % 2; }
int unpairedRow(int column) { return column % 2 == 0 ? kErrorDim - 1 : 0; }

// The k, ascending, whose (I - K H)(i, k) may be non-zero for some i of `rows`: the measured
// components and the rows themselves (the diagonal). The other terms add exact zeros.
struct Terms {
  int count = 0;
  int k[kMeasuredCount + 2] = {};
};
constexpr Terms termsOfRows(int first, int last) {
  Terms t;
  for (int k = 0; k < kErrorDim; ++k) {
    if (measured(k) || (k >= first && k <= last)) t.k[t.count++] = k;
  }
  return t;
}
template <int... kRows>
constexpr std::array<Terms, sizeof...(kRows)> termTable(std::integer_sequence<int, kRows...>, int span) {
  return {termsOfRows(kRows, kRows + span)...};
}
// [i]: of rows i and i + 1 (a pair); of row i alone.
constexpr auto kPairTerms = termTable(std::make_integer_sequence<int, kErrorDim - 1>(), 1);
constexpr auto kRowTerms = termTable(std::make_integer_sequence<int, kErrorDim>(), 0);

// (I - K H) P: I - K H is the identity but for its measured columns, so rows i, i + 1 take the
// terms k measured or i or i + 1 (the others add exact zeros).
ErrorCovariance keptCovariance(const ErrorCovariance& i_kh, const ErrorCovariance& p) {
  ErrorCovariance kept;
  for (int j = 0; j < kErrorDim; ++j) {
    for (int i = firstPairedRow(j); i + 1 < kErrorDim; i += 2) {
      const Terms& terms = kPairTerms[static_cast<size_t>(i)];
      Pair sum = load2(&i_kh(i, terms.k[0])) * splat(p(terms.k[0], j));
      for (int t = 1; t < terms.count; ++t) sum = sum + load2(&i_kh(i, terms.k[t])) * splat(p(terms.k[t], j));
      store2(&kept(i, j), sum);
    }
    const int row = unpairedRow(j);
    double terms[kErrorDim];
    for (int k = 0; k < kErrorDim; ++k) terms[k] = i_kh(row, k) * p(k, j);
    kept(row, j) = unrolledSum<kErrorDim>(terms);
  }
  return kept;
}

// kept (I - K H)^T + (K R) K^T, each coefficient the two lazy products' sum.
ErrorCovariance josephSum(const ErrorCovariance& kept, const ErrorCovariance& i_kh,
                          const Eigen::Matrix<double, kErrorDim, kMeasuredCount>& gain_noise,
                          const Eigen::Matrix<double, kErrorDim, kMeasuredCount>& gain) {
  ErrorCovariance out;
  for (int j = 0; j < kErrorDim; ++j) {
    const Terms& terms = kRowTerms[static_cast<size_t>(j)];  // (I - K H)(j, k) is an exact zero for the others
    for (int i = firstPairedRow(j); i + 1 < kErrorDim; i += 2) {
      Pair kept_part = load2(&kept(i, terms.k[0])) * splat(i_kh(j, terms.k[0]));
      for (int t = 1; t < terms.count; ++t) kept_part = kept_part + load2(&kept(i, terms.k[t])) * splat(i_kh(j, terms.k[t]));
      Pair noise_part = load2(&gain_noise(i, 0)) * splat(gain(j, 0));
      for (int m = 1; m < kMeasuredCount; ++m) noise_part = noise_part + load2(&gain_noise(i, m)) * splat(gain(j, m));
      store2(&out(i, j), kept_part + noise_part);
    }
    const int row = unpairedRow(j);
    double kept_terms[kErrorDim], noise_terms[kMeasuredCount];
    for (int k = 0; k < kErrorDim; ++k) kept_terms[k] = kept(row, k) * i_kh(j, k);
    for (int m = 0; m < kMeasuredCount; ++m) noise_terms[m] = gain_noise(row, m) * gain(j, m);
    out(row, j) = unrolledSum<kErrorDim>(kept_terms) + unrolledSum<kMeasuredCount>(noise_terms);
  }
  return out;
}

}  // namespace

PoseUpdateResult updatePose(NavState& state, ErrorCovariance& covariance, const PoseMeasurement& pose,
                            double gate_chi2) {
  using Mat6 = PoseMatrix;
  using Vec6 = PoseVector;
  using Gain = Eigen::Matrix<double, kErrorDim, kMeasuredCount>;
  using Selection = Eigen::Matrix<double, kMeasuredCount, kErrorDim>;

  Vec6 residual;
  residual.head<3>() = pose.position - state.position;
  // q_meas = q (x) Exp(dtheta + noise): the residual is the local rotation from estimate to pose.
  residual.tail<3>() = quat::boxMinus(pose.orientation, state.orientation);

  // H selects the measured components: H P is their rows of P, H P H^T their rows and columns.
  Vec6 noise_var;
  noise_var << Vec3::Constant(pose.position_var), Vec3::Constant(pose.attitude_var);
  Selection measured_rows;
  Mat6 innovation_cov;
  for (int a = 0; a < kMeasuredCount; ++a) {
    measured_rows.row(a) = covariance.row(kMeasured[a]);
    for (int b = 0; b < kMeasuredCount; ++b) innovation_cov(a, b) = covariance(kMeasured[a], kMeasured[b]) + (a == b ? noise_var[a] : 0.0);
  }
  const Eigen::LLT<Mat6> llt(innovation_cov);
  PoseUpdateResult result;
  result.innovation = residual;
  result.innovation_cov = innovation_cov;
  if (llt.info() != Eigen::Success) return result;
  result.mahalanobis_sq = residual.dot(llt.solve(residual));
  if (!(result.mahalanobis_sq <= gate_chi2)) return result;
  result.accepted = true;

  const Gain gain = llt.solve(measured_rows).transpose();  // P H^T S^-1 with P and S symmetric
  const ErrorVector correction = gain * residual;
  // Joseph form keeps P symmetric positive definite despite rounding:
  // (I - K H) P (I - K H)^T + K R K^T, with R diagonal.
  ErrorCovariance i_kh = ErrorCovariance::Identity();
  for (int m = 0; m < kMeasuredCount; ++m) i_kh.col(kMeasured[m]) -= gain.col(m);
  const Gain gain_noise = gain * noise_var.asDiagonal();
  ErrorCovariance updated = josephSum(keptCovariance(i_kh, covariance), i_kh, gain_noise, gain);

  state.position += correction.segment<3>(kErrPos);
  state.velocity += correction.segment<3>(kErrVel);
  const Vec3 dtheta = correction.segment<3>(kErrRot);
  state.orientation = quat::multiply(state.orientation, quat::exp(dtheta)).normalized();
  state.gyro_bias += correction.segment<3>(kErrGyroBias);
  state.accel_bias += correction.segment<3>(kErrAccelBias);

  // Moving the attitude reference by dtheta rotates the remaining attitude error (ESKF reset).
  // G P G^T with G the identity but for its attitude block: only the attitude rows and columns move.
  const Mat3 reset = Mat3::Identity() - 0.5 * skew(dtheta);
  updated.middleRows<3>(kErrRot) = (reset * updated.middleRows<3>(kErrRot)).eval();
  updated.middleCols<3>(kErrRot) = (updated.middleCols<3>(kErrRot) * reset.transpose()).eval();
  covariance = 0.5 * (updated + updated.transpose());
  return result;
}

Vec3 correctedBodyRate(const ImuDelta& delta, const Vec3& gyro_bias) {
  if (!(delta.dt > 0.0)) return Vec3::Zero();
  return delta.delta_angle / delta.dt - gyro_bias;
}

}  // namespace sdlqr::estimator
