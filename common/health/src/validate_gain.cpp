#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "sdlqr/math/discretize.hpp"
#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/lqr_extensions.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/health/validate.hpp"

namespace sdlqr {

double closedLoopSpectralRadius(const GainSet& m, const RotorDrag& drag) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  if (m.law == ControlLaw::kSdlqrIntegral || m.law == ControlLaw::kSdlqrActuator) {
    return extendedClosedLoopSpectralRadius(m.law, m.x_lin, m.u_lin, m.dt, m.thrust_time_constant, m.K, m.K_aug, drag);
  }
  const Quat q = orientation(m.x_lin);
  if (!m.K.allFinite() || !m.x_lin.allFinite() || !m.u_lin.allFinite() || !std::isfinite(m.dt) || m.dt <= 0.0 ||
      q.norm() < 1e-9) {
    return kNan;
  }
  State x = m.x_lin;
  orientation(x).normalize();
  const TangentBasis E = tangentBasis(orientation(x));
  const Linearization linearization = linearize(x, m.u_lin, m.thrust_gain, drag);
  const TangentMatrix A = E.transpose() * linearization.A * E;
  const TangentInputMatrix B = E.transpose() * linearization.B;
  const DiscreteSystem<kTangentDim, kInputDim> discrete = discretizeZoh<kTangentDim, kInputDim>(A, B, m.dt);
  // K = K_r E^T with orthonormal E, so K E recovers the tangent gain; u = u0 + K (x - x0) closes
  // the loop as Ad + Bd K_r (the paper's sign convention).
  const TangentGainMatrix K_r = m.K * E;
  const TangentMatrix closed = discrete.A + discrete.B * K_r;
  if (!closed.allFinite()) return kNan;
  Eigen::EigenSolver<TangentMatrix> solver(closed, /*computeEigenvectors=*/false);
  if (solver.info() != Eigen::Success) return kNan;
  return solver.eigenvalues().cwiseAbs().maxCoeff();
}

RejectReason validateClosedLoop(const GainSet& m, const RotorDrag& drag, double max_spectral_radius) {
  const double radius = closedLoopSpectralRadius(m, drag);
  return std::isfinite(radius) && radius < max_spectral_radius ? RejectReason::kNone : RejectReason::kUnstable;
}

}  // namespace sdlqr
