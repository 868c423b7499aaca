#!/usr/bin/python3
"""Plots of a comparison folder written by `sdlqr-compare` (docs/controllers.md, Comparing the controllers).

usage: scripts/plot_compare.py DIR [--out PLOTS_DIR]

Reads DIR/tracks/<experiment>.csv (controller, t, x, y, z: SIM_TRUTH at 25 Hz), the uploaded
trajectories DIR/tracks/<experiment>.path.csv (segment, x, y, z) and DIR/sweep.csv, and writes
PNGs (Agg backend) to PLOTS_DIR (default DIR/plots), the names report.md links:
  <experiment>.png   every controller's track overlaid: top view over the uploaded path, x, y, z
                     over time
  speed_sweep.png    path error RMS and max against speed, per controller (a cross: failed)
Needs Debian's python3-matplotlib: run with /usr/bin/python3.
"""

import glob
import math
import os


from plot_files import folder_arguments, number, plt, read_rows, save


def by_controller(path):
    """controller -> (t, x, y, z) lists, in the file's order (the benchmark's)."""
    _, rows = read_rows(path)
    tracks = {}
    for r in rows:
        t, x, y, z = tracks.setdefault(r[0], ([], [], [], []))
        for column, value in zip((t, x, y, z), r[1:5]):
            column.append(number(value))
    return tracks


def experiment_plot(track_path, out_dir):
    name = os.path.basename(track_path)[: -len(".csv")]
    tracks = by_controller(track_path)
    path_file = track_path[: -len(".csv")] + ".path.csv"
    fig = plt.figure(figsize=(12, 7))
    top = fig.add_subplot(1, 2, 1)
    axes = [fig.add_subplot(3, 2, 2 * i + 2) for i in range(3)]
    if os.path.exists(path_file):
        _, rows = read_rows(path_file)
        for segment in sorted({r[0] for r in rows}, key=int):
            xs = [number(r[1]) for r in rows if r[0] == segment]
            ys = [number(r[2]) for r in rows if r[0] == segment]
            top.plot(xs, ys, "k.", markersize=3, label="uploaded path" if segment == "0" else None)
    for controller, (t, x, y, z) in tracks.items():
        line, = top.plot(x, y, linewidth=1, label=controller)
        for ax, values in zip(axes, (x, y, z)):
            ax.plot(t, values, linewidth=1, color=line.get_color())
    top.set_xlabel("x [m]")
    top.set_ylabel("y [m]")
    top.set_aspect("equal", adjustable="datalim")
    top.grid(True, alpha=0.3)
    top.legend(fontsize=8)
    for ax, axis in zip(axes, "xyz"):
        ax.set_ylabel(axis + " [m]")
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("simulation time [s]")
    fig.suptitle(name + " (SIM_TRUTH)")
    save(fig, os.path.join(out_dir, name + ".png"), dpi=100)


def sweep_plot(sweep_path, out_dir):
    header, rows = read_rows(sweep_path)
    col = {name.split(" [")[0]: i for i, name in enumerate(header)}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    controllers = []
    for r in rows:
        if r[0] not in controllers:
            controllers.append(r[0])
    for controller in controllers:
        mine = [r for r in rows if r[0] == controller and r[col["result"]] != "infeasible"]
        speeds = [number(r[col["speed"]]) for r in mine]
        for ax, metric in zip(axes, ("path_error_rms", "path_error_max")):
            values = [number(r[col[metric]]) for r in mine]
            line, = ax.plot(speeds, values, marker="o", label=controller)
            failed = [(s, v) for s, v, r in zip(speeds, values, mine) if r[col["result"]] == "fail"]
            if failed:
                ax.plot([s for s, _ in failed], [v if math.isfinite(v) else 0.0 for _, v in failed], "x",
                        markersize=12, color=line.get_color())
    for ax, metric in zip(axes, ("path error RMS [m]", "path error max [m]")):
        ax.set_xlabel("speed asked [m/s]")
        ax.set_ylabel(metric)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("speed sweep (a cross: the first failing speed)")
    save(fig, os.path.join(out_dir, "speed_sweep.png"), dpi=100)


def main():
    compare_dir, out_dir = folder_arguments(__doc__.splitlines()[0])
    tracks = sorted(p for p in glob.glob(os.path.join(compare_dir, "tracks", "*.csv")) if not p.endswith(".path.csv"))
    for path in tracks:
        experiment_plot(path, out_dir)
    sweep = os.path.join(compare_dir, "sweep.csv")
    if os.path.exists(sweep):
        sweep_plot(sweep, out_dir)
    print(f"plots of {len(tracks)} experiments{' and the sweep' if os.path.exists(sweep) else ''} in {out_dir}")


if __name__ == "__main__":
    main()
