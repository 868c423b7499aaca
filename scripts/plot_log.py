#!/usr/bin/python3
"""Basic plots of a flight exported by `sdlqr-logger export LOG --out DIR`.

usage: scripts/plot_log.py DIR [--vehicle QUAD1] [--out PLOTS_DIR]

Writes PNGs (Agg backend, no display needed) to PLOTS_DIR (default DIR/plots):
  position.png        position per axis: REFERENCE x[0..2], SIM_TRUTH and STATE_EST
  position_error.png  position minus reference per axis and its norm (truth, else estimate)
  rate_step.png       RATE_CMD body_rate[1] (omega_y) with p_x, p_x,ref and v_x (the paper's Fig. 6)
  thrust.png          RATE_CMD thrust and where it was clipped
  gains_solve.png     GAINS solve_us and iterations over time
  estimator_error.png STATE_EST minus SIM_TRUTH: position, velocity, attitude angle
A plot whose channels are absent is skipped with a message. Time is simulation time (utime) in
seconds from the first message of the flight. Needs Debian's python3-matplotlib and numpy:
run with /usr/bin/python3.
"""

import argparse
import csv
import os
import sys

import numpy as np

import plot_files
from plot_files import plt


def column_name(header_cell):
    """'position[0] [m]' -> 'position[0]'."""
    cut = header_cell.rfind(" [")
    return header_cell if cut < 0 else header_cell[:cut]


class Channel:
    """Numeric columns of one exported CSV, by field name without unit."""

    def __init__(self, path):
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        self.names = [column_name(c) for c in rows[0]]
        self.units = dict(zip(self.names, rows[0]))
        self.rows = rows[1:]
        self._cache = {}

    def __len__(self):
        return len(self.rows)

    def __contains__(self, name):
        return name in self.names

    def __getitem__(self, name):
        if name not in self._cache:
            i = self.names.index(name)
            self._cache[name] = np.array([float(r[i]) for r in self.rows])
        return self._cache[name]

    def vector(self, name, size):
        return np.column_stack([self[f"{name}[{k}]"] for k in range(size)])


def load(folder, vehicle, base):
    path = os.path.join(folder, vehicle, base + ".csv") if vehicle else os.path.join(folder, base + ".csv")
    if not os.path.exists(path):
        return None
    channel = Channel(path)
    return channel if len(channel) else None


def need(plot, channels, *names):
    missing = [n for n in names if channels.get(n) is None]
    if missing:
        print(f"plot_log: skipping {plot}: no {', '.join(missing)} in the export")
        return False
    return True


def angle_between(q_a, q_b):
    """Rotation angle [rad] between unit quaternions (rows w,x,y,z), sign-independent."""
    dot = np.abs(np.sum(q_a * q_b, axis=1))
    return 2.0 * np.arccos(np.clip(dot, 0.0, 1.0))


def interp_rows(t_new, t, values):
    return np.column_stack([np.interp(t_new, t, values[:, k]) for k in range(values.shape[1])])


def save(fig, out, name):
    print(f"plot_log: wrote {plot_files.save(fig, os.path.join(out, name))}")


def time_plot(ylabel, height):
    """One gridded plot against simulation time, 9 inches wide: (fig, ax)."""
    fig, ax = plt.subplots(figsize=(9, height))
    ax.set_ylabel(ylabel)
    ax.set_xlabel("simulation time [s]")
    ax.grid(True)
    return fig, ax


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folder", help="export folder of sdlqr-logger export")
    parser.add_argument("--vehicle", default="", help="vehicle prefix of the channels, e.g. QUAD1")
    parser.add_argument("--out", help="folder for the PNGs (default: FOLDER/plots)")
    args = parser.parse_args()
    if not os.path.isdir(args.folder):
        print(f"plot_log: no folder {args.folder}", file=sys.stderr)
        return 2
    out = args.out or os.path.join(args.folder, "plots")
    os.makedirs(out, exist_ok=True)

    names = ["REFERENCE", "SIM_TRUTH", "STATE_EST", "RATE_CMD", "GAINS"]
    channels = {n: load(args.folder, args.vehicle, n) for n in names}
    present = [c for c in channels.values() if c is not None]
    if not present:
        print(f"plot_log: none of {', '.join(names)} in {args.folder}", file=sys.stderr)
        return 2
    t0 = min(c["utime"][0] for c in present)

    def t(channel):
        return (channel["utime"] - t0) * 1e-6

    ref, truth, est = channels["REFERENCE"], channels["SIM_TRUTH"], channels["STATE_EST"]
    cmd, gains = channels["RATE_CMD"], channels["GAINS"]
    axes_names = ["x", "y", "z"]

    if ref is not None or truth is not None or est is not None:
        fig, axes = plt.subplots(3, 1, sharex=True, figsize=(9, 7))
        for k, ax in enumerate(axes):
            if ref is not None:
                ax.plot(t(ref), ref[f"x[{k}]"], "k--", label="reference")
            if truth is not None:
                ax.plot(t(truth), truth[f"position[{k}]"], label="truth")
            if est is not None:
                ax.plot(t(est), est[f"position[{k}]"], alpha=0.7, label="estimate")
            ax.set_ylabel(f"p{axes_names[k]} [m]")
            ax.grid(True)
        axes[0].legend(loc="best")
        axes[-1].set_xlabel("simulation time [s]")
        save(fig, out, "position.png")
    else:
        print("plot_log: skipping position.png: no REFERENCE, SIM_TRUTH or STATE_EST in the export")

    actual = truth if truth is not None else est
    if actual is None:
        print("plot_log: skipping position_error.png: no SIM_TRUTH or STATE_EST in the export")
    elif need("position_error.png", channels, "REFERENCE"):
        ta = t(actual)
        p_ref = interp_rows(ta, t(ref), ref.vector("x", 3))
        error = actual.vector("position", 3) - p_ref
        fig, axes = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
        for k in range(3):
            axes[0].plot(ta, error[:, k], label=f"e{axes_names[k]}")
        axes[0].set_ylabel("position - reference [m]")
        axes[0].legend(loc="best")
        axes[1].plot(ta, np.linalg.norm(error, axis=1), "k")
        axes[1].set_ylabel("|error| [m]")
        axes[1].set_xlabel("simulation time [s]")
        axes[0].set_title("from " + ("SIM_TRUTH" if actual is truth else "STATE_EST"))
        for ax in axes:
            ax.grid(True)
        save(fig, out, "position_error.png")

    if need("rate_step.png", channels, "RATE_CMD"):
        fig, ax = time_plot("ω_y [rad/s]", 5)
        ax.plot(t(cmd), cmd["body_rate[1]"], "C0", label="ω_y command [rad/s]")
        right = ax.twinx()
        if ref is not None:
            right.plot(t(ref), ref["x[0]"], "k--", label="p_x,ref [m]")
        if actual is not None:
            right.plot(t(actual), actual["position[0]"], "C1", label="p_x [m]")
            right.plot(t(actual), actual["velocity[0]"], "C2", label="v_x [m/s]")
        right.set_ylabel("p_x [m], v_x [m/s]")
        lines = ax.get_legend_handles_labels()
        more = right.get_legend_handles_labels()
        ax.legend(lines[0] + more[0], lines[1] + more[1], loc="best")
        save(fig, out, "rate_step.png")

    if need("thrust.png", channels, "RATE_CMD"):
        fig, ax = time_plot("mass-normalized thrust [m/s²]", 4)
        ax.plot(t(cmd), cmd["thrust"], label="thrust command")
        clipped = (cmd["saturated"].astype(int) & 2) != 0
        if clipped.any():
            ax.plot(t(cmd)[clipped], cmd["thrust"][clipped], "r.", label="clipped to [c_min, c_max]")
        ax.legend(loc="best")
        save(fig, out, "thrust.png")

    if need("gains_solve.png", channels, "GAINS"):
        fig, ax = time_plot("solve_us [µs]", 4)
        ax.plot(t(gains), gains["solve_us"], ".", label="solve time")
        right = ax.twinx()
        right.plot(t(gains), gains["iterations"], "C1", drawstyle="steps-post", label="iterations")
        right.set_ylabel("iterations [-]")
        ax.set_title(f"median {np.median(gains['solve_us']):.1f} µs, max {np.max(gains['solve_us']):.1f} µs")
        save(fig, out, "gains_solve.png")

    if need("estimator_error.png", channels, "STATE_EST", "SIM_TRUTH"):
        plot_estimator_error(est, truth, t, out)
    return 0


def plot_estimator_error(est, truth, t, out):
    axes_names = ["x", "y", "z"]
    te = t(est)
    inside = (te >= t(truth)[0]) & (te <= t(truth)[-1])
    if "status" in est:
        inside &= est["status"] != 0  # STATUS_INITIALIZING: no estimate yet
    te = te[inside]
    if len(te) == 0:
        print("plot_log: skipping estimator_error.png: STATE_EST and SIM_TRUTH do not overlap in time")
    else:
        p_err = est.vector("position", 3)[inside] - interp_rows(te, t(truth), truth.vector("position", 3))
        v_err = est.vector("velocity", 3)[inside] - interp_rows(te, t(truth), truth.vector("velocity", 3))
        # Nearest truth sample for the attitude (quaternions are not interpolated componentwise).
        nearest = np.clip(np.searchsorted(t(truth), te), 0, len(truth) - 1)
        q_err = angle_between(est.vector("orientation", 4)[inside], truth.vector("orientation", 4)[nearest])
        fig, axes = plt.subplots(3, 1, sharex=True, figsize=(9, 7))
        for k in range(3):
            axes[0].plot(te, p_err[:, k], label=f"e{axes_names[k]}")
            axes[1].plot(te, v_err[:, k], label=f"ev{axes_names[k]}")
        axes[2].plot(te, np.degrees(q_err), "k")
        axes[0].set_ylabel("position [m]")
        axes[1].set_ylabel("velocity [m/s]")
        axes[2].set_ylabel("attitude [deg]")
        axes[2].set_xlabel("simulation time [s]")
        axes[0].set_title("STATE_EST - SIM_TRUTH")
        for ax in axes[:2]:
            ax.legend(loc="best")
        for ax in axes:
            ax.grid(True)
        save(fig, out, "estimator_error.png")


if __name__ == "__main__":
    sys.exit(main())
