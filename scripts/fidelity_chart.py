#!/usr/bin/env python3
"""Fidelity chart ("model no more than a scene needs"): Mu's five-link robot and its
two reductions (configs/robots/mu2004_three_link.yaml: knees locked, point feet;
mu2004_compass_gait.yaml: also the torso lumped at the hip) solve the same torque-squared gait
problem over a speed sweep 0.3 .. 1.2 m/s at one step-frequency rule: the step length stays
Mu's 0.35 m, so the step lasts 0.35 / v s (frequency proportional to speed). The five-link
problem is configs/ocp/mu2004_walk.yaml (SSP + DSP split 6 : 1, double impact, clearance, ZMP);
the reductions are configs/ocp/{three_link,compass_gait}_walk.yaml (SSP only, single impact)
with the reduced robot and the same step. Every point is a cold `gaitopt optimize` solve.
Writes OUT/fidelity.md (table of cost of transport, peak joint torque and solve time, each as
a ratio to the five-link value) and OUT/fidelity.csv.

Usage: scripts/fidelity_chart.py GAITOPT_BINARY OUT_DIR
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SPEEDS = [0.3, 0.45, 0.6, 0.75, 0.9, 1.05, 1.2]
STEP = 0.35  # [m], Mu's
ROBOTS = [  # label, base config, robot file (None: the base's own), DSP share of the step
    ("five-link", "mu2004_walk.yaml", None, 1 / 7),
    ("three-link", "three_link_walk.yaml", "mu2004_three_link.yaml", 0),
    ("compass", "compass_gait_walk.yaml", "mu2004_compass_gait.yaml", 0),
]


def point_config(base, robot, dsp_share, speed, tmp):
    """The base config at the step length STEP and speed `speed`, with absolute paths."""
    ocp_dir = os.path.join(ROOT, "configs", "ocp")
    duration = STEP / speed
    lines = []
    for line in open(os.path.join(ocp_dir, base)):
        key = line.split(":")[0].strip()
        if key == "robot":
            name = robot or os.path.basename(line.split(":", 1)[1].strip())
            line = f"robot: {os.path.join(ROOT, 'configs', 'robots', name)}\n"
        elif key == "initial_guess" and "straight_leg" not in line:
            line = f"initial_guess: {os.path.normpath(os.path.join(ocp_dir, line.split(':', 1)[1].strip()))}\n"
        elif key == "step_length":
            line = f"step_length: {STEP}\n"
        elif key == "- {name":
            phase = line.split("name:")[1].split(",")[0].strip()
            share = 1 - dsp_share if phase == "SSP" else dsp_share
            segments = line.split("segments:")[1].split("}")[0].strip()
            line = f"  - {{name: {phase}, duration: {duration * share:.6f}, segments: {segments}}}\n"
        lines.append(line)
    path = os.path.join(tmp, f"{os.path.splitext(base)[0]}_{speed}.yaml")
    with open(path, "w") as f:
        f.writelines(lines)
    return path


def solve(binary, config, out):
    run = subprocess.run([binary, "optimize", "--config", config, "--out", out, "--quiet"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        return None
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"cot": s["cost_of_transport"], "peak": max(abs(t) for t in s["peak_torque"]),
            "time": s["wall_time_s"], "cost": s["cost"]}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    binary, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for speed in SPEEDS:
            for label, base, robot, dsp in ROBOTS:
                config = point_config(base, robot, dsp, speed, tmp)
                r = solve(binary, config, os.path.join(tmp, f"{label}_{speed}"))
                rows.append({"speed": speed, "robot": label, **(r or {})})
                print(speed, label, r, flush=True)
    with open(os.path.join(out_dir, "fidelity.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, ["speed", "robot", "cot", "peak", "time", "cost"])
        w.writeheader()
        w.writerows(rows)
    write_table(rows, os.path.join(out_dir, "fidelity.md"))


def ratio(a, b):
    return f"{a / b:.2f}" if a is not None and b else "-"


def write_table(rows, path):
    by = {(r["speed"], r["robot"]): r for r in rows}
    out = ["Torque-squared optimum of each model at Mu's step (0.35 m, step time 0.35 / v), cold "
           "solves by scripts/fidelity_chart.py; cost of transport = absolute joint work / (m g d); "
           "peak = largest |joint torque|; solve = Ipopt wall time on the machine that ran it. "
           "Ratios to the five-link value in parentheses; 'failed': no converged solve.", "",
           "| speed m/s | five-link CoT | peak N m | solve s | three-link CoT / peak / time "
           "(ratio to five-link) | compass CoT / peak / time (ratio) |",
           "|---:|---:|---:|---:|---|---|"]
    for v in SPEEDS:
        ref = by[(v, "five-link")]
        if "cot" not in ref:
            out.append(f"| {v} | failed | | | | |")
            continue
        cells = [f"{v}", f"{ref['cot']:.3f}", f"{ref['peak']:.1f}", f"{ref['time']:.2f}"]
        for label in ("three-link", "compass"):
            r = by[(v, label)]
            cells.append("failed" if "cot" not in r else
                         f"{r['cot']:.3f} / {r['peak']:.1f} / {r['time']:.2f} "
                         f"({ratio(r['cot'], ref['cot'])} / {ratio(r['peak'], ref['peak'])} / "
                         f"{ratio(r['time'], ref['time'])})")
        out.append("| " + " | ".join(cells) + " |")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
