#!/usr/bin/python3
"""What each gait of a study costs and walks, over the walk battery of the studies
configs/studies/strike_cost.yaml, ensemble_candidates.yaml, sensitivity_penalty.yaml,
ensemble_export.yaml and ensemble_walks.yaml (walk
blocks rigid, rigid_length, rigid_push, rigid_cases, lcp, dart; any of them may be missing).

Usage: walk_battery_table.py STUDY_DIR
STUDY_DIR is the folder `gaitopt study` wrote: solves.csv (gait, converged, cost,
strike_normal_velocity_m_s, impulse_trailing_cone_ratio) and walks.csv (gait, walk, controller,
plant_option, plant, steps). Writes into STUDY_DIR, printing their paths:
  summary.csv  one row per gait (per value of the last axis when the study has axes; its
               label names the row): convergence, cost, strike speed [m/s], the trailing impulse's
               |P_t| / P_n and, per controller, the plant-mass interval walked 20 steps on the
               rigid ground around the nominal, the length errors, pushes [N s] and Mu's cases
               walked, and the plant masses walked on the LCP ground and in DART (per
               controller of CONTROLLERS that the walks hold)
  summary.md   the same as a table
A missing or malformed input ends the script with "error: <file>: ..." and exit code 1.
"""
import os

import plot_io
import plot_style as style
from ensemble_front_chart import fmt_interval, interval, plant_mass, read_walks
from plot_io import InputError

# Every controller a battery may walk, in the table's order; a table has those its walks hold.
CONTROLLERS = {"computed_torque": "CT", "computed_torque_plan_dsp": "CT plan DSP",
               "mu_sliding_mode": "Mu", "mu_sliding_mode_plan_dsp": "Mu plan DSP"}
SOLVE_COLUMNS = ["gait", "converged", "cost", "strike_normal_velocity_m_s",
                 "impulse_trailing_cone_ratio"]
# (column name, walk block of the study, what the plant value is): the walks listed as values.
LISTED = [("lengths", "rigid_length", "length-error"), ("pushes", "rigid_push", "push"),
          ("cases", "rigid_cases", "uncertainty-case"), ("lcp", "lcp", "mass-error"),
          ("dart", "dart", "mass-error")]


def optional_number(text):
    return float(text) if text else None


def optional_text(value, spec):
    return "" if value is None else format(value, spec)


def label_column(header):
    """The column that names a row: the study's last axis when it has axes (its columns sit
    between gait and status), else gait."""
    return header[header.index("status") - 1] if "status" in header else "gait"


def read_solves(path):
    """(the label column, [(row label, {converged, cost, speed, ratio})] in the study's order)."""
    header, rows = plot_io.read_rows(path, "solve table")
    plot_io.require_columns(path, header, SOLVE_COLUMNS)
    col = {name: header.index(name) for name in header}
    label = label_column(header)
    out = []
    for line, row in enumerate(rows, start=2):
        try:
            speed, ratio = (optional_number(row[col[n]]) for n in SOLVE_COLUMNS[3:])
            out.append((row[col[label]], {"converged": row[col["converged"]] == "1",
                                           "cost": float(row[col["cost"]]),
                                           "speed": speed, "ratio": ratio}))
        except (ValueError, IndexError) as e:
            raise InputError(f"{path}: line {line}: {e}") from None
    return label, out


def walked(values):
    """The plant values walked 20 steps, as text: "-1 1 2", or "none"."""
    return " ".join(f"{v:g}" for v in sorted(values) if values[v] == 20) or "none"


def cells(gait, walks, controller):
    """The walk columns of one gait and controller, in the table's order."""
    rigid = walks.get((gait, "rigid", controller))
    masses = {plant_mass(m): s for m, s in (rigid or {}).items()}
    out = ["—" if rigid is None else fmt_interval(interval(masses)) or "falls at ×1"]
    for _, walk, _ in LISTED:
        values = walks.get((gait, walk, controller))
        if walk in ("lcp", "dart") and values is not None:
            values = {plant_mass(m): s for m, s in values.items()}
        out.append("—" if values is None else walked(values))
    return out


def walked_controllers(walks):
    """The controllers of CONTROLLERS that walk in `walks`, in the table's order."""
    present = {controller for _, _, controller in walks}
    return [c for c in CONTROLLERS if c in present]


def walk_columns(controllers):
    """(controller label, column name) of every walk column, in the table's order."""
    names = ["rigid_mass", *[name for name, _, _ in LISTED]]
    return [(CONTROLLERS[c], n) for c in controllers for n in names]


def write_tables(solves, walks, out):
    controllers = walked_controllers(walks)
    columns = walk_columns(controllers)
    walk_cells = {gait: [c for controller in controllers for c in cells(gait, walks, controller)]
                  for gait, _ in solves}
    csv_path, md_path = os.path.join(out, "summary.csv"), os.path.join(out, "summary.md")
    with style.replacing(csv_path) as tmp, open(tmp, "w", encoding="utf-8") as f:
        f.write(",".join(["gait", "converged", "cost", "strike_normal_velocity_m_s",
                          "impulse_trailing_cone_ratio",
                          *[f"{c.replace(' ', '_')}_{n}" for c, n in columns]])
                + "\n")
        for gait, s in solves:
            row = [gait, str(int(s["converged"])), f"{s['cost']:.6g}",
                   optional_text(s["speed"], ".4g"), optional_text(s["ratio"], ".4g")]
            f.write(",".join(row + walk_cells[gait]) + "\n")
    with style.replacing(md_path) as tmp, open(tmp, "w", encoding="utf-8") as f:
        f.write("| gait | cost | strike m/s | trailing \\|P_t\\|/P_n | "
                + " | ".join(f"{c}: {n.replace('_', ' ')}" for c, n in columns) + " |\n")
        f.write("|---|---:|---:|---:|" + "---|" * len(columns) + "\n")
        for gait, s in solves:
            speed = "—" if s["speed"] is None or s["speed"] < 1e-6 else f"{s['speed']:.3f}"
            ratio = "—" if s["ratio"] is None else f"{s['ratio']:.3f}"
            cost = f"{s['cost']:.1f}" + ("" if s["converged"] else ", not converged")
            f.write(f"| {gait} | {cost} | {speed} | {ratio} | " + " | ".join(walk_cells[gait])
                    + " |\n")
    return csv_path, md_path


def main(out):
    label, solves = read_solves(os.path.join(out, "solves.csv"))
    walks = read_walks(os.path.join(out, "walks.csv"), label, str, float)
    for path in write_tables(solves, walks, out):
        print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__, arguments=1)
