#!/usr/bin/python3
"""Fidelity chart from scripts/fidelity_chart.py's CSV: cost of transport, peak
joint torque and solve time of the five-link robot and its three-link and compass-gait
reductions against walking speed, and each reduction's ratio to the five-link value (the band
of +-10 % marks where a small model answers within 10 %). A failed solve is a missing point.

Usage: plots/fidelity_plots.py RESULT_DIR   (reads DIR/fidelity.csv, writes DIR/fidelity.png)
"""
import os

import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402

import plot_io  # noqa: E402

NAMES = ["speed", "robot", "cot", "peak", "time"]
QUANTITIES = [("cot", "cost of transport"), ("peak", "peak joint torque [N m]"),
              ("time", "solve time [s]")]
REFERENCE = "five-link"


def series(rows, robot, key):
    pick = np.array([r == robot for r in rows["robot"]])
    return rows["speed"][pick], rows[key][pick]


def draw(axes, rows):
    robots = list(dict.fromkeys(rows["robot"]))
    for col, (key, label) in enumerate(QUANTITIES):
        top, bottom = axes[0][col], axes[1][col]
        ref_v, ref_y = series(rows, REFERENCE, key)
        for robot in robots:
            v, y = series(rows, robot, key)
            colour = f"C{robots.index(robot)}"  # one colour per robot in both rows
            top.plot(v, y, "o-", color=colour, label=robot)
            if robot != REFERENCE:
                shared = np.isin(v, ref_v)
                ratio = y[shared] / ref_y[np.isin(ref_v, v)]
                bottom.plot(v[shared], ratio, "o-", color=colour, label=robot)
        top.set_ylabel(label)
        top.set_yscale("log" if key == "time" else "linear")
        bottom.axhspan(0.9, 1.1, color="0.85", label="within 10 %")
        bottom.set_ylabel(f"{label.split(' [')[0]} / five-link")
        bottom.set_xlabel("walking speed [m/s]")
    axes[0][0].legend(fontsize=8)
    axes[1][0].legend(fontsize=8)


def main(result_dir):
    path = os.path.join(result_dir, "fidelity.csv")
    rows = plot_io.read_csv(path, "fidelity table", NAMES, strings=("robot",),
                             optional=("cot", "peak", "time"), finite=False)
    fig, axes = plt.subplots(2, 3, figsize=(14, 7), sharex=True)
    draw(axes, rows)
    fig.suptitle("Model no more than a scene needs: Mu's five-link robot and its reductions, "
                 "torque-squared optimum at a 0.35 m step", fontsize=11)
    fig.tight_layout()
    style.save(fig, os.path.join(result_dir, "fidelity.png"))


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
