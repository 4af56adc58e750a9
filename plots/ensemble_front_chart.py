#!/usr/bin/python3
"""The cost-robustness front of the gait designed with model variants
(configs/studies/ensemble_front.yaml).

Usage: ensemble_front_chart.py STUDY_DIR DEFAULT_GAIT_DIR
STUDY_DIR is the folder `gaitopt study` wrote: solves.csv (width_percent, the ensemble width W
[%], then converged, cost and the posture in degrees) and walks.csv (width_percent, walk: the
ground, controller, plant: the mass error, steps, ...); DEFAULT_GAIT_DIR holds the default
optimum (summary.json's cost). Writes into STUDY_DIR, printing their paths:
  OUT_DIR/front.csv  one row per width: convergence, cost, its ratio to the default optimum's,
                     posture (degrees) and, per ground and controller, the plant-mass interval
                     walked 20 steps without a gap around the nominal (empty when the nominal fails)
  OUT_DIR/front.md   the same as a table
  OUT_DIR/front.png  cost ratio against the width of each interval, one line per ground and
                     controller, the points labelled with the ensemble width; a gait that
                     falls on the nominal plant left of the intervals, under "falls at ×1";
                     an open marker where the interval reaches the end of its ground's sweep
                     (the legend gives each ground's range)
A missing or malformed input ends the script with "error: <file>: ..." and exit code 1.
"""
import os

import plot_io
import plot_style as style
from plot_io import InputError

GROUNDS = ["rigid", "lcp", "dart"]
CONTROLLERS = {"computed_torque": "computed torque", "mu_sliding_mode": "Mu's sliding mode"}
POSTURE = ["max_torso_lean", "max_stance_knee_flexion", "max_swing_knee_flexion"]
WALK_COLUMNS = ["width_percent", "walk", "controller", "plant", "steps"]


def interval(walks):
    """(lowest, highest) plant mass of the run of 20-step walks that holds 1.0, or None."""
    masses = sorted(walks)
    if 1.0 not in walks or walks[1.0] < 20:
        return None
    i = j = masses.index(1.0)
    while i > 0 and walks[masses[i - 1]] == 20:
        i -= 1
    while j + 1 < len(masses) and walks[masses[j + 1]] == 20:
        j += 1
    return masses[i], masses[j]


def cut_by_sweep(walked, masses):
    """True when an interval reaches the lowest or highest plant swept: the sweep, not a fall,
    ends it there, so its true width is unknown (at least the one drawn)."""
    return walked is not None and (walked[0] == min(masses) or walked[1] == max(masses))


def sweep_ranges(walks):
    """{ground: (lowest, highest) plant mass swept} over every width and controller: the
    grounds are swept over different ranges (rigid ±0.2, LCP and DART ±0.1 in the shipped
    study), so equal widths are not equally robust."""
    ranges = {}
    for (_, ground, _), masses in walks.items():
        lo, hi = ranges.get(ground, (min(masses), max(masses)))
        ranges[ground] = (min(lo, *masses), max(hi, *masses))
    return ranges


def plant_mass(error):
    """The plant's mass scale of a mass-error column value."""
    return round(1 + error, 6)


def read_walks(path, first="width_percent", first_of=int, plant_of=plant_mass):
    """{(first column, walk, controller): {plant_of(plant): steps}} of a study's walks.csv:
    by default {(width, ground, controller): {plant mass: steps}}."""
    header, rows = plot_io.read_rows(path, "walk table")
    plot_io.require_columns(path, header, [first, *WALK_COLUMNS[1:]])
    col = {name: header.index(name) for name in header}
    walks = {}
    for line, row in enumerate(rows, start=2):
        try:
            key = (first_of(row[col[first]]), row[col["walk"]], row[col["controller"]])
            plant = plant_of(float(row[col["plant"]]))
            walks.setdefault(key, {})[plant] = int(row[col["steps"]] or 0)
        except (ValueError, IndexError) as e:
            raise InputError(f"{path}: line {line}: {e}") from None
    return walks


def read_solves(path):
    """{width: {converged, cost, posture...}}"""
    header, rows = plot_io.read_rows(path, "solve table")
    posture = [f"{k}_deg" for k in POSTURE]
    plot_io.require_columns(path, header, ["width_percent", "converged", "cost", *posture])
    col = {name: header.index(name) for name in header}
    widths = {}
    for line, row in enumerate(rows, start=2):
        try:
            s = {"converged": row[col["converged"]] == "1", "cost": float(row[col["cost"]])}
            s.update({k: float(row[col[f"{k}_deg"]]) if row[col[f"{k}_deg"]] else None
                      for k in POSTURE})
            widths[int(row[col["width_percent"]])] = s
        except (ValueError, IndexError) as e:
            raise InputError(f"{path}: line {line}: {e}") from None
    return dict(sorted(widths.items()))


def default_cost(folder):
    path = os.path.join(folder, "summary.json")
    summary = plot_io.read_json(path)
    plot_io.require_numbers(path, summary, ["cost"])
    return summary["cost"]


def rows_of(widths, walks, default_cost):
    rows = []
    for width, s in widths.items():
        row = {"width_percent": width, "converged": s["converged"], "cost": s["cost"],
               "cost_ratio": s["cost"] / default_cost}
        row.update({k: s[k] for k in POSTURE})
        for ground in GROUNDS:
            for controller in CONTROLLERS:
                masses = walks.get((width, ground, controller), {})
                row[(ground, controller)] = interval(masses)
                row[(ground, controller, "cut")] = cut_by_sweep(row[(ground, controller)], masses)
        rows.append(row)
    return rows


def fmt_interval(i):
    if i is None:
        return ""
    return f"{i[0]:g} only" if i[0] == i[1] else f"{i[0]:g}-{i[1]:g}"


def write_tables(rows, out):
    keys = [(g, c) for g in GROUNDS for c in CONTROLLERS]
    names = [f"{g}_{c}" for g, c in keys]
    with style.replacing(os.path.join(out, "front.csv")) as tmp, open(tmp, "w") as f:
        f.write(",".join(["width_percent", "converged", "cost", "cost_ratio", *POSTURE, *names])
                + "\n")
        for r in rows:
            posture = ["" if r[k] is None else f"{r[k]:.3g}" for k in POSTURE]
            f.write(",".join([str(r["width_percent"]), str(int(r["converged"])), f"{r['cost']:.6g}",
                              f"{r['cost_ratio']:.4g}", *posture,
                              *[fmt_interval(r[k]) for k in keys]]) + "\n")
    with style.replacing(os.path.join(out, "front.md")) as tmp, open(tmp, "w") as f:
        f.write("| width W % | cost (× default) | torso, stance knee, swing knee [deg] | "
                + " | ".join(f"{g}: {CONTROLLERS[c]}" for g, c in keys) + " |\n")
        f.write("|---|---|---|" + "---|" * len(keys) + "\n")
        for r in rows:
            posture = ", ".join("—" if r[k] is None else f"{r[k]:.1f}" for k in POSTURE)
            cost = f"{r['cost']:.1f} ({r['cost_ratio']:.2f})" + ("" if r["converged"] else
                                                                 ", not converged")
            cells = [fmt_interval(r[k]) or "falls at ×1" for k in keys]
            f.write(f"| {r['width_percent']} | {cost} | {posture} | " + " | ".join(cells) + " |\n")


# Where a gait that falls on the nominal plant is drawn: left of the intervals, apart from a
# gait that walks the nominal plant only (an interval of width 0).
FALLS_AT = -0.06
# Marker sizes by ground, largest first, so that coinciding points of several grounds all show.
MARKER_SIZES = [9, 6.5, 4]


def front_points(rows, ground, controller):
    """[(interval width or FALLS_AT, cost ratio, ensemble width W)] of the converged widths."""
    points = []
    for r in rows:
        if r["converged"]:
            walked = r[(ground, controller)]
            points.append((FALLS_AT if walked is None else walked[1] - walked[0],
                           r["cost_ratio"], r["width_percent"]))
    return points


def cut_points(rows, ground, controller):
    """[(interval width, cost ratio)] of the converged widths whose interval the sweep cuts."""
    return [(r[(ground, controller)][1] - r[(ground, controller)][0], r["cost_ratio"])
            for r in rows if r["converged"] and r.get((ground, controller, "cut"))]


def label_points(ax, points):
    """One label per place (cost ratios equal to 0.01 share one), naming every ensemble width
    drawn there ("W=5, 10")."""
    at = {}
    for x, y, width in points:
        at.setdefault((x, round(y, 2)), []).append((y, width))
    for (x, _), drawn in at.items():
        text = "W=" + ", ".join(str(w) for w in sorted({w for _, w in drawn}))
        ax.annotate(text, (x, max(y for y, _ in drawn)), fontsize=7, xytext=(5, 3),
                    textcoords="offset points")


def ground_label(ground, ranges):
    """The legend's name of a ground with the plant masses it was swept over."""
    if ground not in ranges:
        return ground
    lo, hi = ranges[ground]
    return f"{ground} (swept ×{lo:g}–{hi:g})"


def draw(rows, path, ranges=None):
    plt = style.pyplot()
    ranges = ranges or {}
    fig, axes = plt.subplots(1, len(CONTROLLERS), figsize=(9, 4.6), sharey=True)
    for ax, (controller, label) in zip(axes, CONTROLLERS.items()):
        drawn = []
        for ground, marker, size in zip(GROUNDS, "osD", MARKER_SIZES):
            points = front_points(rows, ground, controller)
            line, = ax.plot([p[0] for p in points], [p[1] for p in points], marker=marker,
                            markersize=size, label=ground_label(ground, ranges))
            cut = cut_points(rows, ground, controller)
            # Open markers: the interval is at least this wide, the sweep ended it.
            ax.plot([p[0] for p in cut], [p[1] for p in cut], ls="none", marker=marker,
                    markersize=size, color=line.get_color(), markerfacecolor="white")
            drawn += points
        label_points(ax, drawn)
        style.falls_column(ax, FALLS_AT)
        style.finish(ax, "plant-mass interval walked 20 steps (width)", "cost / default optimum's",
                     title=label, legend=False)
    handles, labels = axes[0].get_legend_handles_labels()
    handles.append(axes[0].plot([], [], ls="none", marker="o", color="0.3",
                                markerfacecolor="white")[0])
    labels.append("open: reaches the end of its sweep (cut off by it)")
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=8)
    fig.suptitle("Ensemble widths: cost against the mass interval walked "
                 "(points: ensemble width W %)", fontsize=9)
    fig.tight_layout(rect=(0, 0.13, 1, 1))
    style.save(fig, path)


def main(out, default_gait):
    widths = read_solves(os.path.join(out, "solves.csv"))
    walks = read_walks(os.path.join(out, "walks.csv"))
    rows = rows_of(widths, walks, default_cost(default_gait))
    write_tables(rows, out)
    draw(rows, os.path.join(out, "front.png"), sweep_ranges(walks))
    for name in ("front.csv", "front.md", "front.png"):
        print(os.path.join(out, name))


if __name__ == "__main__":
    plot_io.run_main(main, __doc__, arguments=2)
