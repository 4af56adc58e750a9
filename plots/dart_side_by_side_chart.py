#!/usr/bin/python3
"""DART beside the toolkit's own grounds (scripts/dart_side_by_side.sh), in one picture.

Usage: dart_side_by_side_chart.py OUT_DIR
OUT_DIR holds walks.csv (gait, controller, ground, steps, ...: one 20-step walk per gait on each
ground rigid, lcp and dart) and intervals.csv (gait, controller, ground, push_from_Ns,
push_to_Ns, mass_from, mass_to: the push [N s] and plant-mass [x nominal] intervals walked 20
steps on the grounds rigid and dart, both cells empty when the gait falls at nominal). Writes,
printing its path:
  OUT_DIR/side_by_side.png  one row per gait (walks.csv's order, the controller in parentheses):
                            (a) the steps walked of 20 on each ground, (b) the push interval and
                            (c) the plant-mass interval walked on the rigid ground and in DART,
                            an "x" at the nominal for a gait that falls there
A missing or malformed input ends the script with "error: <file>: ..." and exit code 1.
"""
import os

import numpy as np

import plot_io
import plot_style as style
from plot_io import InputError

WALK_GROUNDS = {"rigid": "rigid", "lcp": "LCP", "dart": "DART"}
INTERVAL_GROUNDS = ["rigid", "dart"]
COLOURS = {"rigid": "tab:blue", "lcp": "tab:orange", "dart": "tab:green"}
# (from column, to column, nominal, axis label, panel title)
INTERVALS = [
    ("push_from_Ns", "push_to_Ns", 0.0, "push [N s]", "(b) push interval walked 20 steps"),
    ("mass_from", "mass_to", 1.0, "plant mass [× nominal]",
     "(c) plant-mass interval walked 20 steps"),
]
FIGSIZE = (12, 4.5)
BAR = 0.26  # bar height and spacing of panel (a), in gait rows
OFFSET = 0.15  # the rigid and DART segments sit this far above and below their gait's row


def read_table(path, what, names, grounds, optional=()):
    """{gait: {ground: {"controller": ..., name: value}}} in the file's gait order; every gait
    needs exactly one row per ground."""
    rows = plot_io.read_csv(path, what, ["gait", "controller", "ground", *names],
                            strings=("gait", "controller", "ground"), optional=optional)
    plot_io.check_values(path, "ground", rows["ground"], grounds)
    table = {}
    for i, (gait, ground) in enumerate(zip(rows["gait"], rows["ground"])):
        if ground in table.setdefault(gait, {}):
            raise InputError(f"{path}:{i + 2}: a second '{ground}' row of gait '{gait}'")
        table[gait][ground] = {k: rows[k][i] for k in ("controller", *names)}
    for gait, found in table.items():
        missing = [g for g in grounds if g not in found]
        if missing:
            raise InputError(f"{path}: no '{missing[0]}' row of gait '{gait}'")
    return table


def read_intervals(path, gaits):
    """read_table of intervals.csv; each interval both cells empty or from <= to, and a row
    pair for each of `gaits`."""
    names = [c for lo, hi, *_ in INTERVALS for c in (lo, hi)]
    table = read_table(path, "interval table", names, INTERVAL_GROUNDS, optional=names)
    for gait in gaits:
        if gait not in table:
            raise InputError(f"{path}: no rows of gait '{gait}'")
        for ground, row in table[gait].items():
            for lo, hi, *_ in INTERVALS:
                if np.isnan(row[lo]) != np.isnan(row[hi]) or row[lo] > row[hi]:
                    raise InputError(f"{path}: gait '{gait}', ground '{ground}': '{lo}' "
                                     f"{row[lo]:g} to '{hi}' {row[hi]:g} is not an interval")
    return table


def draw_steps(ax, walks):
    """Panel (a): one bar per ground, the steps written at its end."""
    rows = np.arange(len(walks))
    for k, (ground, name) in enumerate(WALK_GROUNDS.items()):
        bars = ax.barh(rows + (k - 1) * BAR, [walks[g][ground]["steps"] for g in walks], BAR,
                       color=COLOURS[ground], label=name)
        ax.bar_label(bars, fmt="%g", padding=3, fontsize=7)
    ax.set_xlim(0, 23)
    ax.set_axisbelow(True)
    style.finish(ax, "steps walked", "gait (controller)", title="(a) steps walked of 20",
                 legend=False)


def draw_interval(ax, intervals, lo, hi, nominal, xlabel, title):
    """Panel (b) or (c): the interval walked on each ground, or an x at the nominal."""
    ax.axvline(nominal, color="0.6", lw=0.8, ls=":")
    for row, gait in enumerate(intervals):
        for ground, dy in zip(INTERVAL_GROUNDS, (-OFFSET, OFFSET)):
            cells = intervals[gait][ground]
            if np.isnan(cells[lo]):
                ax.plot(nominal, row + dy, "x", color=COLOURS[ground], ms=7, mew=1.8)
            else:
                ax.plot([cells[lo], cells[hi]], [row + dy] * 2, "|-", color=COLOURS[ground],
                        lw=2, ms=9, mew=1.8)
    style.finish(ax, xlabel, "", title=title, legend=False)


def draw(walks, intervals, path):
    plt = style.pyplot()
    fig, axes = plt.subplots(1, 3, figsize=FIGSIZE, sharey=True)
    draw_steps(axes[0], walks)
    for ax, spec in zip(axes[1:], INTERVALS):
        draw_interval(ax, intervals, *spec)
    axes[0].set_yticks(range(len(walks)),
                       [f"{g}\n({walks[g]['rigid']['controller']})" for g in walks])
    axes[0].invert_yaxis()
    handles, labels = axes[0].get_legend_handles_labels()
    handles += axes[1].plot([], [], "x", color="0.3", ms=7, mew=1.8, ls="none")
    fig.legend(handles, labels + ["falls at nominal"], loc="lower center", ncol=4)
    fig.suptitle("DART beside the rigid and LCP grounds: 20-step walks and the intervals walked")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    style.save(fig, path)


def main(out):
    walks = read_table(os.path.join(out, "walks.csv"), "walk table", ["steps"], WALK_GROUNDS)
    intervals = read_intervals(os.path.join(out, "intervals.csv"), walks)
    path = os.path.join(out, "side_by_side.png")
    draw(walks, {gait: intervals[gait] for gait in walks}, path)
    print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
