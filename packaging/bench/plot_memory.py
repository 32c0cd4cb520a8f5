#!/usr/bin/python3
"""Draws memory against frames carved from the CSVs of `sonarcarve-cli bench reconstruct --csv`.

    plot_memory.py OUT.png "LABEL=FILE.csv" ["LABEL=FILE.csv" ...]

For each run: resident memory (VmRSS, solid) and its anonymous part (RssAnon, dotted) while the
frames are carved, and the peak (VmHWM) the whole run reached, occlusion and mesh included, as a
marker at its last frame. A tool for the docs' figures only: the project does not depend on it.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_samples(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main(argv):
    if len(argv) < 3 or any("=" not in a for a in argv[2:]):
        sys.exit(__doc__)
    fig, ax = plt.subplots(figsize=(8, 5), dpi=110)
    for i, run in enumerate(argv[2:]):
        label, path = run.split("=", 1)
        rows = read_samples(path)
        colour = f"C{i}"
        carving = [r for r in rows if r["stage"] == "carve"]
        frames = [int(r["frames_carved"]) for r in carving]
        ax.plot(frames, [float(r["rss_mb"]) for r in carving], "-", color=colour,
                label=f"{label}: resident while carving")
        ax.plot(frames, [float(r["rss_anon_mb"]) for r in carving], ":", color=colour)
        last = rows[-1]
        ax.plot([int(last["frames_carved"])], [float(last["peak_rss_mb"])], "o",
                color=colour, label=f"{label}: peak of the run (occlusion, mesh)")
    ax.set_xlabel("frames carved")
    ax.set_ylabel("memory, MB (dotted: anonymous)")
    ax.set_title("Reconstruction memory against mission length")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(argv[1])


if __name__ == "__main__":
    main(sys.argv)
