#!/usr/bin/python3
"""Figures of the paper's trajectory experiments (Fig. 7-9) from exported flight logs.

usage: scripts/plot_experiments.py --out PLOTS_DIR [--report report.md] RUN_DIR [RUN_DIR ...]

Each RUN_DIR is what `./sdlqr run` writes: csv/ (from `sdlqr-logger export`) and report.json
(from `sdlqr-analyze`, whose "scenario" names the experiment). Writes to PLOTS_DIR:
  <scenario>_paths.png   the three axis views (x-y, x-z, y-z) of the flown path (SIM_TRUTH) over
                         the trajectory's samples (TRAJECTORY), like Fig. 7 and Fig. 8
  <scenario>_error.png   distance to the closest point of the path and error to the time-indexed
                         reference over time, and the commanded thrust and body rates
  pulled_spatial_vs_temporal.png
                         Fig. 9: both pulled flights over the path (x-y view), the spring's hold
                         point, the samples the temporal flight skipped, and the distance to the
                         path over time (when both minsnap_pulled runs are given)
With --report, also writes a Markdown report: the metrics table of every run (from report.json)
and the figures (paths relative to the report; a run's own plots/ folder, e.g. hover_jumps' Fig.
4-6 from plot_log.py, is linked when present).
Needs Debian's python3-matplotlib and numpy: run with /usr/bin/python3.
"""

import argparse
import csv
import json
import os
import sys

import numpy as np

import plot_files
from plot_files import plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_log import Channel  # noqa: E402  (shared CSV reader)


class Run:
    """One exported flight with its analysis report."""

    def __init__(self, folder):
        self.folder = folder
        with open(os.path.join(folder, "report.json"), encoding="utf-8") as f:
            self.report = json.load(f)
        self.scenario = self.report["scenario"]
        csv_dir = os.path.join(folder, "csv")
        self.truth = Channel(os.path.join(csv_dir, "SIM_TRUTH.csv"))
        self.command = Channel(os.path.join(csv_dir, "RATE_CMD.csv"))
        self.disturbance = self._optional(os.path.join(csv_dir, "DISTURBANCE.csv"))
        self.tracked = bool(self.report.get("trajectories"))
        self.trajectory = self._trajectory(os.path.join(csv_dir, "TRAJECTORY.csv")) if self.tracked else None

    @staticmethod
    def _optional(path):
        if not os.path.exists(path):
            return None
        channel = Channel(path)
        return channel if len(channel) else None

    @staticmethod
    def _trajectory(path):
        """Times, positions and closed flag of the first uploaded trajectory (JSON array cells)."""
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        if len(rows) < 2:
            raise SystemExit(f"plot_experiments: no trajectory in {path}")
        names = [c[: c.rfind(" [")] if c.rfind(" [") > 0 else c for c in rows[0]]
        row = dict(zip(names, rows[1]))
        x = np.array(json.loads(row["x[num_samples][10]"]), dtype=float)
        return {
            "start": float(row["start_utime"]) * 1e-6,
            "t": np.array(json.loads(row["t[num_samples]"]), dtype=float),
            "p": x[:, 0:3],
            "closed": row["closed"] == "1",
        }

    def window(self):
        """Start and end [s] of the tracked trajectory, from the report."""
        t = self.report["trajectories"][0]
        return t["start_s"], t["end_s"]

    def truth_in_window(self):
        start, end = self.window()
        t = self.truth["utime"] * 1e-6
        keep = (t >= start) & (t <= end)
        return t[keep], self.truth.vector("position", 3)[keep]


def closest_distance(points, path):
    """Distance [m] from each point (N x 3) to the polyline through `path` (M x 3)."""
    a, b = path[:-1], path[1:]
    seg = b - a
    length2 = np.maximum((seg**2).sum(axis=1), 1e-12)
    best = np.full(len(points), np.inf)
    for start in range(0, len(points), 2000):  # chunks keep the N x M arrays small
        p = points[start : start + 2000, None, :]
        gamma = np.clip(((p - a) * seg).sum(axis=2) / length2, 0.0, 1.0)
        d = np.linalg.norm(p - (a + gamma[..., None] * seg), axis=2)
        best[start : start + 2000] = d.min(axis=1)
    return best


def scheduled_positions(run, t):
    """The trajectory at (t - start): the time-indexed reference, laps wrapped when closed."""
    traj = run.trajectory
    tau = t - traj["start"]
    period = traj["t"][-1] - traj["t"][0]
    if traj["closed"] and period > 0:
        tau = traj["t"][0] + np.mod(tau - traj["t"][0], period)
    return np.column_stack([np.interp(tau, traj["t"], traj["p"][:, k]) for k in range(3)])


def save(fig, out, name):
    print(f"plot_experiments: wrote {plot_files.save(fig, os.path.join(out, name))}")


def plot_paths(run, out):
    t, p = run.truth_in_window()
    ref = run.trajectory["p"]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8))
    for ax, (i, j) in zip(axes, [(0, 1), (0, 2), (1, 2)]):
        ax.plot(ref[:, i], ref[:, j], "o", ms=3, color="tab:gray", label="trajectory samples")
        ax.plot(ref[:, i], ref[:, j], "-", lw=0.8, color="tab:gray")
        ax.plot(p[:, i], p[:, j], "-", lw=1.2, color="tab:blue", label="flown (truth)")
        ax.set_xlabel("xyz"[i] + " [m]")
        ax.set_ylabel("xyz"[j] + " [m]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
    axes[0].legend(loc="best", fontsize=8)
    m = run.report["trajectories"][0]
    fig.suptitle(
        f"{run.scenario}: path error RMS {m['path_error_rms_m']:.3f} m, max {m['path_error_max_m']:.3f} m, "
        f"{m['laps']:.2f} laps"
    )
    save(fig, out, f"{run.scenario}_paths.png")


def plot_errors(run, out):
    t, p = run.truth_in_window()
    start, end = run.window()
    d_path = closest_distance(p, run.trajectory["p"])
    d_time = np.linalg.norm(p - scheduled_positions(run, t), axis=1)
    ct = run.command["utime"] * 1e-6
    keep = (ct >= start) & (ct <= end)
    fig, axes = plt.subplots(3, 1, figsize=(10, 8), sharex=True)
    axes[0].plot(t - start, d_path, label="to the closest point of the path")
    axes[0].plot(t - start, d_time, lw=0.8, alpha=0.7, label="to the time-indexed reference")
    axes[0].set_ylabel("position error [m]")
    axes[0].legend(loc="upper right", fontsize=8)
    for k, name in enumerate(["omega_x", "omega_y", "omega_z"]):
        axes[1].plot(ct[keep] - start, run.command[f"body_rate[{k}]"][keep], lw=0.8, label=name)
    axes[1].set_ylabel("commanded rate [rad/s]")
    axes[1].legend(loc="upper right", fontsize=8)
    axes[2].plot(ct[keep] - start, run.command["thrust"][keep], lw=0.8, color="tab:red")
    axes[2].set_ylabel("thrust c [m/s^2]")
    axes[2].set_xlabel("time since the trajectory started [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.suptitle(f"{run.scenario}: tracking error and inputs")
    save(fig, out, f"{run.scenario}_error.png")


def plot_pulled(spatial, temporal, out):
    ref = spatial.trajectory["p"]
    fig, axes = plt.subplots(1, 2, figsize=(15, 6.2), gridspec_kw={"width_ratios": [1.1, 1]})
    ax = axes[0]
    ax.plot(ref[:, 0], ref[:, 1], "o-", ms=2.5, lw=0.6, color="tab:gray", label="trajectory samples")
    for run, color in [(spatial, "tab:blue"), (temporal, "tab:orange")]:
        t, p = run.truth_in_window()
        ax.plot(p[:, 0], p[:, 1], "-", lw=1.2, color=color, label=f"flown, {run.report['trajectories'][0]['tracking']}")
    skipped = temporal.report["trajectories"][0]["skipped"]
    if skipped:
        idx = [s["index"] for s in skipped]
        ax.plot(ref[idx, 0], ref[idx, 1], "x", ms=8, mew=2, color="tab:red",
                label=f"skipped by temporal tracking ({len(idx)})")
    if spatial.disturbance is not None and "hold_position[0]" in spatial.disturbance:
        hx, hy = spatial.disturbance["hold_position[0]"][0], spatial.disturbance["hold_position[1]"][0]
        ax.plot([hx], [hy], "k*", ms=12, label="hold point of the pull")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax = axes[1]
    for run, color in [(spatial, "tab:blue"), (temporal, "tab:orange")]:
        t, p = run.truth_in_window()
        start, _ = run.window()
        ax.plot(t - start, closest_distance(p, run.trajectory["p"]), color=color,
                label=run.report["trajectories"][0]["tracking"])
        for pull in run.report["trajectories"][0]["pulls"]:
            ax.axvspan(pull["start_s"] - start, pull["release_s"] - start, color=color, alpha=0.12)
    ax.axhline(0.1, color="k", lw=0.8, ls="--", label="0.1 m")
    ax.set_xlabel("time since the trajectory started [s]")
    ax.set_ylabel("distance to the path [m]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    s, tm = spatial.report["trajectories"][0], temporal.report["trajectories"][0]
    fig.suptitle(
        f"held 2 s and pulled off the path: spatial skipped {s['samples_skipped']} samples, back on the path "
        f"{s['pulls'][0]['return_time_s']:.2f} s after release; temporal skipped {tm['samples_skipped']}"
        if s["pulls"] and s["pulls"][0]["return_time_s"] is not None
        else "held 2 s and pulled off the path"
    )
    save(fig, out, "pulled_spatial_vs_temporal.png")


def fmt(value, spec, scale=1.0):
    return "-" if value is None else format(value * scale, spec)


def write_report(runs, plots_dir, path):
    """Markdown: one metrics table for the trajectory flights, one for hover flights, figures."""
    base = os.path.dirname(os.path.abspath(path))
    rel = lambda p: os.path.relpath(p, base)  # noqa: E731
    lines = ["# The paper's experiments", ""]
    lines.append("Each flight ran the real processes on a private LCM bus; positions are the simulator's truth. "
                 "Checks are the scenario's criteria (`config/scenarios/<name>.yaml`).")
    lines.append("")
    lines.append("| experiment | tracking | checks | path error RMS (x / y / z) | path error max | time-indexed RMS "
                 "| completion | laps | samples skipped / passed | saturation | thrust c | pull: off at release, "
                 "back < 0.1 m after | gain solve median / p99 | estimator RMS |")
    lines.append("|" + " --- |" * 14)
    hover = []
    for run in runs:
        r = run.report
        checks = sum(c["pass"] for c in r["checks"])
        verdict = f"{'PASS' if r['passed'] else 'FAIL'} {checks}/{len(r['checks'])}"
        solve = f"{fmt(r['gains_solve_us']['median'], '.0f')} / {fmt(r['gains_solve_us']['p99'], '.0f')} us"
        est = f"{fmt(r['estimator']['position_rms_all_m'], '.2f', 100)} cm"
        if not run.tracked:
            hover.append((run, verdict, solve, est))
            continue
        for t in r["trajectories"]:
            axis = " / ".join(fmt(v, ".3f") for v in t["path_error_rms_axis_m"])
            pulls = "; ".join(f"{fmt(p['distance_at_release_m'], '.2f')} m, {fmt(p['return_time_s'], '.2f')} s"
                              for p in t["pulls"]) or "-"
            completion = f"{fmt(t['completion_time_s'], '.2f')} s" if t["completed"] else "-"
            lines.append(
                f"| {r['scenario']} | {t['tracking']} | {verdict} | {fmt(t['path_error_rms_m'], '.3f')} m ({axis}) "
                f"| {fmt(t['path_error_max_m'], '.3f')} m | {fmt(t['time_error_rms_m'], '.3f')} m | {completion} "
                f"| {fmt(t['laps'], '.2f')} | {t['samples_skipped']} / {t['samples_passed']} "
                f"| {fmt(t['saturation_percent'], '.1f')} % | {fmt(t['thrust_min'], '.2f')}..{fmt(t['thrust_max'], '.2f')} m/s^2 "
                f"| {pulls} | {solve} | {est} |")
    lines.append("")
    lines.append("Path error: distance from the vehicle to the closest point of the polyline through the trajectory's "
                 "samples, from the upload until the reference is within 5 cm of the end (or the next command). "
                 "Time-indexed: to the trajectory at the elapsed time. A sample is skipped when the reference went "
                 "past it and the vehicle never came within the scenario's `skip_radius` (default 0.3 m) of it while "
                 "the reference was within 3 m of path of it. Saturation: share of RATE_CMD with a clipped rate or "
                 "thrust.")
    lines.append("")
    if hover:
        lines.append("| experiment | checks | settle times (< 5 cm) | pulls: back within 10 cm after | gain solve median / p99 | estimator RMS |")
        lines.append("|" + " --- |" * 6)
        for run, verdict, solve, est in hover:
            r = run.report
            settle = ", ".join(f"{w['label']} {fmt(w['settle_time_s'], '.2f')} s" for w in r["setpoints"] if w["jump"])
            pulls = ", ".join(f"{p['label']} {fmt(p['return_time_s'], '.2f')} s" for p in r["pulls"]) or "-"
            lines.append(f"| {r['scenario']} | {verdict} | {settle} | {pulls} | {solve} | {est} |")
        lines.append("")
    lines.append("## Figures")
    lines.append("")
    for run in runs:
        own = os.path.join(run.folder, "plots")
        if not run.tracked and os.path.isdir(own):
            lines.append(f"### {run.scenario} (Fig. 4-6)")
            lines.append("")
            for name in ["position.png", "position_error.png", "rate_step.png", "thrust.png"]:
                if os.path.exists(os.path.join(own, name)):
                    lines.append(f"![{run.scenario} {name}]({rel(os.path.join(own, name))})")
            lines.append("")
        if run.tracked:
            figure = {"minsnap_fast": " (Fig. 7)", "ellipse_infeasible": " (Fig. 8)"}.get(run.scenario, "")
            lines.append(f"### {run.scenario}{figure}")
            lines.append("")
            for suffix in ["paths", "error"]:
                lines.append(f"![{run.scenario} {suffix}]({rel(os.path.join(plots_dir, f'{run.scenario}_{suffix}.png'))})")
            lines.append("")
    pulled = os.path.join(plots_dir, "pulled_spatial_vs_temporal.png")
    if os.path.exists(pulled):
        lines.append("### minsnap_pulled, spatial against temporal tracking (Fig. 9)")
        lines.append("")
        lines.append(f"![pulled]({rel(pulled)})")
        lines.append("")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
    print(f"plot_experiments: wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", metavar="RUN_DIR")
    parser.add_argument("--out", required=True, metavar="PLOTS_DIR")
    parser.add_argument("--report", metavar="FILE", help="also write a Markdown report with the metrics table")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    by_name = {}
    runs = []
    for folder in args.runs:
        try:
            run = Run(folder)
        except (OSError, KeyError, ValueError) as e:
            print(f"plot_experiments: {folder}: {e}", file=sys.stderr)
            return 2
        runs.append(run)
        if not run.tracked:
            print(f"plot_experiments: {run.scenario}: no tracked trajectory (see its own plots/)")
            continue
        by_name[run.scenario] = run
        plot_paths(run, args.out)
        plot_errors(run, args.out)
    if "minsnap_pulled" in by_name and "minsnap_pulled_temporal" in by_name:
        plot_pulled(by_name["minsnap_pulled"], by_name["minsnap_pulled_temporal"], args.out)
    if args.report:
        write_report(runs, args.out, args.report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
