#!/usr/bin/python3
"""Speed against accuracy of the three grounds, from bench/ground_bench's CSV.

Usage: ground_chart.py BENCH_CSV   (writes BENCH_CSV's folder/ground_speed_accuracy.png)
The ground models overlaid in one picture, one line per ground (and variant) through its time
steps, x the wall time of a 10-step walk; left, y the largest difference of hip height at equal
hip x from the tight rigid reference (the path); right, the difference of the walk's end time
(the timing). A time step whose walk failed (diverged, slipped, fell) is a red-edged X at its
own wall time and value, labelled with the step and the failure; where the value does not exist
(no end time) or the wall time is not positive (too short to show on the log axis), the failure
is a left-pointing marker on the axis edge and named in the notes under the panels, one line
each. The legend sits under the panels, so it hides no point; its failure marker shows only
when a panel draws one.
Prints the picture's path, then a markdown table of the rows.
"""
import os
import sys
import textwrap

import matplotlib
import numpy as np

import plot_io
import plot_style as style

plt = style.pyplot()

NAMES = ["ground", "variant", "time_step", "steps", "failure", "hip_deviation_m", "timing_s",
         "wall_s"]
STRINGS = ("ground", "variant", "failure")


def short_failure(text, width=38):
    """The failure without its long tail: 'step 1: diverged' from 'step 1: diverged: ...'."""
    return textwrap.shorten(": ".join(text.split(": ")[:2]), width, placeholder="...")


def draw(ax, rows, column, ylabel):
    """`column` against wall time per (ground, variant); failed runs marked where they are.
    Returns the notes on failures that have no point on this panel."""
    keys = list(dict.fromkeys(zip(rows["ground"], rows["variant"])))
    ok = rows["failure"] == ""
    notes = []
    edge = []  # (y, colour, text) of failures drawn on the left edge
    for ground, variant in keys:
        sel = (rows["ground"] == ground) & (rows["variant"] == variant)
        good = sel & ok
        line, = ax.loglog(rows["wall_s"][good], rows[column][good], "o-",
                          label=f"{ground} ({variant})")
        colour = line.get_color()
        for x, y, h in zip(rows["wall_s"][good], rows[column][good],
                           rows["time_step"][good]):
            ax.annotate(f"{h:g}", (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7,
                        color=colour)
        for i in np.flatnonzero(sel & ~ok):
            x, y, h = rows["wall_s"][i], rows[column][i], rows["time_step"][i]
            what = f"h = {h:g} s failed: {short_failure(rows['failure'][i])}"
            if np.isfinite(y) and y > 0 and x > 0:
                ax.plot(x, y, "X", color=colour, mec=style.FAIL, mew=1.5, ms=11, zorder=4)
                ax.annotate(what, (x, y), textcoords="offset points", xytext=(7, -3),
                            fontsize=7, color=style.FAIL)
            elif np.isfinite(y) and y > 0:
                edge.append((y, colour, f"h = {h:g} s: {short_failure(rows['failure'][i])}\n"
                                        f"wall time {x:.3g} s (off the log axis)"))
            else:
                notes.append(f"{ground} ({variant}), {what}: no {ylabel.split(':')[0]} "
                             f"value to draw")
    if edge:
        ax.autoscale_view()
        left = ax.get_xlim()[0]
        for y, colour, text in edge:
            ax.plot(left, y, "<", color=colour, mec=style.FAIL, mew=1.5, ms=10, zorder=4,
                    clip_on=False)
            ax.annotate(text, (left, y), textcoords="offset points", xytext=(9, -6),
                        fontsize=7, color=style.FAIL, va="top",
                        bbox={"fc": "w", "ec": "none", "alpha": 0.85, "pad": 1})
        ax.set_xlim(left=left)
    if any(line.get_marker() == "X" for line in ax.lines):  # no legend entry for no marker
        ax.plot([], [], "X", color="0.6", mec=style.FAIL, mew=1.5, ms=9, ls="none",
                label="walk failed (at its wall time)")
    ax.set_xlabel("wall time of a 10-step walk [s]")
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", alpha=0.3)
    return notes


NOTE_WIDTH = 150  # characters of a note's line across the figure's width


def note_lines(notes):
    """One line per distinct note, wrapped at NOTE_WIDTH: joined on one line they ran off
    both edges of the figure."""
    lines = []
    for note in dict.fromkeys(notes):
        lines += textwrap.wrap(note, NOTE_WIDTH, subsequent_indent="    ")
    return lines


def legend_entries(axes):
    """(handles, labels) of every panel without repeats: the failure marker may be on either."""
    entries = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    return list(entries.values()), list(entries)


def table(rows):
    """The rows as a markdown table."""
    lines = ["| ground | variant | time step [s] | steps | hip path deviation [m] | "
             "end time difference [s] | wall time [s] | failure |",
             "|---|---|---|---|---|---|---|---|"]
    for i in range(len(rows["ground"])):
        lines.append(f"| {rows['ground'][i]} | {rows['variant'][i]} | {rows['time_step'][i]:g} | "
                     f"{int(rows['steps'][i])} | {rows['hip_deviation_m'][i]:.2e} | "
                     f"{rows['timing_s'][i]:.2e} | "
                     f"{rows['wall_s'][i]:.3f} | {rows['failure'][i]} |")
    return "\n".join(lines)


def main(path):
    rows = plot_io.read_csv(path, "ground bench", NAMES, strings=STRINGS, finite=False)
    fig, (path_ax, time_ax) = plt.subplots(1, 2, figsize=(13, 6.2))
    notes = draw(path_ax, rows, "hip_deviation_m",
                 "path: max hip height difference at equal hip x [m]")
    notes += draw(time_ax, rows, "timing_s", "timing: end time difference after 10 steps [s]")
    handles, labels = legend_entries((path_ax, time_ax))
    lines = note_lines(notes)
    line_height = 0.026  # of the figure's height, one 8-point line at 1.3 spacing, with a gap
    notes_top = 0.015 + line_height * len(lines)
    bottom = 0.06 + notes_top
    fig.legend(handles, labels, loc="lower center", ncol=len(labels),
               bbox_to_anchor=(0.5, notes_top))
    if lines:
        fig.text(0.5, 0.01, "\n".join(lines), ha="center", va="bottom", fontsize=8,
                 color=style.FAIL, linespacing=1.3)
    fig.suptitle("Speed against accuracy of the ground models, against a tight rigid reference "
                 "(labels: time step [s])")
    out = os.path.join(os.path.dirname(os.path.abspath(path)), "ground_speed_accuracy.png")
    fig.tight_layout(rect=(0, bottom, 1, 1))
    style.save(fig, out)
    print(f"wrote {os.path.basename(out)}", file=sys.stderr)
    print(table(rows))


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
