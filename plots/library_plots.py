#!/usr/bin/python3
"""Draws the cost of transport over a `gaitopt library` folder.

Usage: library_plots.py LIBRARY_DIR
Reads LIBRARY_DIR/index.json (axes speed/step_length/slope and any config keys after them, and
one entry per finished point with its speed, step_length, slope, config_values, converged,
cost_of_transport and poly_cost_of_transport) and writes LIBRARY_DIR/library.png, printing its
path. One figure, up to four panels:
  (a) cost of transport against speed, one colour per step length (and slope): the optimal
      gait solid with markers, the polynomial gait at the same points dashed; failed points a
      red x at the bottom of the axes, counted in the legend;
  (b) with >= 2 speeds and >= 2 step lengths: a heat map of the optimal cost of transport over
      speed x step length on the first slope, failed cells hatched, unfinished cells blank;
  (c) with >= 2 slopes: cost of transport against slope, one line per speed at the middle step
      length;
  (d) with a config key of >= 2 values: cost of transport against the first such key, one line
      per speed at the middle step length.
A missing folder, a missing or malformed index.json ends the script with "error: ..." on
stderr and exit code 2 (bad input).
"""
import os
import sys

import numpy as np

import plot_io
import plot_style
from plot_io import InputError

# matplotlib is imported by load_matplotlib() once the input has been checked: it takes a
# second to import, and bad input should fail fast.
plt = Rectangle = blended_transform_factory = None

EXIT_BAD_INPUT = 2
FAIL_COLOUR = plot_style.FAIL
AXES = ("speed", "step_length", "slope")
AXIS_LABELS = {"speed": "speed [m/s]", "step_length": "step length [m]", "slope": "slope [rad]"}
POINT_NUMBERS = ("speed", "step_length", "slope")
POINT_COTS = ("cost_of_transport", "poly_cost_of_transport")
# Relative tolerance matching a point's values to the axes (index.csv keeps 12 digits).
MATCH_TOL = 1e-9
# Cells annotated with their value when the heat map is at most this many cells.
ANNOTATE_CELLS = 36


# ---------------------------------------------------------------------------------------------
# Reading


def config_keys(axes):
    """The config keys the library sweeps, in the grid's order (after the walk's axes)."""
    return [name for name in axes if name not in AXES]


def read_axes(path, d):
    """axes -> {name: sorted float array}, each non-empty and strictly increasing: the walk's
    three, then the config keys in the file's order."""
    plot_io.require_type(path, d, "axes", dict, "an object with speed, step_length, slope")
    plot_io.require_keys(path, d["axes"], list(AXES), "axes.")
    axes = {}
    for name in list(AXES) + [k for k in d["axes"] if k not in AXES]:
        values = d["axes"][name]
        if (not isinstance(values, list) or not values
                or not all(plot_io.is_number(v) and np.isfinite(v) for v in values)):
            raise InputError(f"{path}: key 'axes.{name}': expected a non-empty list of finite "
                             f"numbers, got {values!r}")
        a = np.array(values, dtype=float)
        if np.any(np.diff(a) <= 0):
            raise InputError(f"{path}: key 'axes.{name}': expected increasing values, "
                             f"got {values!r}")
        axes[name] = a
    return axes


def position(path, where, axis, values, value):
    """Index of `value` on the axis, or an InputError."""
    k = int(np.argmin(np.abs(values - value)))
    if abs(values[k] - value) > MATCH_TOL * max(1.0, abs(value)):
        raise InputError(f"{path}: key '{where}.{axis}': {value:g} is not on the grid's "
                         f"{axis} axis")
    return k


def read_points(path, d, axes):
    """points -> list of dicts with the grid position `at` (speed, step, slope indices),
    `converged` and the two costs of transport (NaN when null)."""
    plot_io.require_type(path, d, "points", list, "a list of points")
    points, seen = [], set()
    for i, p in enumerate(d["points"]):
        where = f"points[{i}]"
        if not isinstance(p, dict):
            raise InputError(f"{path}: key '{where}': expected an object, got {p!r}")
        plot_io.require_type(path, p, "point", str, "a string", where + ".")
        plot_io.require_numbers(path, p, POINT_NUMBERS, prefix=where + ".")
        plot_io.require_numbers(path, p, POINT_COTS, nullable=True, prefix=where + ".")
        plot_io.require_type(path, p, "converged", bool, "true or false", where + ".")
        keys = config_keys(axes)
        values = p.get("config_values", [])
        if (not isinstance(values, list) or len(values) != len(keys)
                or not all(plot_io.is_number(v) for v in values)):
            raise InputError(f"{path}: key '{where}.config_values': expected {len(keys)} "
                             f"numbers (one per config axis), got {values!r}")
        at = tuple(position(path, where, a, axes[a], p[a]) for a in AXES) + tuple(
            position(path, where, a, axes[a], v) for a, v in zip(keys, values))
        if at in seen:
            raise InputError(f"{path}: key '{where}': point {p['point']} given twice")
        seen.add(at)
        cot = p["cost_of_transport"]
        if p["converged"] and cot is None:
            raise InputError(f"{path}: key '{where}.cost_of_transport': a converged point "
                             f"needs a number, got null")
        poly = p["poly_cost_of_transport"]
        points.append({"at": at, "name": p["point"], "converged": p["converged"],
                       "cot": np.nan if cot is None else float(cot),
                       "poly": np.nan if poly is None else float(poly)})
    return points


# What a point's optimum minimised (its summary.json's cost_type), for the legend: an optimum of
# the torque squared can cost more transport than the polynomial gait.
COST_NAMES = {"torque_squared": "∫Στ² optimum", "abs_work": "absolute-work optimum",
              "cost_of_transport": "cost-of-transport optimum"}


def optimum_name(library_dir, points):
    """COST_NAMES of the first converged point whose folder kept its summary, else 'optimal'."""
    for p in points:
        path = os.path.join(library_dir, "points", p["name"], "summary.json")
        if p["converged"] and os.path.isfile(path):
            return COST_NAMES.get(plot_io.read_json(path).get("cost_type"), "optimal")
    return "optimal"


def read_index(library_dir):
    """(index.json object, axes, points) of the folder."""
    if not os.path.isdir(library_dir):
        raise InputError(f"{library_dir}: not a folder (expected a `gaitopt library` output)")
    path = os.path.join(library_dir, "index.json")
    d = plot_io.read_json(path, "library index")
    axes = read_axes(path, d)
    return d, axes, read_points(path, d, axes)


# ---------------------------------------------------------------------------------------------
# Panels


def series_label(axes, at):
    """Legend text of one line of fixed (step length, slope, config values); the slope and the
    config keys only when they take several values."""
    step, slope, *keyed = at
    text = f"L = {axes['step_length'][step]:g} m"
    if len(axes["slope"]) > 1:
        text += f", slope {axes['slope'][slope]:+g}"
    for key, k in zip(config_keys(axes), keyed):
        if len(axes[key]) > 1:
            text += f", {key.rsplit('.', 1)[-1]} {axes[key][k]:g}"
    return text


def mark_failed(ax, xs, label):
    """Red x at the bottom of the axes at each x (data units), one legend entry with the
    count."""
    if not xs:
        return
    trans = blended_transform_factory(ax.transData, ax.transAxes)
    ax.plot(xs, [0.03] * len(xs), "x", color=FAIL_COLOUR, ms=9, mew=2, transform=trans,
            clip_on=False, zorder=4, label=label)


def draw_cot_speed(ax, axes, points, optimum="optimal"):
    """(a) CoT against speed: one colour per (step length, slope), the optimum (named
    `optimum`) solid, polynomial dashed; failed points as red x at the bottom."""
    speeds = axes["speed"]
    series = sorted({p["at"][1:] for p in points})
    colours = plt.get_cmap("viridis" if len(series) > 10 else "tab10")
    for n, line in enumerate(series):
        colour = colours(n / max(1, len(series) - 1) if len(series) > 10 else n % 10)
        mine = sorted((p for p in points if p["at"][1:] == line), key=lambda p: p["at"][0])
        ok = [p for p in mine if p["converged"]]
        ax.plot([speeds[p["at"][0]] for p in ok], [p["cot"] for p in ok], "o-", color=colour,
                ms=5, lw=1.5, label=series_label(axes, line))
        poly = [p for p in mine if np.isfinite(p["poly"])]
        if poly:
            ax.plot([speeds[p["at"][0]] for p in poly], [p["poly"] for p in poly], "--",
                    color=colour, lw=1.2, alpha=0.9)
    failed = [speeds[p["at"][0]] for p in points if not p["converged"]]
    mark_failed(ax, failed, f"failed ({len(failed)})")
    # A legend entry explaining the dashes once.
    ax.plot([], [], "k--", lw=1.2, label="polynomial gait (dashed)")
    ax.set_xlabel(AXIS_LABELS["speed"])
    ax.set_ylabel("cost of transport")
    ax.set_title(f"(a) cost of transport: {optimum} (solid) vs polynomial (dashed)",
                 fontsize=10)
    ax.grid(True, alpha=0.4)
    shown = [v for p in points if p["converged"] for v in (p["cot"], p["poly"])
             if np.isfinite(v)]
    if shown:
        ax.set_ylim(0, 1.15 * max(shown))  # polynomial values at failed points may be cut
    else:
        ax.set_ylim(bottom=0)
    if len(speeds) == 1:
        ax.set_xlim(speeds[0] - 0.1, speeds[0] + 0.1)
    ax.legend(fontsize=7, loc="best", ncol=2 if len(series) > 5 else 1)


def tick_labels(values):
    """Axis values as short tick texts."""
    return [f"{v:.3g}" for v in values]


def draw_heat_map(fig, ax, axes, points):
    """(b) optimal CoT over speed x step length on the first slope, one equal cell per grid
    point (the axes need not be evenly spaced); failed cells hatched, unfinished ones blank."""
    speeds, steps = axes["speed"], axes["step_length"]
    cot = np.full((len(steps), len(speeds)), np.nan)
    failed = []
    for p in points:
        i, j, *rest = p["at"]
        if any(rest):  # the first slope and config values only
            continue
        if p["converged"]:
            cot[j, i] = p["cot"]
        else:
            failed.append((i, j))
    xe, ye = np.arange(len(speeds) + 1) - 0.5, np.arange(len(steps) + 1) - 0.5
    mesh = ax.pcolormesh(xe, ye, np.ma.masked_invalid(cot), cmap="viridis", shading="flat")
    ax.set_facecolor("0.92")  # unfinished cells
    fig.colorbar(mesh, ax=ax, label="optimal cost of transport")
    for i, j in failed:
        ax.add_patch(Rectangle((i - 0.5, j - 0.5), 1, 1, fill=False, hatch="xx",
                               edgecolor=FAIL_COLOUR, lw=0))
        ax.plot(i, j, "x", color=FAIL_COLOUR, ms=10, mew=2)
    if cot.size <= ANNOTATE_CELLS:
        finite = cot[np.isfinite(cot)]
        mid = (finite.min() + finite.max()) / 2 if finite.size else 0
        for j in range(len(steps)):
            for i in range(len(speeds)):
                if np.isfinite(cot[j, i]):
                    ax.text(i, j, f"{cot[j, i]:.3g}", ha="center", va="center", fontsize=7,
                            color="k" if cot[j, i] > mid else "w")
    every = max(1, len(speeds) // 12)  # at most about 12 tick labels
    ax.set_xticks(range(0, len(speeds), every), tick_labels(speeds[::every]))
    every = max(1, len(steps) // 12)
    ax.set_yticks(range(0, len(steps), every), tick_labels(steps[::every]))
    ax.set_xlim(xe[0], xe[-1])
    ax.set_ylim(ye[0], ye[-1])
    ax.plot([], [], "x", color=FAIL_COLOUR, ms=8, mew=2, label=f"failed ({len(failed)})")
    ax.legend(fontsize=7, loc="upper right", framealpha=0.9)
    ax.set_xlabel(AXIS_LABELS["speed"])
    ax.set_ylabel(AXIS_LABELS["step_length"])
    slope = f", slope {axes['slope'][0]:+g} rad" if len(axes["slope"]) > 1 else ""
    ax.set_title(f"(b) optimal cost of transport{slope}", fontsize=10)


def draw_cot_along(ax, axes, points, axis):
    """CoT against axis number `axis` (> 1): one line per speed at the middle step length, the
    other axes at their first values."""
    names = list(axes)
    xs, speeds = axes[names[axis]], axes["speed"]
    step = len(axes["step_length"]) // 2

    def on_line(p):
        return p["at"][1] == step and not any(
            k for a, k in enumerate(p["at"]) if a > 1 and a != axis)

    colours = plt.get_cmap("plasma")
    for i, v in enumerate(speeds):
        mine = sorted((p for p in points if p["at"][0] == i and on_line(p)),
                      key=lambda p: p["at"][axis])
        ok = [p for p in mine if p["converged"]]
        colour = colours(0.85 * i / max(1, len(speeds) - 1))
        ax.plot([xs[p["at"][axis]] for p in ok], [p["cot"] for p in ok], "o-", color=colour,
                ms=5, label=f"v = {v:g} m/s")
    failed = [xs[p["at"][axis]] for p in points if on_line(p) and not p["converged"]]
    mark_failed(ax, failed, f"failed ({len(failed)})")
    ax.set_ylabel("cost of transport")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=7, loc="best")


def draw_cot_slope(ax, axes, points):
    """(c) CoT against slope."""
    draw_cot_along(ax, axes, points, AXES.index("slope"))
    ax.set_xlabel(AXIS_LABELS["slope"] + ", > 0 uphill")
    step = len(axes["step_length"]) // 2
    ax.set_title(f"(c) optimal cost of transport vs slope, L = {axes['step_length'][step]:g} m",
                 fontsize=10)


def draw_cot_config(ax, axes, points, key):
    """(d) CoT against a config key of the base problem."""
    draw_cot_along(ax, axes, points, list(axes).index(key))
    ax.set_xlabel(key)
    ax.set_title(f"(d) optimal cost of transport vs {key}", fontsize=10)


# ---------------------------------------------------------------------------------------------
# Picture


def headline(d, axes, points):
    solved = sum(p["converged"] for p in points)
    total = int(np.prod([len(values) for values in axes.values()]))
    dims = " x ".join(f"{len(values)} {a.replace('_', ' ') if a in AXES else a}"
                      for a, values in axes.items())
    return (f"Gait library: {solved} of {total} points solved, {len(points) - solved} failed "
            f"({dims})")


def library_figure(d, axes, points, optimum="optimal"):
    heat = len(axes["speed"]) >= 2 and len(axes["step_length"]) >= 2
    by_slope = len(axes["slope"]) >= 2
    by_key = next((k for k in config_keys(axes) if len(axes[k]) >= 2), None)
    panels = 1 + heat + by_slope + (by_key is not None)
    fig, axs = plt.subplots(1, panels, figsize=(6.4 * panels, 4.8), squeeze=False)
    axs = list(axs.flat)
    draw_cot_speed(axs.pop(0), axes, points, optimum)
    if heat:
        draw_heat_map(fig, axs.pop(0), axes, points)
    if by_slope:
        draw_cot_slope(axs.pop(0), axes, points)
    if by_key is not None:
        draw_cot_config(axs.pop(0), axes, points, by_key)
    fig.suptitle(headline(d, axes, points), fontsize=11)
    fig.tight_layout()
    return fig


def load_matplotlib():
    global plt, Rectangle, blended_transform_factory
    plot_style.pyplot()
    import matplotlib.pyplot
    import matplotlib.patches
    import matplotlib.transforms
    plt = matplotlib.pyplot
    Rectangle = matplotlib.patches.Rectangle
    blended_transform_factory = matplotlib.transforms.blended_transform_factory


def main(library_dir):
    d, axes, points = read_index(library_dir)
    load_matplotlib()
    fig = library_figure(d, axes, points, optimum_name(library_dir, points))
    path = os.path.join(library_dir, "library.png")
    plot_style.save(fig, path)
    print(path)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(EXIT_BAD_INPUT)
    try:
        main(sys.argv[1])
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(EXIT_BAD_INPUT)
