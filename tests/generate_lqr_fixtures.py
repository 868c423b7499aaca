#!/usr/bin/python3
"""Reference gains for tests/unit/common/lqr_test.cpp, computed independently of the C++ code.

Run once with Debian's SciPy:  /usr/bin/python3 tests/generate_lqr_fixtures.py
It writes tests/fixtures/lqr_reference.yaml. Independent means: the model is written again here,
its Jacobians come from complex-step differentiation (exact to rounding, no hand derivation),
the discretization is scipy.linalg.expm of the augmented matrix and the Riccati solution is
scipy.linalg.solve_discrete_are (QZ, not doubling) on the 9-state tangent system.
"""
import os
import sys

import numpy as np
import scipy
import scipy.linalg as sla

GRAVITY = 9.81
Q_DIAG = [100, 100, 100, 1, 1, 1, 1, 10, 10, 10]
R_DIAG = [1, 5, 5, 0.1]


def quat_multiply(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return np.array([aw * bw - ax * bx - ay * by - az * bz,
                     aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw])


def rotate(q, v):
    """Rotate v by the unit quaternion q (body to world) as q (x) [0, v] (x) conj(q)."""
    conj = np.array([q[0], -q[1], -q[2], -q[3]])
    return quat_multiply(quat_multiply(q, np.concatenate(([0.0], v))), conj)[1:]


def dynamics(x, u):
    """Paper eq. (3); q enters as q / ||q|| (the norm without abs(), so complex steps pass)."""
    q = x[3:7]
    q_unit = q / np.sqrt(np.sum(q * q))
    omega, thrust = u[:3], u[3]
    x_dot = np.zeros(10, dtype=x.dtype)
    x_dot[0:3] = x[7:10]
    x_dot[3:7] = 0.5 * quat_multiply(q_unit, np.concatenate(([0.0], omega)))
    x_dot[7:10] = thrust * rotate(q_unit, np.array([0.0, 0.0, 1.0])) - np.array([0.0, 0.0, GRAVITY])
    return x_dot


def complex_step_jacobians(x, u, h=1e-30):
    A = np.zeros((10, 10))
    B = np.zeros((10, 4))
    for j in range(10):
        dx = x.astype(complex)
        dx[j] += 1j * h
        A[:, j] = dynamics(dx, u.astype(complex)).imag / h
    for j in range(4):
        du = u.astype(complex)
        du[j] += 1j * h
        B[:, j] = dynamics(x.astype(complex), du).imag / h
    return A, B


def tangent_basis(q):
    """E = blockdiag(I3, G, I3); G: the x, y, z columns of the left multiplication matrix of q."""
    w, x, y, z = q
    G = np.array([[-x, -y, -z],
                  [w, -z, y],
                  [z, w, -x],
                  [-y, x, w]])
    E = np.zeros((10, 9))
    E[0:3, 0:3] = np.eye(3)
    E[3:7, 3:6] = G
    E[7:10, 6:9] = np.eye(3)
    return E


def zoh(A, B, dt):
    n, m = B.shape
    augmented = np.zeros((n + m, n + m))
    augmented[:n, :n] = A * dt
    augmented[:n, n:] = B * dt
    exponential = sla.expm(augmented)
    return exponential[:n, :n], exponential[:n, n:]


def tangent_lqr(x, u, dt):
    q = x[3:7] / np.linalg.norm(x[3:7])
    x = x.copy()
    x[3:7] = q
    A, B = complex_step_jacobians(x, u)
    E = tangent_basis(q)
    Q = np.diag(Q_DIAG).astype(float)
    R = np.diag(R_DIAG).astype(float)
    Ar, Br, Qr = E.T @ A @ E, E.T @ B, E.T @ Q @ E
    Ad, Bd = zoh(Ar, Br, dt)
    P = sla.solve_discrete_are(Ad, Bd, Qr, R)
    P = 0.5 * (P + P.T)
    Kr = -np.linalg.solve(R + Bd.T @ P @ Bd, Bd.T @ P @ Ad)
    residual = Ad.T @ P @ Ad - P - Ad.T @ P @ Bd @ np.linalg.solve(R + Bd.T @ P @ Bd, Bd.T @ P @ Ad) + Qr
    relative_residual = np.linalg.norm(residual) / np.linalg.norm(Qr)
    spectral_radius = max(abs(np.linalg.eigvals(Ad + Bd @ Kr)))
    return Kr @ E.T, P, relative_residual, spectral_radius


def quat_from_axis_angle(axis, degrees):
    axis = np.asarray(axis, dtype=float)
    axis = axis / np.linalg.norm(axis)
    half = np.radians(degrees) / 2.0
    return np.concatenate(([np.cos(half)], np.sin(half) * axis))


def yaw_tilt(yaw_deg, tilt_axis, tilt_deg):
    return quat_multiply(quat_from_axis_angle([0, 0, 1], yaw_deg), quat_from_axis_angle(tilt_axis, tilt_deg))


IDENTITY = [1.0, 0.0, 0.0, 0.0]

# name, position, quaternion, velocity, body rate, thrust, dt
CASES = [
    ("hover", [0, 0, 0], IDENTITY, [0, 0, 0], [0, 0, 0], GRAVITY, 0.01),
    ("hover_away_from_origin", [3, -2, 5], IDENTITY, [0, 0, 0], [0, 0, 0], GRAVITY, 0.01),
    ("tilt_60_roll", [0, 0, 1], yaw_tilt(0, [1, 0, 0], 60), [0, 0, 0], [0, 0, 0], 18.0, 0.01),
    ("tilt_60_pitch", [0, 0, 1], yaw_tilt(0, [0, 1, 0], 60), [0, 0, 0], [0, 0, 0], 18.0, 0.01),
    ("yaw_180", [0, 0, 1], yaw_tilt(180, [1, 0, 0], 0), [0, 0, 0], [0, 0, 0], GRAVITY, 0.01),
    ("yaw_90", [0, 0, 1], yaw_tilt(90, [1, 0, 0], 0), [0, 0, 0], [0, 0, 0], GRAVITY, 0.01),
    ("velocity_5_x", [0, 0, 1], IDENTITY, [5, 0, 0], [0, 0, 0], GRAVITY, 0.01),
    ("velocity_5_diag", [0, 0, 1], IDENTITY, [0, -4, 3], [0, 0, 0], GRAVITY, 0.01),
    ("rate_10_x", [0, 0, 1], IDENTITY, [0, 0, 0], [10, 0, 0], GRAVITY, 0.01),
    ("rate_10_y", [0, 0, 1], IDENTITY, [0, 0, 0], [0, 10, 0], GRAVITY, 0.01),
    ("rate_10_z", [0, 0, 1], IDENTITY, [0, 0, 0], [0, 0, 10], GRAVITY, 0.01),
    ("rate_8_mixed", [0, 0, 1], IDENTITY, [0, 0, 0], [5, -5, 4], GRAVITY, 0.01),
    ("thrust_min", [0, 0, 1], IDENTITY, [0, 0, 0], [0, 0, 0], 2.0, 0.01),
    ("thrust_max", [0, 0, 1], IDENTITY, [0, 0, 0], [0, 0, 0], 18.0, 0.01),
    ("knife_edge_90", [0, 0, 1], yaw_tilt(0, [1, 0, 0], 90), [0, 3, 0], [0, 0, 0], GRAVITY, 0.01),
    ("tilt_60_yaw_180_fast_rates", [1, 1, 2], yaw_tilt(180, [1, 1, 0], 60), [5, 0, 0], [3, -2, 1], 18.0, 0.01),
    ("tilt_45_rate_10_thrust_min", [0, 0, 1], yaw_tilt(30, [1, -1, 0], 45), [0, 0, -2], [7.07, 7.07, 0], 2.0, 0.01),
    ("yaw_180_tilt_30_spin", [0, 0, 1], yaw_tilt(180, [0, 1, 0], 30), [0, 0, 0], [0, 0, -10], 2.0, 0.01),
    ("flip_upside_down", [0, 0, 3], yaw_tilt(0, [1, 0, 0], 180), [0, 0, 1], [6, 0, 0], 18.0, 0.01),
    ("random_attitude", [0.5, -1, 2], yaw_tilt(-70, [0.3, -0.5, 0.9], 40), [1, 2, -3], [2, -1, 0.5], 12.0, 0.01),
    ("reverse_rates_thrust_max", [0, 0, 1], yaw_tilt(45, [0, 1, 0], 20), [-5, 0, 0], [-7, 7, 0], 18.0, 0.01),
    ("hover_dt_2ms", [0, 0, 1], IDENTITY, [0, 0, 0], [0, 0, 0], GRAVITY, 0.002),
    ("tilt_60_dt_20ms", [0, 0, 1], yaw_tilt(20, [1, 0, 0], 60), [2, 0, 0], [1, 2, 3], 18.0, 0.02),
]


def flow(values):
    return "[" + ", ".join(repr(float(v)) for v in values) + "]"


def main():
    out_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures", "lqr_reference.yaml")
    lines = [
        "# Generated by tests/generate_lqr_fixtures.py (SciPy %s, NumPy %s); do not edit by hand." % (
            scipy.__version__, np.__version__),
        "# Complex-step Jacobians, scipy.linalg.expm ZOH, scipy.linalg.solve_discrete_are on the 9-state",
        "# tangent system; K is the paper's 4x10 gain (u = u0 + K (x - x0)), P the 9x9 tangent solution.",
        "q_diag: " + flow(Q_DIAG),
        "r_diag: " + flow(R_DIAG),
        "cases:",
    ]
    worst = 0.0
    for name, p, q, v, omega, thrust, dt in CASES:
        x = np.concatenate((p, q, v)).astype(float)
        u = np.array(list(omega) + [thrust], dtype=float)
        K, P, residual, radius = tangent_lqr(x, u, dt)
        worst = max(worst, residual)
        print("%-28s residual %.2e  closed-loop spectral radius %.6f" % (name, residual, radius))
        if not (np.all(np.isfinite(K)) and radius < 1.0):
            sys.exit("reference failed for " + name)
        lines += [
            "  - name: " + name,
            "    x: " + flow(x),
            "    u: " + flow(u),
            "    dt: " + repr(float(dt)),
            "    scipy_residual: " + repr(float(residual)),
            "    K:",
        ] + ["      - " + flow(row) for row in K] + ["    P:"] + ["      - " + flow(row) for row in P]
    with open(out_path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %d cases to %s (worst SciPy residual %.2e)" % (len(CASES), out_path, worst))


if __name__ == "__main__":
    main()
