"""What the plot scripts share: the Agg backend (files only, no display), reading the CSV files of
the tools (a header row, then one row per flight or sample) and writing one figure."""

import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend choice)


def read_rows(path):
    """(header, rows) of a CSV file, every cell a string."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        return header, list(reader)


def number(text):
    """A CSV cell as a float; empty or "nan" is NaN."""
    return float(text) if text not in ("", "nan") else float("nan")


def save(fig, path, dpi=110):
    """Writes the figure to path (PNG) and frees it; returns path."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def folder_arguments(description):
    """DIR [--out PLOTS_DIR] of a script that plots a folder: (DIR, PLOTS_DIR), the latter created
    (default DIR/plots)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("dir")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    out_dir = args.out or os.path.join(args.dir, "plots")
    os.makedirs(out_dir, exist_ok=True)
    return args.dir, out_dir
