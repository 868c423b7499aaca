#pragma once
// Eigen aliases and the index layout of the paper's state x = [p, q, v] and input u = [omega, c].

#include <Eigen/Core>

namespace sdlqr {

inline constexpr int kStateDim = 10;
inline constexpr int kTangentDim = 9;  // state with the quaternion replaced by its 3-dim tangent
inline constexpr int kInputDim = 4;

// Offsets into x (eq. 1) and u (eq. 2).
enum StateIndex : int { kPos = 0, kQuat = 3, kVel = 7 };
enum TangentIndex : int { kTanPos = 0, kTanRot = 3, kTanVel = 6 };
enum InputIndex : int { kRate = 0, kThrust = 3 };

using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using Quat = Eigen::Vector4d;  // Hamilton quaternion stored w, x, y, z, body to world

using State = Eigen::Matrix<double, kStateDim, 1>;
using Input = Eigen::Matrix<double, kInputDim, 1>;
using StateMatrix = Eigen::Matrix<double, kStateDim, kStateDim>;
using InputMatrix = Eigen::Matrix<double, kStateDim, kInputDim>;
using GainMatrix = Eigen::Matrix<double, kInputDim, kStateDim>;  // the paper's 4x10 K
using InputWeight = Eigen::Matrix<double, kInputDim, kInputDim>;

using TangentVector = Eigen::Matrix<double, kTangentDim, 1>;
using TangentMatrix = Eigen::Matrix<double, kTangentDim, kTangentDim>;
using TangentInputMatrix = Eigen::Matrix<double, kTangentDim, kInputDim>;
using TangentGainMatrix = Eigen::Matrix<double, kInputDim, kTangentDim>;

// Segment views instead of magic offsets; they work on State and on any 10-vector expression.
template <typename Derived> auto position(Eigen::MatrixBase<Derived>& x) { return x.template segment<3>(kPos); }
template <typename Derived> auto position(const Eigen::MatrixBase<Derived>& x) { return x.template segment<3>(kPos); }
template <typename Derived> auto orientation(Eigen::MatrixBase<Derived>& x) { return x.template segment<4>(kQuat); }
template <typename Derived> auto orientation(const Eigen::MatrixBase<Derived>& x) { return x.template segment<4>(kQuat); }
template <typename Derived> auto velocity(Eigen::MatrixBase<Derived>& x) { return x.template segment<3>(kVel); }
template <typename Derived> auto velocity(const Eigen::MatrixBase<Derived>& x) { return x.template segment<3>(kVel); }
template <typename Derived> auto bodyRate(Eigen::MatrixBase<Derived>& u) { return u.template segment<3>(kRate); }
template <typename Derived> auto bodyRate(const Eigen::MatrixBase<Derived>& u) { return u.template segment<3>(kRate); }

inline State makeState(const Vec3& p, const Quat& q, const Vec3& v) {
  State x;
  x << p, q, v;
  return x;
}

inline Input makeInput(const Vec3& omega, double thrust) {
  Input u;
  u << omega, thrust;
  return u;
}

inline Quat identityQuat() { return Quat(1.0, 0.0, 0.0, 0.0); }

}  // namespace sdlqr
