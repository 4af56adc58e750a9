#!/usr/bin/python3
"""The passive walker's period-doubling route to chaos (bench/passive_bifurcation.cpp).

Usage: passive_bifurcation_chart.py DIR
Reads DIR/branch.csv (period, slope, step, duration_s, interleg_angle_rad, max_multiplier,
most_negative_multiplier: the period-1 and period-2 gaits found by Newton's method) and
DIR/orbit.csv (slope, step, duration_s, interleg_angle_rad: the last steps of a long passive walk
at each slope) and writes DIR/bifurcation.png, printing its path:
  left    step time against slope over the walks' slopes: the walk's steps (dots, the attractor:
          one value per period-1 gait, two past the first doubling, then four, eight, chaos) over
          the gaits found by Newton's method (lines)
  middle  inter-leg angle at touchdown against slope, the same way, over every slope
  right   the period-1 gait's most negative multiplier against slope: it crosses -1 at the first
          doubling (dashed: the slope 0.015 Garcia et al. 1998 publish)
A missing or malformed file ends the script with "error: <file>: ..." and exit code 1.
"""
import os

import numpy as np

import plot_io
import plot_style as style
from plot_io import InputError

PUBLISHED_DOUBLING = 0.015
BRANCH = ("period", "slope", "step", "duration_s", "interleg_angle_rad", "max_multiplier",
          "most_negative_multiplier")
ORBIT = ("slope", "step", "duration_s", "interleg_angle_rad")


def draw_against_slope(ax, branch, orbit, key, label, lo=None):
    """The gaits (lines) and the walk's steps (dots) from slope `lo` on (all when None)."""
    ax.plot(orbit["slope"], orbit[key], ".", color="k", ms=1.5, zorder=3,
            label="steps of a long passive walk")
    for period, colour in ((1, "tab:blue"), (2, "tab:orange")):
        mine = branch["period"] == period
        for step in np.unique(branch["step"][mine]):
            rows = mine & (branch["step"] == step)
            ax.plot(branch["slope"][rows], branch[key][rows], "-", color=colour, lw=1,
                    label=f"period-{period} gait (Newton)" if step == 0 else None)
    ax.axvline(PUBLISHED_DOUBLING, color="0.4", ls="--", lw=0.8,
               label=f"published doubling, {PUBLISHED_DOUBLING} rad")
    if lo is not None:
        ax.set_xlim(lo, orbit["slope"].max() + 2e-4)
        shown = orbit[key][orbit["slope"] >= lo]
        ax.set_ylim(shown.min() - 0.02 * np.ptp(shown), shown.max() + 0.02 * np.ptp(shown))
    style.finish(ax, "slope [rad]", label, fontsize=7)


def fitted_limits(*values, margin=0.05):
    """(low, high) holding every finite value given (and the +-1 lines): a fixed -1.6 .. 1.2
    cut the period-1 gait's multipliers past the doubling (they reach 1.7)."""
    shown = np.concatenate([np.atleast_1d(np.asarray(v, dtype=float)) for v in values])
    shown = shown[np.isfinite(shown)]
    lo, hi = shown.min(), shown.max()
    pad = margin * (hi - lo)
    return lo - pad, hi + pad


def few_ticks(ax):
    """At most five slope ticks: matplotlib's default ran 0.0025-wide labels into each other."""
    from matplotlib.ticker import MaxNLocator

    ax.xaxis.set_major_locator(MaxNLocator(5))


def draw_multiplier(ax, branch):
    one = branch["period"] == 1
    real = one & np.isfinite(branch["most_negative_multiplier"])
    ax.plot(branch["slope"][real], branch["most_negative_multiplier"][real], "o-", ms=3,
            label="most negative real multiplier")
    ax.plot(branch["slope"][one], branch["max_multiplier"][one], "s-", ms=3,
            label="largest |multiplier|")
    ax.axhline(-1, color="tab:red", lw=0.8)
    ax.axhline(1, color="tab:red", lw=0.8)
    ax.axvline(PUBLISHED_DOUBLING, color="0.4", ls="--", lw=0.8)
    ax.set_ylim(*fitted_limits(branch["most_negative_multiplier"][real],
                               branch["max_multiplier"][one], -1.0, 1.0))
    style.finish(ax, "slope [rad]", "multiplier of the period-1 gait",
                 "stability of the period-1 gait", fontsize=7)


def main(folder):
    branch = plot_io.read_csv(os.path.join(folder, "branch.csv"), "gait branches", BRANCH,
                              finite=False)
    orbit = plot_io.read_csv(os.path.join(folder, "orbit.csv"), "passive walks", ORBIT)
    if not np.any(branch["period"] == 1):
        raise InputError(f"{os.path.join(folder, 'branch.csv')}: no period-1 gait")
    plt = style.pyplot()
    fig, axs = plt.subplots(1, 3, figsize=(15, 4.4))
    draw_against_slope(axs[0], branch, orbit, "duration_s", "step time [sqrt(l/g)]",
                       lo=orbit["slope"].min())
    draw_against_slope(axs[1], branch, orbit, "interleg_angle_rad", "inter-leg angle [rad]")
    draw_multiplier(axs[2], branch)
    for ax in axs:
        few_ticks(ax)
    fig.suptitle("Simplest walker (Garcia et al. 1998), passive down a slope: period doubling "
                 "to chaos")
    fig.tight_layout()
    path = os.path.join(folder, "bifurcation.png")
    style.save(fig, path)
    print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
