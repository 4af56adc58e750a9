#!/usr/bin/python3
"""Cost against robustness of the strike study (configs/studies/strike_study.yaml).

Usage: strike_study_chart.py STUDY_DIR OUT_DIR
       strike_study_chart.py --redraw OUT_DIR
STUDY_DIR is the folder `gaitopt study` wrote: solves.csv (one row per variant: the
friction_margin, zmp_margin and strike_velocity labels and the run's folder), runs/FOLDER
(summary.json of `gaitopt optimize`; none after a failed solve) and one `gaitopt stability`
folder per variant and controller, stability/FOLDER/0_<controller>/summary.json with the push
and mass_error sweeps. Writes, printing their paths:
  OUT_DIR/strike_study.csv  one row per variant and controller: strike velocity, margins, cost,
                            the optimum's ZMP margin and friction ratio, the walking intervals
                            (empty when the walk fails at nominal) and the failures beside them
                            (at nominal: the sweep's nominal_failure in summary.json)
  OUT_DIR/strike_study.md   one row per variant: cost, then push and mass intervals per controller
  OUT_DIR/strike_study.png  cost against the widest push interval (left) and the widest mass
                            interval (right) over the controllers, one point per variant: colour
                            the strike velocity, marker the margins
--redraw draws OUT_DIR/strike_study.png again from OUT_DIR/strike_study.csv alone (the study's
runs/ and stability/ folders are not kept in results/).
A missing or malformed summary ends the script with "error: <file>: ..." and exit code 1.
"""
import csv
import os
import sys

import plot_io
import plot_style as style
from plot_io import InputError

AXES = ["strike_velocity", "friction_margin", "zmp_margin"]
CONTROLLERS = ["computed_torque", "sliding_mode", "mu_sliding_mode"]
# Sweep name in summary.json: (column prefix, scale to the table's unit, unit).
SWEEPS = {"push": ("push", 1.0, "N s"), "mass_error": ("mass", 100.0, "%")}
# A variant falling at nominal sits this fraction of the axis's widest interval left of 0.
FALLS_FRACTION = 0.12
MARKERS = ["o", "s", "D", "^", "v", "P", "*", "h"]
FIELDS = ["variant", "strike_velocity", "friction_margin", "zmp_margin", "status", "cost",
          "min_zmp_margin", "max_friction_ratio", "controller", "push_from", "push_to",
          "mass_from", "mass_to", "push_fails", "mass_fails"]


def sweep_cells(path, s, sweep):
    """(from, to, failures) of one sweep, from and to None without a walking interval."""
    plot_io.require_keys(path, s, ["sweeps"])
    if sweep not in s["sweeps"]:
        raise InputError(f"{path}: missing sweep '{sweep}'")
    w = s["sweeps"][sweep]
    unit = SWEEPS[sweep][1]
    fails = [f"{w[k]['value'] * unit:g}: {w[k]['failure']}"
             for k in ("fails_below", "fails_above") if k in w]
    if w.get("walks_from") is None:
        plot_io.require_keys(path, w, ["nominal_failure"])
        fails = [f"at nominal: {w['nominal_failure']}"]
    scale = lambda x: None if x is None else x * unit
    return scale(w.get("walks_from")), scale(w.get("walks_to")), "; ".join(fails)


def variant_rows(study, variant):
    """The CSV rows of one variant: one per controller swept, one without controller when the
    solve failed."""
    name = variant["folder"]
    v, f, z = (variant[axis] for axis in AXES)
    row = {"variant": f"v{v:g}_f{f:g}_z{z:g}", **{axis: variant[axis] for axis in AXES}}
    gait = os.path.join(study, "runs", name, "summary.json")
    if not os.path.exists(gait):
        return [dict(row, status="solve failed")]
    g = plot_io.read_json(gait)
    plot_io.require_numbers(gait, g, ["cost", "min_zmp_margin"])
    # null: some normal force reached 0 between the nodes (the ratio is unbounded)
    plot_io.require_numbers(gait, g, ["max_friction_ratio"], nullable=True)
    row.update(status=g.get("status", ""), cost=g["cost"], min_zmp_margin=g["min_zmp_margin"],
               max_friction_ratio=g["max_friction_ratio"])
    rows = []
    for c in CONTROLLERS:
        path = os.path.join(study, "stability", name, f"0_{c}", "summary.json")
        if not os.path.exists(path):
            continue
        s = plot_io.read_json(path)
        push = sweep_cells(path, s, "push")
        mass = sweep_cells(path, s, "mass_error")
        rows.append(dict(row, controller=c, push_from=push[0], push_to=push[1], mass_from=mass[0],
                         mass_to=mass[1], push_fails=push[2], mass_fails=mass[2]))
    return rows


def read_study(study):
    """Every variant's rows, by strike velocity, friction margin, ZMP margin."""
    path = os.path.join(study, "solves.csv")
    header, rows = plot_io.read_rows(path, "study solve table")
    plot_io.require_columns(path, header, [*AXES, "folder"])
    variants = []
    for line, r in enumerate(rows, start=2):
        v = dict(zip(header, r))
        try:
            variants.append({**v, **{axis: float(v[axis]) for axis in AXES}})
        except ValueError as e:
            raise InputError(f"{path}: line {line}: {e}") from None
    variants.sort(key=lambda v: tuple(v[axis] for axis in AXES))
    return [r for v in variants for r in variant_rows(study, v)]


def read_table(path):
    """The rows write_csv wrote, as read_study returns them: an empty cell is a missing key
    (a failed solve has no cost, a variant not swept no controller) or None for an interval."""
    header, lines = plot_io.read_rows(path, "strike study table")
    plot_io.require_columns(path, header, FIELDS)
    numbers = set(AXES) | {"cost", "min_zmp_margin", "max_friction_ratio"}
    bounds = {"push_from", "push_to", "mass_from", "mass_to"}
    rows = []
    for line, cells in enumerate(lines, start=2):
        r = {}
        try:
            for name, text in zip(header, cells):
                if name in bounds:
                    r[name] = float(text) if text else None
                elif text:
                    r[name] = float(text) if name in numbers else text
        except ValueError as e:
            raise InputError(f"{path}: line {line}: {e}") from None
        rows.append(r)
    return rows


def width(r, column):
    """Length of a walking interval, None when the walk fails at nominal."""
    lo, hi = r.get(f"{column}_from"), r.get(f"{column}_to")
    return None if lo is None else hi - lo


def widest(rs, column):
    """The widest walking interval of a variant over its controllers, None when every one
    fails at nominal (a fall is not an interval of 0: that is a gait walking the nominal only)."""
    walked = [w for w in (width(x, column) for x in rs if "controller" in x) if w is not None]
    return max(walked, default=None)


def falls_x(widths):
    """Where a variant that falls at nominal is drawn: left of 0 by FALLS_FRACTION of the
    widest interval drawn (of 5 units, the empty axis's width, when none is wider than 0)."""
    return -FALLS_FRACTION * (max([w for w in widths if w is not None] + [0]) or 5.0)


def interval(r, column):
    """'from .. to' of a walking interval, 'fails' when the walk fails at nominal."""
    lo, hi = r.get(f"{column}_from"), r.get(f"{column}_to")
    return "fails" if lo is None else f"{lo:g} .. {hi:g}"


def write_csv(rows, path):
    with style.replacing(path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, FIELDS)
        w.writeheader()
        for r in rows:
            w.writerow({k: ("" if r.get(k) is None else r[k]) for k in FIELDS})


def by_variant(rows):
    variants = {}
    for r in rows:
        variants.setdefault(r["variant"], []).append(r)
    return variants


def write_markdown(rows, path):
    controllers = [c for c in CONTROLLERS if any(r.get("controller") == c for r in rows)]
    head = ["strike v [m/s]", "friction margin", "ZMP margin [m]", "cost"]
    for c in controllers:
        head += [f"push [N s], {c}", f"mass [%], {c}"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for rs in by_variant(rows).values():
        r = rs[0]
        cells = [f"{r['strike_velocity']:g}", f"{r['friction_margin']:g}",
                 f"{r['zmp_margin']:g}", "solve failed" if "cost" not in r else f"{r['cost']:.2f}"]
        swept = {x["controller"]: x for x in rs if "controller" in x}
        for c in controllers:
            x = swept.get(c)
            cells += [interval(x, "push"), interval(x, "mass")] if x else ["", ""]
        lines.append("| " + " | ".join(cells) + " |")
    with style.replacing(path) as tmp, open(tmp, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def chart(rows, path):
    """Cost against the widest interval over the controllers, one point per variant."""
    plt = style.pyplot()
    from matplotlib.ticker import NullFormatter
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), sharey=True)
    solved = [rs for rs in by_variant(rows).values() if "cost" in rs[0]]
    velocities = sorted({rs[0]["strike_velocity"] for rs in solved})
    margins = sorted({(rs[0]["friction_margin"], rs[0]["zmp_margin"]) for rs in solved})
    cmap = plt.cm.viridis
    for ax, (sweep, (column, _, unit)) in zip(axes, SWEEPS.items()):
        widths = [widest(rs, column) for rs in solved]
        falls = falls_x(widths)
        for rs, w in zip(solved, widths):
            r = rs[0]
            k = margins.index((r["friction_margin"], r["zmp_margin"]))
            colour = cmap(velocities.index(r["strike_velocity"]) / max(len(velocities) - 1, 1))
            ax.scatter(falls if w is None else w, r["cost"], color=colour,
                       marker=MARKERS[k % len(MARKERS)], s=46, edgecolor="0.2", lw=0.5)
        ax.set_yscale("log")
        ax.set_yticks([100, 200, 500, 1000, 2000], ["100", "200", "500", "1000", "2000"])
        ax.yaxis.set_minor_formatter(NullFormatter())  # no "6x10^2" between
        if not any(widths):  # an axis of one value would centre it on a range of nothing
            ax.set_xlim(2 * falls, 5)
            what = sweep.replace("_", " ")
            ax.text(0.97, 0.97, f"no variant walks a {what} but the nominal one",
                    transform=ax.transAxes, ha="right", va="top", fontsize=8)  # off the points
        if any(w is None for w in widths):
            style.falls_column(ax, falls)
        style.finish(ax, f"widest walking {sweep} interval over the controllers [{unit}]",
                     "cost of the optimum [N² m² s]", legend=False)
    for v in velocities:
        axes[0].scatter([], [], color=cmap(velocities.index(v) / max(len(velocities) - 1, 1)),
                        marker="o", label=f"strike {v:g} m/s")
    for k, (fm, zm) in enumerate(margins):
        axes[1].scatter([], [], color="0.6", marker=MARKERS[k % len(MARKERS)],
                        label=f"friction margin {fm:g}, ZMP margin {zm:g} m")
    for ax in axes:  # below the axes: the points fill every corner
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, fontsize=8)
    fig.suptitle("Cost against robustness: five-link optimum (mu2004_walk), 20 steps per point")
    fig.tight_layout()
    style.save(fig, path)


def main(args):
    if args[0] == "--redraw":
        png = os.path.join(args[1], "strike_study.png")
        chart(read_table(os.path.join(args[1], "strike_study.csv")), png)
        print(png)
        return
    work, out = args
    rows = read_study(work)
    os.makedirs(out, exist_ok=True)
    paths = [os.path.join(out, f"strike_study.{ext}") for ext in ("csv", "md", "png")]
    write_csv(rows, paths[0])
    write_markdown(rows, paths[1])
    chart(rows, paths[2])
    print("\n".join(paths))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    try:
        main(sys.argv[1:])
    except InputError as e:
        sys.exit(f"error: {e}")
