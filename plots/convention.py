#!/usr/bin/python3
"""Draws gaitopt's angle convention from `gaitopt inspect --state ...` JSON output.

Usage: convention.py INSPECT.json OUT.png
The stick figure is the robot at the given state; each link carries its absolute angle theta_i,
measured from the upward vertical at its proximal joint, clockwise (toward +x) positive.
"""
import json
import math
import sys

import matplotlib
import plot_style as style

plt = style.pyplot()


def main(src: str, out: str) -> None:
    with open(src, encoding="utf-8") as f:
        d = json.load(f)
    theta = d["state"]["theta"]
    fig, ax = plt.subplots(figsize=(6, 6.5))
    ax.axhline(0, color="0.5", lw=1)
    for i, seg in enumerate(d["link_segments"]):
        (x0, y0), (x1, y1) = seg["start"], seg["end"]
        ax.plot([x0, x1], [y0, y1], lw=5, solid_capstyle="round",
                color="tab:blue" if i < d["n_links"] // 2 else
                ("tab:gray" if seg["name"] == "torso" else "tab:orange"))
        # Vertical reference and the angle arc at the proximal joint.
        r = 0.06 + 0.012 * i
        ax.plot([x0, x0], [y0, y0 + 0.12], ls=":", color="k", lw=0.8)
        a0, a1 = 90.0, 90.0 - math.degrees(theta[i])
        arc = [math.radians(a0 + (a1 - a0) * t / 40) for t in range(41)]
        ax.plot([x0 + r * math.cos(a) for a in arc], [y0 + r * math.sin(a) for a in arc],
                color="k", lw=0.8)
        xm, ym = (x0 + x1) / 2, (y0 + y1) / 2
        left = i >= d["n_links"] - d["n_links"] // 2
        ax.annotate(f"{i + 1} {seg['name']}\n$\\theta_{i + 1}$ = {math.degrees(theta[i]):.1f}°",
                    (xm, ym), xytext=(-10 if left else 10, 0), textcoords="offset points",
                    fontsize=8, ha="right" if left else "left")
    ax.plot(0, 0, "ko")
    ax.annotate("B (stance tip, origin)", (0, 0), xytext=(5, -14), textcoords="offset points",
                fontsize=8)
    e = d["swing_tip"]["position"]
    ax.plot(*e, "ko")
    ax.annotate("E (swing tip)", e, xytext=(5, -14), textcoords="offset points", fontsize=8)
    ax.annotate("", xy=(0.25, -0.08), xytext=(0.0, -0.08),
                arrowprops={"arrowstyle": "->"})
    ax.text(0.0, -0.12, "+x: walking direction", fontsize=8)
    ax.set_title("gaitopt angles: u_i = (sin θ_i, cos θ_i); θ from the upward vertical,\n"
                 "clockwise (toward +x) positive; swing-leg links point down (θ ≈ π)",
                 fontsize=9)
    xs = [p for seg in d["link_segments"] for p in (seg["start"][0], seg["end"][0])]
    ax.set_xlim(min(xs) - 0.3, max(xs) + 0.4)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    fig.tight_layout()
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
