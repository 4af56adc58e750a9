#!/usr/bin/python3
"""Draws the 2-D maps of a `gaitopt stability` result folder (called by stability_plots.py).

Usage: map_plots.py RESULT_DIR
Reads RESULT_DIR/summary.json (key `maps`: per map its two parameters `a` and `b` with name,
unit, values, nominal, and the largest walking rectangle around the nominal point) and
RESULT_DIR/map_<a>_<b>.csv, and writes RESULT_DIR/map_<a>_<b>.png per map, printing its path:
two heat maps over the grid, a (rows) against b (columns):
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
    return axis


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

    def label(self, axis):
        if is_fraction(axis):
            return f"{axis['name'].replace('_', ' ')} [%]"
        return f"{axis['name']} [{axis['unit']}]" if axis["unit"] else axis["name"]

    def extent(self):
        """imshow extent with each cell centred on its grid value (b across, a up)."""
        def edges(v):
            h = (v[-1] - v[0]) / (len(v) - 1) / 2
            return v[0] - h, v[-1] + h
        return (*edges(self.b_values), *edges(self.a_values))


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
        hb = (m.b_values[-1] - m.b_values[0]) / (len(m.b_values) - 1) / 2
        ha = (m.a_values[-1] - m.a_values[0]) / (len(m.a_values) - 1) / 2
        ax.add_patch(matplotlib.patches.Rectangle(
            (r["b_from"] - hb, r["a_from"] - ha), r["b_to"] - r["b_from"] + 2 * hb,
            r["a_to"] - r["a_from"] + 2 * ha, fill=False, ec=style.OK, lw=2.5, zorder=3,
            label=f"walking rectangle around nominal ({r['points']} point"
                  f"{'' if r['points'] == 1 else 's'})"))


def draw_steps(ax, fig, m):
    image = ax.imshow(m.steps, origin="lower", aspect="auto", extent=m.extent(),
                      cmap="viridis", vmin=0, vmax=m.requested, interpolation="nearest")
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
    ax.imshow(index, origin="lower", aspect="auto", extent=m.extent(),
              cmap=matplotlib.colors.ListedColormap(colours), vmin=-0.5,
              vmax=len(names) - 0.5, interpolation="nearest")
    handles = [matplotlib.patches.Patch(color=c, label=n) for n, c in zip(names, colours)]
    mark_nominal_and_rectangle(ax, m)
    ax.legend(handles=handles, fontsize=7, loc="upper right")
    ax.set_title("outcome: walked, or the failure's cause")


def map_figure(m, title):
    fig, axes = plt.subplots(1, 2, figsize=(13.2, 5.4))
    draw_steps(axes[0], fig, m)
    draw_causes(axes[1], m)
    for ax in axes:
        ax.set_xlabel(m.label(m.b))
        ax.set_ylabel(m.label(m.a))
        if is_fraction(m.b):
            percent_ticks(ax.xaxis)
        if is_fraction(m.a):
            percent_ticks(ax.yaxis)
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
