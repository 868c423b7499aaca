#!/usr/bin/python3
"""Plots of a batch folder written by `sdlqr-batch` (docs/batches.md, Batches).

usage: scripts/plot_batch.py DIR [--out PLOTS_DIR]

Reads DIR/flights.csv (one row per flight: flight, controller, seed, the drawn parameters, pass,
failed_checks, one column per criterion, <criterion>.value, then the metrics) and writes PNGs
(Agg backend) to PLOTS_DIR (default DIR/plots):
  success_<parameter>.png  success rate against each drawn parameter, per controller, with 95 %
                           Wilson intervals (a grid: per value; otherwise 8 bins of equal count)
  metrics.png              the distribution of every metric per controller
  worst_flights.png        position of the worst flights, flown again by `./sdlqr batch`
                           (DIR/worst/flight-K/truth.csv), when there are any
Needs Debian's python3-matplotlib and numpy: run with /usr/bin/python3.
"""

import glob
import math
import os

import numpy as np

from plot_files import folder_arguments, number, plt, read_rows, save

Z95 = 1.959963984540054


def wilson(passed, total):
    """The same interval as tools/offline/batch/src/summary.cpp."""
    if total == 0:
        return 0.0, 1.0
    p = passed / total
    centre = (p + Z95 * Z95 / (2 * total)) / (1 + Z95 * Z95 / total)
    half = Z95 / (1 + Z95 * Z95 / total) * math.sqrt(p * (1 - p) / total + Z95 * Z95 / (4 * total * total))
    return max(0.0, centre - half), min(1.0, centre + half)


def columns(header):
    """Parameter columns (between seed and pass) and metric columns (after the last .value)."""
    params = header[header.index("seed") + 1:header.index("pass")]
    last_value = max([i for i, h in enumerate(header) if h.endswith(".value")] + [header.index("failed_checks")])
    return params, header[last_value + 1:]


def success_plot(header, rows, param, out_dir):
    col, pass_col, ctl_col = header.index(param), header.index("pass"), header.index("controller")
    fig, ax = plt.subplots(figsize=(7, 4))
    for controller in sorted({r[ctl_col] for r in rows}):
        mine = [(number(r[col]), r[pass_col] == "1") for r in rows if r[ctl_col] == controller]
        values = sorted({v for v, _ in mine})
        if len(values) <= 12:
            groups = [[ok for v, ok in mine if v == value] for value in values]
            centres = values
        else:
            mine.sort()
            chunks = np.array_split(np.arange(len(mine)), 8)
            groups = [[mine[i][1] for i in chunk] for chunk in chunks]
            centres = [np.mean([mine[i][0] for i in chunk]) for chunk in chunks]
        rates = [sum(g) / len(g) for g in groups]
        intervals = [wilson(sum(g), len(g)) for g in groups]
        low = [r - i[0] for r, i in zip(rates, intervals)]
        high = [i[1] - r for r, i in zip(rates, intervals)]
        ax.errorbar(centres, rates, yerr=[low, high], marker="o", capsize=3, label=controller)
    ax.set_xlabel(param)
    ax.set_ylabel("flights passing every check")
    ax.set_ylim(-0.05, 1.05)
    ax.grid(True, alpha=0.3)
    ax.legend()
    save(fig, os.path.join(out_dir, "success_" + param.replace("[", "_").replace("]", "") + ".png"))


def metrics_plot(header, rows, metrics, out_dir):
    ctl_col = header.index("controller")
    controllers = sorted({r[ctl_col] for r in rows})
    cols = 3
    lines = (len(metrics) + cols - 1) // cols
    fig, axes = plt.subplots(lines, cols, figsize=(4 * cols, 2.8 * lines), squeeze=False)
    for ax, metric in zip(axes.flat, metrics):
        col = header.index(metric)
        for controller in controllers:
            values = [number(r[col]) for r in rows if r[ctl_col] == controller]
            finite = [v for v in values if math.isfinite(v)]
            if finite:
                ax.hist(finite, bins=20, alpha=0.6, label=controller)
            missing = len(values) - len(finite)
            if missing:
                ax.text(0.98, 0.9, f"{missing} not reached", transform=ax.transAxes, ha="right", fontsize=8)
        ax.set_title(metric, fontsize=9)
    for ax in list(axes.flat)[len(metrics):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=8)
    save(fig, os.path.join(out_dir, "metrics.png"))


def worst_plot(batch_dir, out_dir):
    flights = sorted(glob.glob(os.path.join(batch_dir, "worst", "flight-*", "truth.csv")))
    if not flights:
        print("no worst flights flown again (none failed): worst_flights.png skipped")
        return
    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    for path in flights:
        data = np.genfromtxt(path, delimiter=",", names=True)
        label = os.path.basename(os.path.dirname(path))
        for ax, axis in zip(axes, "xyz"):
            ax.plot(data["t"], data[axis], label=label)
    for ax, axis in zip(axes, "xyz"):
        ax.set_ylabel(axis + " [m]")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("simulation time [s]")
    fig.suptitle("worst flights (SIM_TRUTH)")
    save(fig, os.path.join(out_dir, "worst_flights.png"))


def main():
    batch_dir, out_dir = folder_arguments(__doc__.splitlines()[0])
    header, rows = read_rows(os.path.join(batch_dir, "flights.csv"))
    params, metrics = columns(header)
    for param in params:
        success_plot(header, rows, param, out_dir)
    metrics_plot(header, rows, metrics, out_dir)
    worst_plot(batch_dir, out_dir)
    print(f"plots of {len(rows)} flights in {out_dir}")


if __name__ == "__main__":
    main()
