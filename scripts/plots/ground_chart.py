#!/usr/bin/python3
"""Speed against accuracy of the three grounds, from bench/ground_bench's CSV.

Usage: ground_chart.py BENCH_CSV   (writes BENCH_CSV's folder/ground_speed_accuracy.png)
One line per ground (and variant) through its time steps, x the wall time of a 10-step walk;
left, y the largest difference of hip height at equal hip x from the tight rigid reference (the
path); right, the difference of the walk's end time (the timing). A time step whose walk failed
(diverged, slipped, fell) is a cross on the band at the top, labelled with the step.
Prints the picture's path, then a markdown table of the rows.
"""
import os
import sys

import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402

import plot_io  # noqa: E402

DPI = style.DPI
NAMES = ["ground", "variant", "time_step", "steps", "failure", "hip_deviation_m", "timing_s",
         "wall_s"]
STRINGS = ("ground", "variant", "failure")


def draw(ax, rows, column, ylabel):
    """`column` against wall time per (ground, variant); failures on the top band."""
    keys = list(dict.fromkeys(zip(rows["ground"], rows["variant"])))
    ok = rows["failure"] == ""
    top = 3 * np.max(rows[column][ok]) if np.any(ok) else 1.0
    for ground, variant in keys:
        sel = (rows["ground"] == ground) & (rows["variant"] == variant)
        good = sel & ok
        line, = ax.loglog(rows["wall_s"][good], rows[column][good], "o-",
                          label=f"{ground} ({variant})")
        for x, y, h in zip(rows["wall_s"][good], rows[column][good],
                           rows["time_step"][good]):
            ax.annotate(f"{h:g}", (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7,
                        color=line.get_color())
        for x, h in zip(rows["wall_s"][sel & ~ok], rows["time_step"][sel & ~ok]):
            x = max(x, 1e-3)
            ax.plot(x, top, "x", color=line.get_color(), ms=9, mew=2)
            ax.annotate(f"h={h:g} fails", (x, top), textcoords="offset points", xytext=(4, -10),
                        fontsize=7, color=line.get_color())
    ax.axhline(top / 1.5, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel("wall time of a 10-step walk [s]")
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")


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
    fig, (path_ax, time_ax) = plt.subplots(1, 2, figsize=(14, 6))
    draw(path_ax, rows, "hip_deviation_m", "path: max hip height difference at equal hip x [m]")
    draw(time_ax, rows, "timing_s", "timing: end time difference after 10 steps [s]")
    fig.suptitle("Speed against accuracy of the ground models, against a tight rigid reference "
                 "(labels: time step [s]; crosses: walk failed)", fontsize=11)
    out = os.path.join(os.path.dirname(os.path.abspath(path)), "ground_speed_accuracy.png")
    fig.tight_layout()
    fig.savefig(out, dpi=DPI)
    print(f"wrote {os.path.basename(out)}", file=sys.stderr)
    print(table(rows))


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
