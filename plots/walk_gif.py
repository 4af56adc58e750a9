#!/usr/bin/python3
"""Draws walk.gif, the first steps of a `gaitopt simulate` walk as an animated stick figure, for
the README (the report page of `gaitopt report` animates the whole walk).

Usage: walk_gif.py RESULT_DIR
Reads RESULT_DIR/stick.csv (walk_plots.read_stick), and the foot from summary.json
(robot_foot.py), and writes RESULT_DIR/walk.gif with Pillow,
one GIF frame per stick.csv frame at its real-time spacing, the ground and the axes fixed so the
robot is seen to walk across. A missing or malformed file ends the script with exit code 1.
"""
import os

import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402

import plot_io  # noqa: E402
import walk_plots  # noqa: E402
from robot_foot import robot_foot  # noqa: E402

STEPS = 6  # shown: enough to see the gait repeat, small enough for a README (about 1 MB)
DPI = 80


def first_steps(frames, steps):
    return [f for f in frames if f[1] <= steps]


# A tip this close to the ground [m] stands on its foot (the leading tip in the double support).
ON_GROUND = 2e-3


def feet_at(p0, p1, foot):
    """([x heel, x toe], y) of each foot on the ground: under the stance tip (the first link's
    start) and under the other tip (the last link's end) when it is on the ground."""
    heel, toe = foot
    tips = [p0[0]] + ([p1[-1]] if abs(p1[-1][1]) < ON_GROUND else [])
    return [([x - heel, x + toe], [y, y]) for x, y in tips]


def link_colours(n, step):
    """Colour of each link (numbered from the stance tip) in `step`: each physical leg keeps its
    colour (style.link_colours for step 1: leg A blue, leg B orange) though the stance and
    swing legs trade places, and so link numbers, at every touchdown."""
    colours = style.link_colours(n)
    return colours if step % 2 == 1 else colours[::-1]


def x_limits(x_min, x_max, foot):
    """The x range shown: the links' range plus the heel behind and the toe ahead of it (a
    fixed 0.1 m cut the leading toe of a 0.15 m foot), and 0.05 m to spare."""
    heel, toe = foot if foot else (0.0, 0.0)
    return x_min - max(heel + 0.05, 0.1), x_max + max(toe + 0.05, 0.1)


def draw(frames, path, foot=None):
    starts = np.concatenate([f[2] for f in frames] + [f[3] for f in frames])
    x_min, y_min = starts.min(axis=0)
    x_max, y_max = starts.max(axis=0)
    fig, ax = plt.subplots(figsize=(8, 2.8))
    ax.set_aspect("equal")
    ax.set_xlim(*x_limits(x_min, x_max, foot))
    ax.set_ylim(min(y_min, 0) - 0.05, y_max + 0.08)
    ax.axhline(0, color="0.3", lw=1.5)
    ax.set_xlabel("x [m]")
    ax.set_yticks([])
    n = len(frames[0][2])
    lines = [ax.plot([], [], lw=4, solid_capstyle="round")[0] for _ in range(n)]
    feet = [ax.plot([], [], lw=3, solid_capstyle="butt", color="0.15")[0] for _ in range(2)]
    label = ax.text(0.01, 0.92, "", transform=ax.transAxes, fontsize=10)
    fig.tight_layout()

    def update(i):
        t, step, p0, p1 = frames[i]
        for k, (line, colour) in enumerate(zip(lines, link_colours(n, step))):
            line.set_data([p0[k, 0], p1[k, 0]], [p0[k, 1], p1[k, 1]])
            line.set_color(colour)
        drawn = feet_at(p0, p1, foot) if foot else []
        for k, line in enumerate(feet):
            line.set_data(*(drawn[k] if k < len(drawn) else ([], [])))
        label.set_text(f"step {step}   t = {t:.2f} s")
        return lines + feet + [label]

    dt = np.diff([f[0] for f in frames])
    interval_ms = 1000 * float(np.median(dt[dt > 0])) if np.any(dt > 0) else 50
    anim = animation.FuncAnimation(fig, update, frames=len(frames), interval=interval_ms,
                                   blit=True)
    with style.replacing(path) as tmp:
        anim.save(tmp, writer=animation.PillowWriter(fps=1000 / interval_ms), dpi=DPI)
    plt.close(fig)


def main(result_dir):
    stick = os.path.join(result_dir, "stick.csv")
    n = int(plot_io.read_csv(stick, "stick diagram", ["link"])["link"].max())
    frames = first_steps(walk_plots.read_stick(stick, n), STEPS)
    summary = os.path.join(result_dir, "summary.json")
    foot = robot_foot(summary, plot_io.read_json(summary))[0] if os.path.isfile(summary) else None
    path = os.path.join(result_dir, "walk.gif")
    draw(frames, path, foot)
    print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
