#!/usr/bin/python3
"""Side-by-side table of two gait result folders (their summary.json), as markdown.

Usage: compare_gaits.py A_DIR B_DIR [OUT.md]
Prints the table; with OUT.md also writes it there. Columns: A, B and B/A.
"""
import json
import sys

ROWS = [
    ("status", "status", None),
    ("cost_of_transport", "cost of transport", "{:.4f}"),
    ("energy_J", "energy (absolute work) [J]", "{:.2f}"),
    ("torque_squared", "torque-squared integral [N^2 m^2 s]", "{:.1f}"),
    ("min_normal_force", "min normal force [N]", "{:.1f}"),
    ("max_friction_ratio", "max friction ratio abs(Fx)/Fy", "{:.3f}"),
    ("min_zmp_margin", "min ZMP margin [m]", "{:.4f}"),
    ("impact_energy_loss_J", "impact energy loss [J]", "{:.3g}"),
    ("step_length", "step length [m]", "{:.3f}"),
    ("speed", "speed [m/s]", "{:.3f}"),
]


def load(folder):
    try:
        with open(f"{folder}/summary.json", encoding="utf-8") as f:
            return json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        sys.exit(f"error: {folder}/summary.json: {e}")


def cell(value, fmt):
    return str(value) if fmt is None else fmt.format(value)


def table(a_dir, b_dir):
    a, b = load(a_dir), load(b_dir)
    lines = [f"| quantity | A: {a_dir} | B: {b_dir} | B/A |", "|---|---:|---:|---:|"]
    for key, label, fmt in ROWS:
        va, vb = a.get(key), b.get(key)
        if va is None or vb is None:
            continue
        ratio = f"{vb / va:.2f}" if fmt and isinstance(va, (int, float)) and va != 0 else ""
        lines.append(f"| {label} | {cell(va, fmt)} | {cell(vb, fmt)} | {ratio} |")
    names = [j["name"] for j in a.get("joints", [])]
    for j, (pa, pb) in enumerate(zip(a.get("peak_torque", []), b.get("peak_torque", []))):
        name = names[j] if j < len(names) else f"joint {j}"
        ratio = f"{pb / pa:.2f}" if pa else ""
        lines.append(f"| peak torque {name} [N m] | {pa:.1f} | {pb:.1f} | {ratio} |")
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    text = table(sys.argv[1], sys.argv[2])
    print(text, end="")
    if len(sys.argv) == 4:
        with open(sys.argv[3], "w", encoding="utf-8") as f:
            f.write(text)


if __name__ == "__main__":
    main()
