#pragma once
// Exact zero-order-hold discretization of x_dot = A x + B u at a step dt:
//
//   exp([[A, B], [0, 0]] dt) = [[Ad, Bd], [0, I]],   x[k+1] = Ad x[k] + Bd u[k].
//
// The matrix exponential is Higham's scaling and squaring with a diagonal Padé approximant
// (N. J. Higham, "The scaling and squaring method for the matrix exponential revisited",
// SIAM J. Matrix Anal. Appl. 26(4), 2005): the degree m in {3, 5, 7, 9, 13} is the lowest whose
// backward-error bound theta_m covers ||M||_1; above theta_13 the matrix is scaled by 2^-s first
// and the result squared s times. Fixed-size Eigen types only: no heap allocation.
//
// Instantiated in discretize.cpp for the sizes the project uses: expm<13>/discretizeZoh<9, 4>
// (tangent system), expm<14>/discretizeZoh<10, 4> (full system, actuator extension), discretizeZoh<12, 4> (integral
// extension), expm<2>, expm<3>/
// discretizeZoh<2, 1> (analytic test cases).

#include <Eigen/Core>

namespace sdlqr {

template <int N>
using SquareMatrix = Eigen::Matrix<double, N, N>;

// exp(M). Precondition: M finite (a non-finite M gives a non-finite result, never a crash).
template <int N>
SquareMatrix<N> expm(const SquareMatrix<N>& M);

template <int NX, int NU>
struct DiscreteSystem {
  Eigen::Matrix<double, NX, NX> A;  // Ad = exp(A dt)
  Eigen::Matrix<double, NX, NU> B;  // Bd = integral_0^dt exp(A s) ds B
};

// ZOH discretization through the exponential of the (NX+NU)-square augmented matrix.
// Preconditions: dt > 0; A, B finite.
template <int NX, int NU>
DiscreteSystem<NX, NU> discretizeZoh(const Eigen::Matrix<double, NX, NX>& A, const Eigen::Matrix<double, NX, NU>& B,
                                     double dt);

}  // namespace sdlqr
