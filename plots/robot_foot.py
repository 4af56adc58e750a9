"""The foot a gait's ZMP is drawn against: heel and toe [m] about each tip.

From summary.json's `foot` key (written since 2026-12-01; 0 and 0 for point tips), else, for
folders written before, from the robot file in configs/robots/ that the summary names (beside
plots/ in a checkout and in an installation).
"""
import glob
import os
import re

import plot_io

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The reason robot_foot gives for a robot whose summary.json says it walks on point tips.
POINT_FEET = "point feet (summary.json)"


def support_region(dsp, leading_x, foot):
    """(back, front) edges [m from tip B] of the region a ZMP must stay in at every row: B's foot,
    heel to toe, in the single support; from B's heel to the toe of the leading tip E, at
    `leading_x` (a number or one per row), in the double support rows `dsp`; the tips themselves
    for point feet (`foot` None)."""
    import numpy as np
    heel, toe = foot if foot is not None else (0.0, 0.0)
    back = np.full(len(dsp), -heel)
    return back, np.where(dsp, leading_x + toe, toe)


def robot_file_foot(text):
    """(heel, toe) from a robot YAML text's `foot: {heel: .., toe: ..}`, or None."""
    try:
        import yaml
        foot = (yaml.safe_load(text) or {}).get("foot")
        if isinstance(foot, dict) and all(plot_io.is_number(foot.get(k)) for k in ("heel", "toe")):
            return float(foot["heel"]), float(foot["toe"])
        return None
    except ImportError:
        m = re.search(r"^foot:\s*\{\s*heel:\s*([-+.\deE]+)\s*,\s*toe:\s*([-+.\deE]+)\s*\}",
                      text, re.M)
        return (float(m[1]), float(m[2])) if m else None


def robot_foot(path, s):
    """((heel, toe) [m], where it came from), or (None, reason) for point tips, for the summary
    `s` read from `path`. A malformed `foot` key is an InputError naming it."""
    if "foot" in s:
        plot_io.require_type(path, s, "foot", dict, "an object {heel, toe}")
        plot_io.require_numbers(path, s["foot"], ["heel", "toe"], prefix="foot.")
        foot = (float(s["foot"]["heel"]), float(s["foot"]["toe"]))
        return (foot, "summary.json") if any(foot) else (None, POINT_FEET)
    files = ([os.path.join(ROOT, s["robot_file"])] if isinstance(s.get("robot_file"), str)
             else sorted(glob.glob(os.path.join(ROOT, "configs", "robots", "*.yaml"))))
    for robot in files:
        try:
            with open(robot, encoding="utf-8") as f:
                text = f.read()
        except OSError:
            continue
        if re.search(rf"^name:\s*{re.escape(str(s.get('robot')))}\s*$", text, re.M):
            foot = robot_file_foot(text)
            if foot is not None:
                return foot, os.path.relpath(robot, ROOT)
    return None, f"no foot in summary.json or in a robot file named {s.get('robot')}"
