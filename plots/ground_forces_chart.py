#!/usr/bin/python3
"""How smooth the ground forces are: the same walk on several grounds, side by side.

Usage: ground_forces_chart.py OUT_DIR WALK_DIR [WALK_DIR ...]
Reads each WALK_DIR/walk.csv and summary.json of `gaitopt simulate` (columns t, step, fb_y,
fe_y: the normal forces on the stance tip B and the swing tip E; the summary's ground_file names
the ground) and writes OUT_DIR/ground_forces.md (a table) and OUT_DIR/ground_forces.png, printing
their paths. Per walk, over both tips' normal forces sampled at the walk's rate:
  peak force [N]            the largest normal force
  peak force rate [kN/s]    the largest |dF/dt| between two samples
  reversals per s           how often dF/dt changes sign with a change of at least 1 % of the
                            robot's weight on either side (chatter)
The picture shows the leading foot's normal force around its first touchdown (from 40 ms before
to 80 ms after the first sample where E carries load after one where it carried none, or the first
step change if that comes first: a rigid ground's impact) and the three figures as bars. The
curve follows the same physical foot across the step change: E before it, B after it (the tips
are renamed at each touchdown).
A missing or malformed file ends the script with "error: <file>: ..." and exit code 1.
"""
import os
import sys

import numpy as np

import plot_io
import plot_style as style
from plot_io import InputError

COLUMNS = ("t", "step", "fb_y", "fe_y")
WEIGHT_FRACTION = 0.01  # of the robot's weight: a force change below it is not a reversal
WINDOW = (-0.04, 0.08)  # [s] around the first touchdown
UNLOADED = 1.0  # [N]: a tip carrying at most this carries no load


def read_walk(folder):
    """(label, t, step, normal forces of B and E, weight [N]) of one walk folder."""
    cols = plot_io.read_csv(os.path.join(folder, "walk.csv"), "walk log", COLUMNS, min_rows=3)
    summary = plot_io.read_json(os.path.join(folder, "summary.json"))
    plot_io.require_keys(os.path.join(folder, "summary.json"), summary, ["ground_file", "robot"])
    label = os.path.splitext(os.path.basename(str(summary["ground_file"])))[0]
    weight = float(np.max(cols["fb_y"] + cols["fe_y"]))
    return label, cols["t"], cols["step"], np.vstack([cols["fb_y"], cols["fe_y"]]), weight


def reversals(force, threshold):
    """Sign changes of the force's increments, counting only increments above `threshold`."""
    steps = np.diff(force)
    steps = steps[np.abs(steps) >= threshold]
    return int(np.sum(np.diff(np.sign(steps)) != 0))


def figures(t, forces, weight):
    duration = t[-1] - t[0]
    rate = np.abs(np.diff(forces, axis=1)) / np.diff(t)
    nominal = np.median(forces[0][forces[0] > 0]) if np.any(forces[0] > 0) else weight
    count = sum(reversals(f, WEIGHT_FRACTION * nominal) for f in forces)
    return float(forces.max()), float(rate.max()) / 1e3, count / duration


def first_rise(e_force):
    """Index of the first sample where E carries load after one where it carried none, or None.
    A walk may start with both tips down (a compliant ground's E carries load at t = 0): that
    is not a touchdown."""
    loaded = e_force > UNLOADED
    rises = np.nonzero(loaded[1:] & ~loaded[:-1])[0]
    return int(rises[0]) + 1 if rises.size else None


def leading_foot_force(b_force, e_force, change):
    """The touching-down foot's force: E up to the step change at index `change`, then B (the
    same physical foot, renamed by the step change)."""
    force = e_force.copy()
    if change is not None:
        force[change:] = b_force[change:]
    return force


def touchdown_window(t, step, b_force, e_force):
    """(ms from touchdown, the leading foot's normal force) over WINDOW around the first
    touchdown: E's first rise after the walk's start or, if earlier, the first step change (a
    rigid ground's impact loads E only as an impulse)."""
    changes = np.nonzero(np.diff(step) != 0)[0]
    change = int(changes[0]) + 1 if changes.size else None
    rise = first_rise(e_force)
    candidates = [k for k in (rise, change) if k is not None]
    start = t[min(candidates)] if candidates else t[0]
    force = leading_foot_force(b_force, e_force, change)
    keep = (t >= start + WINDOW[0]) & (t <= start + WINDOW[1])
    return 1e3 * (t[keep] - start), force[keep]


def main(out, folders):
    walks = [read_walk(f) for f in folders]
    rows = ["| ground | peak normal force [N] | peak force rate [kN/s] | reversals per s |",
            "|---|---:|---:|---:|"]
    table = []
    for label, t, _, forces, weight in walks:
        peak, rate, chatter = figures(t, forces, weight)
        table.append((label, peak, rate, chatter))
        rows.append(f"| {label} | {peak:.0f} | {rate:.1f} | {chatter:.1f} |")
    os.makedirs(out, exist_ok=True)
    md = os.path.join(out, "ground_forces.md")
    with style.replacing(md) as tmp, open(tmp, "w", encoding="utf-8") as f:
        f.write("\n".join(rows) + "\n")
    plt = style.pyplot()
    fig, axs = plt.subplots(1, 4, figsize=(17, 4.2), gridspec_kw={"width_ratios": [2, 1, 1, 1]})
    for label, t, step, forces, _ in walks:
        ms, force = touchdown_window(t, step, forces[0], forces[1])
        axs[0].plot(ms, force, lw=1.2, label=label)
    style.finish(axs[0], "time from touchdown [ms]", "normal force on the touching-down foot [N]",
                 "the first touchdown", fontsize=8)
    labels = [row[0] for row in table]
    for ax, k, title in zip(axs[1:], (1, 2, 3), ("peak normal force [N]",
                                                 "peak force rate [kN/s]", "reversals per s")):
        ax.bar(labels, [row[k] for row in table], color="tab:blue")
        ax.set_title(title, fontsize=10)
        ax.tick_params(axis="x", rotation=30)
        ax.grid(True, axis="y", alpha=0.4)
    fig.suptitle("The same walk on each ground: how smooth the contact forces are")
    fig.tight_layout()
    png = os.path.join(out, "ground_forces.png")
    style.save(fig, png)
    print(md)
    print(png)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    try:
        main(sys.argv[1], sys.argv[2:])
    except InputError as e:
        sys.exit(f"error: {e}")
