#!/usr/bin/python3
"""Draws the 2-D maps of a `gaitopt stability` result folder (called by stability_plots.py).

Usage: map_plots.py RESULT_DIR
Reads RESULT_DIR/summary.json (key `maps`: per map its two parameters `a` and `b` with name,
unit, values, nominal, geometric (optional), and the largest walking rectangle around the nominal point) and
RESULT_DIR/map_<a>_<b>.csv, and writes RESULT_DIR/map_<a>_<b>.png per map, printing its path:
two heat maps over the grid, a (rows) against b (columns), each cell centred on its value with
its edges midway between neighbours (an axis with the nominal inserted is uneven), a geometric
parameter (`geometric`: the stiffness) on a log axis:
  left:  steps completed, the nominal point starred and the largest walking rectangle around
         it framed;
  right: how each point ended: walked, or the failure's cause (the text after "step k: ").
A missing file, column or key, or a malformed value, ends the script with exit code 1.
"""
import os
import textwrap

import plot_style as style

plt = style.pyplot()
import matplotlib  # noqa: E402
import numpy as np  # noqa: E402

import plot_io  # noqa: E402
from plot_io import InputError  # noqa: E402

OUTCOME_COLUMNS = ["steps_completed", "steps_requested", "fell", "failure"]
WALKED = "walked all steps"
# Failure causes in a fixed colour order, so one cause looks the same in every map.
CAUSE_COLOURS = ["tab:red", "tab:orange", "tab:brown", "tab:pink", "tab:olive", "tab:cyan",
                 "tab:blue", "tab:purple", "0.5"]


def read_axis(path, entry, key):
    plot_io.require_type(path, entry, key, dict, "an object with name, unit, values, nominal")
    axis = entry[key]
    plot_io.require_type(path, axis, "name", str, "a string", f"{key}.")
    plot_io.require_type(path, axis, "unit", str, "a string", f"{key}.")
    plot_io.require_numbers(path, axis, ["values", "nominal"], prefix=f"{key}.")
    if "geometric" in axis:
        plot_io.require_type(path, axis, "geometric", bool, "true or false", f"{key}.")
    return axis


def is_geometric(axis, values):
    """Whether an axis is drawn on a log scale: a parameter spaced by a ratio (summary.json's
    `geometric`; in summaries written before it, the stiffness), with positive values."""
    return bool(axis.get("geometric", axis["name"] == "stiffness")) and bool(np.all(values > 0))


def cell_edges(values, log):
    """The edges of the cells centred on grid values: midway between neighbours (in log space on
    a log axis), the end cells as wide as their neighbours. An uneven axis (the nominal inserted
    into a range, a geometric stiffness) is drawn where its points were walked; evenly spread
    cells put rows at values that never were."""
    x = np.log(values) if log else np.asarray(values, dtype=float)
    if len(x) == 1:
        half = np.array([0.5 if log or x[0] == 0 else 0.5 * abs(x[0])])
    else:
        half = np.diff(x) / 2
    edges = np.concatenate([[x[0] - half[0]], x[:-1] + half[:len(x) - 1], [x[-1] + half[-1]]])
    return np.exp(edges) if log else edges


def cause(failure):
    """The failure without its step: "step 2: foot rotation: ..." -> "foot rotation"."""
    text = failure.split(": ", 1)[1] if failure.startswith("step ") else failure
    return text.split(":")[0].strip() or "failed"


def is_fraction(axis):
    """A unitless sweep of an error (mass_error, length_error): a fraction the tables and docs
    give in percent, so the map does too."""
    return not axis["unit"] and axis["name"].endswith("_error")


def percent_ticks(axis_artist):
    """Tick labels of a fraction in percent (0.05 -> 5)."""
    axis_artist.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{100 * v:g}"))


class Map:
    """One map: its parameters, and its grid of outcomes indexed [a][b]."""

    def __init__(self, result_dir, name, entry):
        path = os.path.join(result_dir, "summary.json")
        self.name = name
        self.a, self.b = read_axis(path, entry, "a"), read_axis(path, entry, "b")
        self.rectangle = entry.get("largest_rectangle_around_nominal")
        csv = os.path.join(result_dir, f"map_{name}.csv")
        cols = plot_io.read_csv(csv, "map", [self.a["name"], self.b["name"]] + OUTCOME_COLUMNS,
                                strings={"fell", "failure"})
        self.a_values = np.unique(cols[self.a["name"]])
        self.b_values = np.unique(cols[self.b["name"]])
        shape = (len(self.a_values), len(self.b_values))
        if shape != (self.a["values"], self.b["values"]):
            raise InputError(f"{csv}: a {shape[0]} x {shape[1]} grid, summary.json says "
                             f"{self.a['values']:g} x {self.b['values']:g}")
        self.steps = np.full(shape, np.nan)
        self.outcome = np.full(shape, "", dtype=object)
        ia = np.searchsorted(self.a_values, cols[self.a["name"]])
        ib = np.searchsorted(self.b_values, cols[self.b["name"]])
        walked = (cols["fell"] == "0") & (cols["steps_completed"] >= cols["steps_requested"])
        for i, j, s, w, f in zip(ia, ib, cols["steps_completed"], walked, cols["failure"]):
            self.steps[i, j] = s
            self.outcome[i, j] = WALKED if w else cause(f)
        self.requested = float(np.max(cols["steps_requested"]))
        self.a_log = is_geometric(self.a, self.a_values)
        self.b_log = is_geometric(self.b, self.b_values)
        self.a_edges = cell_edges(self.a_values, self.a_log)
        self.b_edges = cell_edges(self.b_values, self.b_log)

    def label(self, axis):
        if is_fraction(axis):
            return f"{axis['name'].replace('_', ' ')} [%]"
        return f"{axis['name']} [{axis['unit']}]" if axis["unit"] else axis["name"]

    def grid(self, ax, values, **kw):
        """Draws `values` (indexed [a][b]) as cells between the edges (b across, a up)."""
        return ax.pcolormesh(self.b_edges, self.a_edges, np.ma.masked_invalid(values),
                             shading="flat", **kw)


def layout_under_title(fig, text):
    """The figure's title, wrapped onto as many lines as the figure's width needs (on one line a
    long headline ran off both sides of a one-panel stability.png), and the panels laid out in
    the room below it, whatever its number of lines."""
    title = fig.suptitle(text)
    renderer = fig.canvas.get_renderer()
    room = 0.96 * fig.bbox.width
    width = title.get_window_extent(renderer).width
    if width > room:
        title.set_text(textwrap.fill(text, max(20, int(len(text) * room / width))))
    # The title hangs from y = 0.98 of the figure; the panels start half a line below it.
    title.set_in_layout(False)
    below = title.get_window_extent(renderer).height + 0.5 * title.get_fontsize() * fig.dpi / 72
    fig.tight_layout(rect=(0, 0, 1, title.get_position()[1] - below / fig.bbox.height))
    return title


def mark_nominal_and_rectangle(ax, m):
    ax.plot(m.b["nominal"], m.a["nominal"], "*", color="white", mec="k", ms=14, zorder=4,
            label="nominal")
    r = m.rectangle
    if r:
        # Its cells' own edges: the frame holds exactly the walking cells.
        def span(edges, values, first, last):
            i, k = (int(np.argmin(np.abs(values - v))) for v in (first, last))
            return edges[i], edges[k + 1]
        b0, b1 = span(m.b_edges, m.b_values, r["b_from"], r["b_to"])
        a0, a1 = span(m.a_edges, m.a_values, r["a_from"], r["a_to"])
        ax.add_patch(matplotlib.patches.Rectangle(
            (b0, a0), b1 - b0, a1 - a0, fill=False, ec=style.OK, lw=2.5, zorder=3,
            label=f"walking rectangle around nominal ({r['points']} point"
                  f"{'' if r['points'] == 1 else 's'})"))


def scale_axis(ax, which, axis, values, log):
    """A log scale for a geometric axis; ticks at the grid's values where they are few, so an
    uneven axis shows which values were walked."""
    axis_artist = ax.xaxis if which == "x" else ax.yaxis
    if log:
        (ax.set_xscale if which == "x" else ax.set_yscale)("log")
    if len(values) <= 12:
        axis_artist.set_major_locator(matplotlib.ticker.FixedLocator(values))
        axis_artist.set_minor_locator(matplotlib.ticker.NullLocator())
        axis_artist.set_major_formatter(matplotlib.ticker.FuncFormatter(
            (lambda v, _: f"{v:.4g}") if log else (lambda v, _: f"{v:g}")))
    if is_fraction(axis):
        percent_ticks(axis_artist)


def draw_steps(ax, fig, m):
    image = m.grid(ax, m.steps, cmap="viridis", vmin=0, vmax=m.requested)
    bar = fig.colorbar(image, ax=ax, label="steps completed")
    bar.locator = matplotlib.ticker.MaxNLocator(integer=True)  # steps are whole: no 2.5
    bar.update_ticks()
    mark_nominal_and_rectangle(ax, m)
    ax.legend(fontsize=7, loc="upper right")
    walked = int((m.outcome == WALKED).sum())
    ax.set_title(f"steps completed: {walked} of {m.steps.size} points walk "
                 f"{m.requested:g} steps")


def draw_causes(ax, m):
    causes = sorted({c for c in m.outcome.flat if c != WALKED})
    names = ([WALKED] if (m.outcome == WALKED).any() else []) + causes
    colours = [style.OK if n == WALKED else CAUSE_COLOURS[i % len(CAUSE_COLOURS)]
               for i, n in enumerate(names)]
    index = np.vectorize(names.index)(m.outcome)
    m.grid(ax, index, cmap=matplotlib.colors.ListedColormap(colours), vmin=-0.5,
           vmax=len(names) - 0.5)
    handles = [matplotlib.patches.Patch(color=c, label=n) for n, c in zip(names, colours)]
    mark_nominal_and_rectangle(ax, m)
    ax.legend(handles=handles, fontsize=7, loc="upper right")
    ax.set_title("outcome: walked, or the failure's cause")


def map_figure(m, title):
    fig, axes = plt.subplots(1, 2, figsize=(13.2, 5.4))
    draw_steps(axes[0], fig, m)
    draw_causes(axes[1], m)
    for ax in axes:
        ax.set_xlabel(m.label(m.b) + (" (log scale)" if m.b_log else ""))
        ax.set_ylabel(m.label(m.a) + (" (log scale)" if m.a_log else ""))
        scale_axis(ax, "x", m.b, m.b_values, m.b_log)
        scale_axis(ax, "y", m.a, m.a_values, m.a_log)
    layout_under_title(fig, title)
    return fig


def draw_maps(result_dir, s, title):
    """Writes map_<name>.png for every entry of summary.json's `maps`; returns the paths."""
    paths = []
    for name, entry in s.get("maps", {}).items():
        m = Map(result_dir, name, entry)
        path = os.path.join(result_dir, f"map_{name}.png")
        style.save(map_figure(m, f"{title}: {m.a['name']} x {m.b['name']}"), path)
        paths.append(path)
    return paths


def main(result_dir):
    s = plot_io.read_json(os.path.join(result_dir, "summary.json"), "summary")
    plot_io.require_type(os.path.join(result_dir, "summary.json"), s, "maps", dict,
                         "an object with one entry per map")
    for path in draw_maps(result_dir, s, "Stability map"):
        print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
