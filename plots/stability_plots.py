#!/usr/bin/python3
"""Draws the parameter sweeps and 2-D maps of a `gaitopt stability` result folder.

Usage: stability_plots.py RESULT_DIR
Reads RESULT_DIR/summary.json (key `sweeps`: per swept parameter its unit, number of values,
walking interval walks_from..walks_to around the nominal value, and the nominal value) and one
RESULT_DIR/sweep_<parameter>.csv per parameter, and writes RESULT_DIR/stability.png, printing its
path:
  one panel per sweep: steps completed against the parameter value (green: walked, red: fell),
  the walking interval shaded, the nominal value marked, and the largest Poincare multiplier on
  a twin axis where it was computed (only when the folder has sweeps);
and RESULT_DIR/map_<a>_<b>.png per 2-D map (map_plots.py).
A missing file, column or key, or a malformed value, ends the script with exit code 1.
"""
import math
import os

import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402

import map_plots  # noqa: E402
import plot_io  # noqa: E402
from plot_io import InputError  # noqa: E402

WALK_COLOUR = style.OK
FALL_COLOUR = style.FAIL
MULTIPLIER_COLOUR = style.MULTIPLIER
WALK_SHADE = style.WALK_SHADE
SWEEP_COLUMNS = ["value", "steps_completed", "steps_requested", "fell", "failure",
                 "max_tracking_error", "max_multiplier", "mean_advance", "wall_time_s"]
# Columns that may be empty (not computed, or no completed step).
OPTIONAL_COLUMNS = {"max_multiplier", "max_tracking_error", "mean_advance"}
FELL_TEXTS = {"0": False, "1": True, "false": False, "true": True}
# y-axis tops as a multiple of the data's top, leaving room for the legend above the data.
HEADROOM = 1.55


# ---------------------------------------------------------------------------------------------
# Reading


def read_sweep_entry(path, name, entry):
    """One entry of summary.json's `sweeps`: {unit, values, walks_from, walks_to, nominal}."""
    prefix = f"sweeps.{name}."
    if not isinstance(entry, dict):
        raise InputError(f"{path}: key 'sweeps.{name}': expected an object with unit, values, "
                         f"walks_from, walks_to, nominal")
    plot_io.require_type(path, entry, "unit", str, "a string", prefix)
    if "geometric" in entry:
        plot_io.require_type(path, entry, "geometric", bool, "true or false", prefix)
    plot_io.require_numbers(path, entry, ["values", "nominal"], prefix=prefix)
    plot_io.require_numbers(path, entry, ["walks_from", "walks_to"], nullable=True,
                            prefix=prefix)
    if (entry["walks_from"] is None) != (entry["walks_to"] is None):
        raise InputError(f"{path}: key '{prefix}walks_from'/'walks_to': both numbers or both "
                         f"null")
    return entry


def read_summary(path):
    """summary.json with its `sweeps` object (if any) checked, in the file's order."""
    s = plot_io.read_json(path, "summary")
    if "sweeps" not in s and "maps" in s:
        s["sweeps"] = {}
    plot_io.require_type(path, s, "sweeps", dict, "an object with one entry per swept parameter")
    if not s["sweeps"] and not s.get("maps"):
        raise InputError(f"{path}: key 'sweeps': no swept parameter")
    for name, entry in s["sweeps"].items():
        read_sweep_entry(path, name, entry)
    return s


def read_sweep(path, expected_rows):
    """sweep_<parameter>.csv: name -> array (fell as bool, failure as text), sorted by value."""
    cols = plot_io.read_csv(path, "sweep", SWEEP_COLUMNS, strings={"fell", "failure"},
                            optional=OPTIONAL_COLUMNS, finite=False)
    for name in ("value", "steps_completed", "steps_requested"):
        bad = ~np.isfinite(cols[name])
        if bad.any():
            raise InputError(f"{path}:{int(np.argmax(bad)) + 2}: column '{name}': expected a "
                             f"finite number")
    fell = np.char.lower(cols["fell"])
    plot_io.check_values(path, "fell", fell, tuple(FELL_TEXTS))
    cols["fell"] = np.array([FELL_TEXTS[f] for f in fell], dtype=bool)
    if len(cols["value"]) != expected_rows:
        raise InputError(f"{path}: {len(cols['value'])} rows, summary.json says "
                         f"{expected_rows:g} values")
    order = np.argsort(cols["value"], kind="stable")
    return {name: v[order] for name, v in cols.items()}


class Sweep:
    """One swept parameter: its summary entry and its rows."""

    def __init__(self, result_dir, name, entry):
        self.name = name
        self.unit = entry["unit"]
        # A model error is a fraction, drawn and worded in percent as the maps and docs give it.
        self.fraction = map_plots.is_fraction({"name": name, "unit": self.unit})
        self.geometric = entry.get("geometric")  # None in summaries written before the key
        self.nominal = entry["nominal"]
        self.walks = (None if entry["walks_from"] is None
                      else (entry["walks_from"], entry["walks_to"]))
        self.col = read_sweep(os.path.join(result_dir, f"sweep_{name}.csv"), entry["values"])
        self.value = self.col["value"]
        self.walked = ~self.col["fell"] & (self.col["steps_completed"]
                                           >= self.col["steps_requested"])

    def log_spaced(self):
        """True for a geometric sweep (the ground stiffness), drawn on a log axis: summary.json's
        `geometric`, which holds where the nominal inserted breaks the constant ratio (a pad's
        3e5 in 1e5:1e7:3); in summaries written before it, positive values with a constant
        ratio."""
        v = self.value
        if np.any(v <= 0):
            return False
        if self.geometric is not None:
            return self.geometric
        if len(v) < 3:
            return False
        ratios = v[1:] / v[:-1]
        return bool(np.all(ratios > 1.5) and np.ptp(np.log(ratios)) < 1e-6 * np.log(ratios[0]) + 1e-9)

    def interval_text(self):
        """The walking interval in words: empty, a single value, or from .. to."""
        if self.walks is None:
            if not self.walked.any():
                return f"falls at every tested value ({len(self.value)} values)"
            v = self.value[self.walked]
            span = self.format(v[0]) if len(v) == 1 else (f"{self.number(v[0])} .. "
                                                             f"{self.format(v[-1])}")
            return (f"falls at the nominal {self.format(self.nominal)}; walks at {len(v)} of "
                    f"{len(self.value)} values ({span})")
        lo, hi = self.walks
        if hi == lo:
            where = "the nominal value" if lo == self.nominal else "one value"
            text = f"walks only at {where} {self.format(lo)}"
        else:
            text = f"walks from {self.format(lo)} to {self.format(hi)}"
        return text + self.beyond_text()

    def beyond_text(self):
        """The walked values the interval around the nominal does not reach, if any: a sweep
        can walk again past the values it fell at."""
        lo, hi = self.walks
        v = self.value[self.walked & ((self.value < lo) | (self.value > hi))]
        if len(v) == 0:
            return ""
        span = self.format(v[0]) if len(v) == 1 else f"{self.number(v[0])} .. {self.format(v[-1])}"
        return f"; beyond the falls it walks at {len(v)} more ({span})"

    def label(self):
        """Axis label: the parameter and its unit."""
        if self.fraction:
            return f"{self.name.replace('_', ' ')} [%]"
        return f"{self.name} [{self.unit}]" if self.unit else self.name

    def number(self, x):
        """A value as the axis shows it (a fraction in percent: 0.05 -> 5)."""
        return f"{100 * x:g}" if self.fraction else f"{x:g}"

    def format(self, x):
        return f"{self.number(x)} {'%' if self.fraction else self.unit}".rstrip()


def read_sweeps(result_dir):
    """(summary, [Sweep]) of the folder."""
    s = read_summary(os.path.join(result_dir, "summary.json"))
    return s, [Sweep(result_dir, name, entry) for name, entry in s["sweeps"].items()]


# ---------------------------------------------------------------------------------------------
# Panels


def draw_multiplier(ax, sw):
    """Largest Poincare multiplier on a twin axis, where computed; |lambda| = 1 dotted.
    Returns the twin axes or None when no value was computed."""
    m = sw.col["max_multiplier"]
    have = np.isfinite(m)
    if not have.any():
        return None
    twin = ax.twinx()
    twin.plot(sw.value[have], m[have], "s-", color=MULTIPLIER_COLOUR, ms=4, lw=1,
              label="max |multiplier|")
    twin.axhline(1, color=MULTIPLIER_COLOUR, ls=":", lw=1, label="|multiplier| = 1")
    twin.set_ylim(0, HEADROOM * max(1.1, 1.05 * np.max(m[have])))
    twin.set_ylabel("max |Poincaré multiplier|", color=MULTIPLIER_COLOUR)
    twin.tick_params(axis="y", colors=MULTIPLIER_COLOUR)
    return twin


def draw_sweep(ax, sw):
    """Steps completed against the value (green walked all requested steps, red fell), the
    requested steps dashed, the walking interval shaded, the nominal value marked."""
    if sw.walks is not None:
        lo, hi = sw.walks
        ax.axvspan(lo, hi, **WALK_SHADE,
                   label=f"walks: {sw.format(lo)} .. {sw.format(hi)}" if hi > lo
                   else f"walks only at {sw.format(lo)}")
        if hi == lo:
            ax.axvline(lo, color=WALK_COLOUR, lw=3, alpha=0.3)
    ax.plot(sw.value, sw.col["steps_completed"], color="0.6", lw=1)
    for pick, colour, label in ((sw.walked, WALK_COLOUR, "walked"),
                                (~sw.walked, FALL_COLOUR, "fell")):
        if pick.any():
            ax.plot(sw.value[pick], sw.col["steps_completed"][pick], "o", color=colour, ms=6,
                    label=label, zorder=3)
    requested = np.max(sw.col["steps_requested"])
    ax.axhline(requested, color="k", ls="--", lw=0.8, label=f"requested {requested:g}")
    ax.axvline(sw.nominal, color="k", lw=1.2, label=f"nominal {sw.format(sw.nominal)}")
    ax.set_ylim(-0.05 * requested, HEADROOM * requested)
    ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.set_yticks([t for t in ax.get_yticks() if 0 <= t <= requested])
    twin = draw_multiplier(ax, sw)
    handles, labels = ax.get_legend_handles_labels()
    if twin is not None:
        more = twin.get_legend_handles_labels()
        handles, labels = handles + more[0], labels + more[1]
    (twin or ax).legend(handles, labels, fontsize=7, loc="upper center", ncol=3)
    if sw.log_spaced():
        ax.set_xscale("log")
    if sw.fraction:
        map_plots.percent_ticks(ax.xaxis)
    ax.set_xlabel(sw.label() + (" (log scale)" if sw.log_spaced() else ""))
    ax.set_ylabel("steps completed")
    ax.set_title(f"{sw.name}: {sw.interval_text()}")
    ax.grid(True, alpha=0.4)


# ---------------------------------------------------------------------------------------------
# Picture


def headline(s):
    """What was swept around, from the summary keys that are present: the gait (the reference
    folder's name), the controller with its bandwidth factor and CoP rule where they are not the
    defaults (two sweeps of one gait must not share a title), the robot and the ground."""
    parts = []
    if isinstance(s.get("reference"), str):
        parts.append(f"gait {os.path.basename(s['reference'].rstrip('/'))}")
    if isinstance(s.get("controller"), str):
        gain = s.get("gain_scale")
        parts.append(f"{s['controller']} controller"
                     + (f" at {gain:g} x its gains" if plot_io.is_number(gain) and gain != 1 else ""))
    rules = s.get("contact_rules")
    if isinstance(rules, dict) and isinstance(rules.get("cop_limit"), str):
        parts.append(f"CoP limit: {rules['cop_limit']}")
    if isinstance(s.get("robot"), str):
        parts.append(s["robot"])
    if isinstance(s.get("ground"), str):
        parts.append(f"{s['ground']} ground")
    steps = s.get("steps_requested")
    tail = f" ({steps:g} steps per run)" if plot_io.is_number(steps) else ""
    return "Stability sweeps" + (f": {', '.join(parts)}" if parts else "") + tail


def stability_figure(s, sweeps):
    """One panel per sweep, two columns when there are several."""
    cols = 1 if len(sweeps) == 1 else 2
    rows = math.ceil(len(sweeps) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(6.6 * cols, 4.4 * rows), squeeze=False)
    for ax, sw in zip(axes.flat, sweeps):
        draw_sweep(ax, sw)
    for ax in axes.flat[len(sweeps):]:
        ax.set_visible(False)
    map_plots.layout_under_title(fig, headline(s))
    return fig


def main(result_dir):
    s, sweeps = read_sweeps(result_dir)
    if sweeps:
        path = os.path.join(result_dir, "stability.png")
        style.save(stability_figure(s, sweeps), path)
        print(path)
    title = headline(s).replace("Stability sweeps", "Stability map", 1)
    for path in map_plots.draw_maps(result_dir, s, title):
        print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
