#!/usr/bin/python3
"""Poincare (Floquet) multipliers of closed-loop walks on the unit circle, several walks in one
picture.

Usage: multipliers_plot.py OUT.png WALK_DIR [WALK_DIR ...]
Reads each WALK_DIR/summary.json of `gaitopt simulate` (keys robot, reference, controller,
ground and poincare_multipliers: a list of [re, im] pairs, or null when the walk fell or the map
was not computed) and writes OUT.png, printing its path:
  left   every multiplier in the complex plane with the unit circle: a periodic walk is locally
         stable when all its multipliers lie inside
  right  |multiplier| per walk on a log axis, the largest labelled, |multiplier| = 1 dashed
         (multipliers of a well-tracked gait are 1e-6 .. 1e-2: all at the origin on the left)
A walk without multipliers is named under the picture with its outcome. A missing file or key,
or a malformed value, ends the script with "error: <file>: ..." and exit code 1.
"""
import math
import os
import sys

import numpy as np

import plot_io
import plot_style as style
from plot_io import InputError

MARKERS = ["o", "s", "D", "^", "v", "P", "*", "h"]
# |multiplier| below this is drawn at it on the log axis (an exact zero has no logarithm).
FLOOR = 1e-12


def walk_label(s, folder):
    """'gait, controller, ground' from the summary, the folder's name when keys are missing."""
    parts = [os.path.basename(str(s["reference"]).rstrip("/")) if "reference" in s else None,
             s.get("controller"), f"{s['ground']} ground" if "ground" in s else None]
    parts = [str(p) for p in parts if p]
    return ", ".join(parts) if parts else os.path.basename(folder.rstrip("/"))


def read_walk(folder):
    """(label, multipliers as a complex array or None, outcome text) of one walk folder."""
    path = os.path.join(folder, "summary.json")
    s = plot_io.read_json(path, "summary")
    plot_io.require_keys(path, s, ["poincare_multipliers"])
    z = plot_io.read_multipliers(path, s["poincare_multipliers"])
    outcome = (f"fell: {s.get('failure', '')}".rstrip(": ") if s.get("fell") is True
               else s.get("poincare_failure") or "no multipliers in summary.json")
    return walk_label(s, folder), z, outcome


def draw_unit_circle(ax, series):
    """series: (label, complex array, colour, marker). The multipliers in the complex plane
    with the unit circle, axes equal, at least the circle shown."""
    circle = np.linspace(0, 2 * math.pi, 361)
    ax.fill(np.cos(circle), np.sin(circle), color=style.OK, alpha=0.07, lw=0)
    ax.plot(np.cos(circle), np.sin(circle), color="0.3", lw=1.2, label="unit circle |λ| = 1")
    ax.axhline(0, color="0.7", lw=0.8)
    ax.axvline(0, color="0.7", lw=0.8)
    r = 1.15
    for label, z, colour, marker in series:
        outside = np.abs(z) >= 1
        ax.plot(z.real, z.imag, marker, color=colour, ms=7, mec="black", mew=0.6, ls="none",
                label=label)
        if outside.any():
            ax.plot(z.real[outside], z.imag[outside], "o", ms=14, mfc="none", mec=style.FAIL,
                    mew=1.5)
        r = max(r, 1.1 * float(np.max(np.abs(z), initial=0)))
    ax.set_xlim(-r, r)
    ax.set_ylim(-r, r)
    ax.set_aspect("equal")
    style.finish(ax, "Re λ", "Im λ", "Multipliers in the complex plane", legend=False)


# The marker of a |multiplier| at or below FLOOR: an arrow down, not the walk's own marker,
# which would read as a measured 1e-12.
BELOW_FLOOR = "$\\downarrow$"


def split_at_floor(z):
    """(magnitudes above FLOOR, how many at or below it) of one walk's multipliers."""
    m = np.abs(np.asarray(z))
    return m[m > FLOOR], int(np.sum(m <= FLOOR))


def draw_magnitudes(ax, series):
    """|multiplier| per walk on a log axis, the largest labelled; those at or below FLOOR as an
    arrow at FLOOR. The legend sits under the axes: inside it covered the lowest markers."""
    floored = False
    for k, (label, z, colour, marker) in enumerate(series):
        m, below = split_at_floor(z)
        ax.plot(np.full(len(m), k), m, marker, color=colour, ms=7, mec="black", mew=0.6,
                ls="none", alpha=0.85)
        if below:
            ax.plot(np.full(below, k), np.full(below, FLOOR), marker=BELOW_FLOOR, color=colour,
                    ms=11, ls="none")
            floored = True
        top = float(np.max(m, initial=FLOOR))
        ax.annotate(f"{top:.2g}", (k, top), xytext=(9, 0), textcoords="offset points",
                    va="center", fontsize=8)
    ax.axhline(1, color=style.FAIL, ls="--", lw=1.2, label="|λ| = 1 (stability limit)")
    if floored:
        ax.plot([], [], marker=BELOW_FLOOR, color="0.3", ms=11, ls="none",
                label=f"|λ| ≤ {FLOOR:g} (drawn at {FLOOR:g})")
    ax.set_yscale("log")
    ax.set_xlim(-0.6, len(series) - 0.4)
    ax.set_xticks(range(len(series)))
    ax.set_xticklabels([str(k + 1) for k in range(len(series))])
    ax.grid(True, axis="y", which="major", alpha=0.3)
    style.finish(ax, "walk (numbered as in the legend)", "|λ|",
                 "Magnitudes (log axis; largest labelled)", loc="upper center",
                 bbox_to_anchor=(0.5, -0.17), ncol=2)


def multipliers_figure(walks):
    """walks: (label, z or None, outcome). Left the complex plane, right the magnitudes."""
    plt = style.pyplot()
    have = [(label, z) for label, z, _ in walks if z is not None]
    series = [(f"{k + 1}: {label} (max |λ| {np.max(np.abs(z), initial=0):.2g})", z, f"C{k}",
               MARKERS[k % len(MARKERS)]) for k, (label, z) in enumerate(have)]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 6.2),
                                      gridspec_kw={"width_ratios": [1, 1.1]})
    draw_unit_circle(left, series)
    draw_magnitudes(right, series)
    handles, labels = left.get_legend_handles_labels()
    missing = [f"{label}: {outcome}" for label, z, outcome in walks if z is None]
    note = 0.024 * len(missing) + (0.006 if missing else 0)
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=8,
               bbox_to_anchor=(0.5, note))
    for k, text in enumerate(missing):
        fig.text(0.5, 0.008 + 0.024 * (len(missing) - 1 - k),
                 ("No multipliers: " if k == 0 else "") + text, ha="center", fontsize=8,
                 color="0.3")
    worst = max((float(np.max(np.abs(z), initial=0)) for _, z, _, _ in series), default=None)
    verdict = ("" if worst is None else
               f": largest |λ| {worst:.3g}, " + ("all inside the unit circle (locally stable)"
                                                 if worst < 1 else "outside the unit circle"))
    fig.suptitle(f"Poincaré (Floquet) multipliers of {len(series)} closed-loop walks{verdict}")
    rows = math.ceil((len(series) + 1) / 2)
    fig.tight_layout(rect=(0, 0.037 * rows + 0.024 * len(missing) + 0.02, 1, 1))
    return fig


def main(args):
    walks = [read_walk(folder) for folder in args[1:]]
    fig = multipliers_figure(walks)
    style.save(fig, args[0])
    print(args[0])


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    try:
        main(sys.argv[1:])
    except InputError as e:
        sys.exit(f"error: {e}")
