#!/usr/bin/python3
"""Compares two to four gait result folders (docs/design.md#the-export-contract): a markdown
table and overlaid pictures.

Usage: compare_gaits.py A_DIR B_DIR [C_DIR [D_DIR]] [OUT.md | OUT_DIR]
Without an output, prints the markdown table of the summary.json files (a column per gait, then
B/A, C/A, ...; a ratio is left empty when |A| < 1e-9 or the two differ in sign). Its first row
says what each gait is: polynomial with Mu's hip plan (his DSP stability margin, the thesis' own
design) or with the hip searched for the foot, or optimal, and the file it came from. The last
argument is the output when it ends in .md or is not a gait result folder (no summary.json in
it). With OUT.md, also writes the table there. With OUT_DIR (an existing folder, or any name not
ending in .md), creates it and writes, printing one line per file written:
  comparison.md        the table
  angles_overlay.png   link angles, one panel per link, each from its foot toward the hip
                       (theta, or theta - pi on the swing leg), as overview.png draws them
  torques_overlay.png  joint torques tau0..tau{N-1}, one panel per joint
  forces_overlay.png   normal forces fb_y, fe_y and the friction ratio |f_x|/f_y (f_y > 1 N)
                       with the friction coefficient (summary key 'friction') when present
  zmp_overlay.png      zmp_x with the support interval (stance tip B at x = 0): B's foot, heel to
                       toe, in the single support, and in the DSP from B's heel to the toe of
                       the leading tip E (at step_length, or swing_x when the key is absent), as
                       zmp.png draws it (robot_foot.support_region); the tips on point feet
  comparison.png       angles, torques, normal forces and ZMP on one page
The pictures read each folder's trajectory.csv: A solid, B dashed, C dotted, D dash-dotted, one
colour per quantity; grey vertical lines mark each gait's touchdown (SSP -> DSP; the step end for a
gait without DSP rows). A missing folder, file, column or key, or a malformed value, ends the
script with "error: <file>: <what>" and exit code 65 (EX_DATAERR of sysexits.h, which python
itself never returns): `gaitopt compare` then exits 2, bad input.
"""
import math
import os
import sys

import plot_io
import plot_style as style
from plot_io import InputError
from robot_foot import robot_foot, support_region

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
# B/A is shown only when |A| is at least this (below it the ratio is rounding noise).
RATIO_MIN_A = 1e-9
# The friction ratio is drawn where the normal force exceeds this [N].
MIN_LOADED_FORCE = 1.0
FORCE_COLUMNS = ["fb_x", "fb_y", "fe_x", "fe_y", "zmp_x"]
JOINT_NAMES_5 = ["stance ankle", "stance knee", "stance hip", "swing hip", "swing knee"]
# Line style of each gait, in the order of the folders, and its name in the legends.
LINE_NAMES = {"-": "solid", "--": "dashed", ":": "dotted", "-.": "dash-dotted"}

# ---------------------------------------------------------------------------------------------
# Table


def check_folder(folder):
    if not os.path.isdir(folder):
        raise InputError(f"{folder}: no such folder")


def load(folder):
    """The folder's summary.json; it must have the 'status' key every gait summary has."""
    check_folder(folder)
    path = os.path.join(folder, "summary.json")
    s = plot_io.read_json(path, "summary")
    plot_io.require_keys(path, s, ["status"])
    return s


def cell(value, fmt):
    return fmt.format(value) if fmt is not None and plot_io.is_number(value) else str(value)


def ratio(va, vb):
    """B/A to two decimals, or '' when it means nothing (tiny A, signs differ, not numbers)."""
    if not (plot_io.is_number(va) and plot_io.is_number(vb)):
        return ""
    if abs(va) < RATIO_MIN_A or va * vb < 0:
        return ""
    return f"{vb / va:.2f}"


TAGS = "ABCD"
# A figure a gait's summary does not have.
MISSING = "—"


def design(s):
    """What a gait is, from its summary: polynomial (whose hip plan) or optimal, and its file."""
    source = os.path.basename(str(s.get("config", "")))
    plan = s.get("hip_plan")
    if isinstance(plan, dict):
        how = ("hip searched for the foot (SSP ZMP)" if plan.get("objective") == "zmp" else
               "Mu's hip plan (DSP ZMP)")
        return f"polynomial, {how}, {source}"
    return f"optimal, {source}" if source else "optimal"


def row(label, values, fmt):
    """One table row: the values, then each against A."""
    ratios = [ratio(values[0], v) if fmt else "" for v in values[1:]]
    return "| " + " | ".join([label] + [cell(v, fmt) for v in values] + ratios) + " |"


def table(dirs, summaries=None):
    summaries = [load(d) for d in dirs] if summaries is None else summaries
    tags = TAGS[:len(dirs)]
    head = [f"{t}: {d}" for t, d in zip(tags, dirs)] + [f"{t}/A" for t in tags[1:]]
    lines = ["| quantity | " + " | ".join(head) + " |",
             "|---|" + "---:|" * (len(head))]
    lines.append(row("gait", [design(s) for s in summaries], None))
    lines.append(row("robot", [s.get("robot", MISSING) for s in summaries], None))
    for key, label, fmt in ROWS:
        if all(key not in s for s in summaries):
            continue
        lines.append(row(label, [value(s, key) for s in summaries], fmt))
    peaks = [joint_peaks(s) for s in summaries]
    for name in dict.fromkeys(n for p in peaks for n in p):  # every joint, in order of first use
        lines.append(row(f"peak torque {name} [N m]", [p.get(name, MISSING) for p in peaks],
                         "{:.1f}"))
    return "\n".join(lines) + "\n"


def value(summary, key):
    """A summary's figure for the table: a null is an unbounded figure (summary.json writes an
    infinite friction ratio, where a tip pulls on the ground, as null); a missing key a dash."""
    if key not in summary:
        return MISSING
    return "inf" if summary[key] is None else summary[key]


def joint_peaks(summary):
    """Peak torque by joint name: gaits of other robots have other joints, matched by name."""
    joints = summary.get("joints")
    peaks = summary.get("peak_torque")
    if not isinstance(peaks, list):
        return {}
    names = [j.get("name", "") if isinstance(j, dict) else str(j)
             for j in (joints if isinstance(joints, list) else [])]
    return {(names[j] if j < len(names) and names[j] else f"joint {j}"): p
            for j, p in enumerate(peaks)}


def write_text(path, text):
    try:
        with style.replacing(path) as tmp, open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
    except OSError as e:
        raise InputError(f"{path}: cannot write ({e.strerror})") from e


# ---------------------------------------------------------------------------------------------
# Trajectories


class Gait:
    """One result folder's summary and trajectory, with how it is drawn (tag A/B, line style)."""

    def __init__(self, folder, tag, ls):
        self.folder, self.tag, self.ls = folder.rstrip("/") or folder, tag, ls
        self.s = load(folder)
        traj = plot_io.read_trajectory(os.path.join(folder, "trajectory.csv"),
                                       ["tau0"] + FORCE_COLUMNS)
        self.col, self.t, self.phase = traj.col, traj.t, traj.phase
        self.n, self.n_tau = traj.n, traj.n_tau
        self.dsp, self.t_touchdown = traj.dsp, traj.t_touchdown
        summary = os.path.join(folder, "summary.json")
        for key in ("friction", "step_length"):
            if key in self.s:
                plot_io.require_numbers(summary, self.s, [key])
        self.mu = self.s.get("friction")
        self.foot = robot_foot(summary, self.s)[0]
        self.link_names = self.names_from(self.s.get("links"), self.n)

    @staticmethod
    def names_from(items, count):
        if (isinstance(items, list) and len(items) == count
                and all(isinstance(x, dict) and isinstance(x.get("name"), str) for x in items)):
            return [x["name"] for x in items]
        return None

    def label(self):
        return f"{self.tag}: {self.folder} ({LINE_NAMES[self.ls]})"

    def touchdown_label(self):
        if self.dsp.any():
            return f"{self.tag} touchdown SSP→DSP, t = {self.t_touchdown:.3g} s"
        return f"{self.tag} touchdown at the step end (no DSP), t = {self.t_touchdown:.3g} s"

    def friction_ratio(self, tip):
        """|f_x| / f_y at tip 'b' or 'e' where f_y > MIN_LOADED_FORCE, else NaN."""
        import numpy as np
        fx, fy = self.col[f"f{tip}_x"], self.col[f"f{tip}_y"]
        loaded = fy > MIN_LOADED_FORCE
        return np.where(loaded, np.abs(fx) / np.where(loaded, fy, 1.0), np.nan)

    def leading_tip(self):
        """x of the leading tip E in the DSP rows (NaN in the SSP), or None if unknown."""
        import numpy as np
        if not self.dsp.any():
            return None
        if "step_length" in self.s:
            e = np.full(len(self.t), float(self.s["step_length"]))
        elif "swing_x" in self.col:
            e = self.col["swing_x"].copy()
        else:
            return None
        e[~self.dsp] = np.nan
        return e


# ---------------------------------------------------------------------------------------------
# Pictures (matplotlib is imported here so the table needs only numpy)


def pyplot():
    return style.pyplot()


def colour(i):
    return f"C{i % 10}"


def mark_phases(ax, gaits):
    for g in gaits:
        ax.axvline(g.t_touchdown, color=style.TOUCHDOWN, ls=g.ls, lw=1)


def style_legend(fig, gaits, ncol=2):
    """Figure legend naming the folders (line styles) and their touchdowns."""
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color="k", ls=g.ls, lw=1.6, label=g.label()) for g in gaits]
    handles += [Line2D([], [], color=style.TOUCHDOWN, ls=g.ls, lw=1, label=g.touchdown_label())
                for g in gaits]
    fig.legend(handles=handles, loc="lower center", ncol=ncol, fontsize=8)


def colour_legend(ax, entries, **kw):
    """Axes legend of quantity colours: entries are (colour, label)."""
    from matplotlib.lines import Line2D
    ax.legend(handles=[Line2D([], [], color=c, lw=1.6, label=text) for c, text in entries],
              fontsize=7, **kw)


def finish(ax, xlabel, ylabel, title):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.grid(True, alpha=0.4)


def link_label(gaits, i):
    names = [g.link_names[i] for g in gaits if g.link_names and i < g.n]
    name = names[0] if names and all(x == names[0] for x in names) else ""
    return f"θ{i + 1} {name}".strip()


def joint_label(gaits, j):
    if all(g.n == 5 for g in gaits):
        return f"τ{j} {JOINT_NAMES_5[j]}" if j < 5 else f"τ{j} joint {j}"
    return f"τ{j} joint {j}"


# The angle convention of gait_plots.py's pictures, so a gait looks the same in both.
ANGLES_TITLE = "Link angles, foot toward hip (θ, or θ − π on the swing leg)"


def leg_angle(g, i):
    """Link i's angle [rad] pointing from its foot toward the hip, as overview.png and
    joint_angles.png draw it (gait_plots.physical_links): theta on the stance leg and the torso,
    theta - pi on the swing leg (the links past the middle of the chain)."""
    import numpy as np
    return plot_io.wrap(g.col[f"theta{i + 1}"] - (np.pi if i > (g.n - 1) / 2 else 0.0))


def draw_angle(ax, gaits, i):
    import numpy as np
    for g in gaits:
        if i < g.n:
            ax.plot(g.t, np.degrees(leg_angle(g, i)), color=colour(i), ls=g.ls, lw=1.5)
    mark_phases(ax, gaits)


def draw_torque(ax, gaits, j):
    for g in gaits:
        if j < g.n_tau:
            ax.plot(g.t, g.col[f"tau{j}"], color=colour(j), ls=g.ls, lw=1.5)
    mark_phases(ax, gaits)


def draw_all_angles(ax, gaits):
    n = max(g.n for g in gaits)
    for i in range(n):
        draw_angle(ax, gaits, i)
    colour_legend(ax, [(colour(i), link_label(gaits, i)) for i in range(n)], ncol=2,
                  loc="best")
    finish(ax, "time [s]", "link angle [deg]", ANGLES_TITLE)


def draw_all_torques(ax, gaits):
    m = max(g.n_tau for g in gaits)
    for j in range(m):
        draw_torque(ax, gaits, j)
    colour_legend(ax, [(colour(j), joint_label(gaits, j)) for j in range(m)], ncol=2,
                  loc="best")
    finish(ax, "time [s]", "joint torque [N m]", "Joint torques")


def draw_normal_forces(ax, gaits):
    for g in gaits:
        ax.plot(g.t, g.col["fb_y"], color=style.TIP_B, ls=g.ls, lw=1.5)
        ax.plot(g.t, g.col["fe_y"], color=style.TIP_E, ls=g.ls, lw=1.5)
    mark_phases(ax, gaits)
    colour_legend(ax, [(style.TIP_B, "fb_y, tip B (stance/trailing)"),
                       (style.TIP_E, "fe_y, tip E (swing/leading)")], loc="best")
    finish(ax, "time [s]", "normal force [N]", "Normal ground forces")


def draw_friction(ax, gaits):
    import numpy as np
    top = 0.0
    for g in gaits:
        for tip, c in (("b", style.TIP_B), ("e", style.TIP_E)):
            r = g.friction_ratio(tip)
            ax.plot(g.t, r, color=c, ls=g.ls, lw=1.5)
            if np.any(np.isfinite(r)):
                top = max(top, float(np.nanmax(r)))
    entries = [(style.TIP_B, "|fb_x|/fb_y"), (style.TIP_E, "|fe_x|/fe_y")]
    mus = [g for g in gaits if g.mu is not None]
    for g in mus:
        ax.axhline(g.mu, color="k", ls=g.ls, lw=1.1)
        top = max(top, g.mu)
    if mus:
        same = all(g.mu == mus[0].mu for g in mus)
        text = (f"friction μ = {mus[0].mu:g} ({', '.join(g.tag for g in mus)})" if same else
                "friction μ: " + ", ".join(f"{g.tag} {g.mu:g}" for g in mus))
        entries.append(("k", text))
    mark_phases(ax, gaits)
    ax.set_ylim(0, 1.2 * top if top > 0 else 1)
    colour_legend(ax, entries, loc="best")
    finish(ax, "time [s]", "|f_x| / f_y [-]",
           f"Friction ratio where f_y > {MIN_LOADED_FORCE:g} N")


def draw_zmp(ax, gaits):
    import numpy as np
    entries = [(style.ZMP, "zmp_x")]
    ax.axhline(0, color="0.3", lw=1)
    entries.append(("0.3", "stance/trailing tip B, x = 0"))
    shaded = False
    for g in gaits:
        tip_e = g.leading_tip()
        if tip_e is None:
            continue
        # As zmp.png draws it (gait_plots.py): from B's heel to E's toe, the tips on point feet.
        back, front = support_region(g.dsp, tip_e, g.foot)
        d = g.dsp
        ax.fill_between(g.t[d], back[d], front[d], facecolor="0.6" if g.ls == "-" else "none",
                        alpha=0.25 if g.ls == "-" else 0.6, hatch=None if g.ls == "-" else "//",
                        edgecolor="0.5", lw=0, gid="dsp_support")
        ax.plot(g.t, np.where(d, front, np.nan), color="0.3", ls=g.ls, lw=1)
        shaded = True
    if shaded:
        what = ("B's heel to E's toe" if any(g.foot is not None for g in gaits) else "tip B to tip E")
        entries.append(("0.6", f"DSP support, {what} (solid gait filled, the others hatched)"))
    # The foot in the single support: a ZMP outside [-heel, toe] tips the stance foot.
    for foot in dict.fromkeys(g.foot for g in gaits if g.foot is not None):
        tags = ", ".join(g.tag for g in gaits if g.foot == foot)
        ax.axhspan(-foot[0], foot[1], gid="foot", **style.FOOT_SHADE)
        entries.append((style.FOOT_SHADE["color"],
                        f"foot of B ({tags}): heel {foot[0]:g} m, toe {foot[1]:g} m"))
    for g in gaits:
        ax.plot(g.t, g.col["zmp_x"], color=style.ZMP, ls=g.ls, lw=1.6)
    mark_phases(ax, gaits)
    colour_legend(ax, entries, loc="best")
    finish(ax, "time [s]", "x (from tip B) [m]", "ZMP and support interval")


def grid(plt, count, width=4.0, height=2.9):
    """Small multiples: a figure with at least `count` axes; the unused ones hidden."""
    ncols = 3 if count > 4 else 2 if count > 1 else 1
    nrows = math.ceil(count / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(width * ncols, height * nrows + 1.0),
                             squeeze=False)
    flat = list(axes.ravel())
    for ax in flat[count:]:
        ax.set_visible(False)
    return fig, flat[:count]


def title(fig, what, gaits):
    fig.suptitle(f"{what}: " + " vs ".join(g.label() for g in gaits), fontsize=10)


def save(fig, gaits, path, bottom):
    style_legend(fig, gaits)
    fig.tight_layout(rect=(0, bottom, 1, 1))
    style.save(fig, path)
    print(path)


def small_multiples(plt, gaits, count, draw, ylabel, label, name):
    """One panel per link or joint k: draw(ax, gaits, k), titled label(gaits, k)."""
    fig, axes = grid(plt, count)
    for k, ax in enumerate(axes):
        draw(ax, gaits, k)
        finish(ax, "time [s]", ylabel, label(gaits, k))
    title(fig, name, gaits)
    return fig, 0.1


def angles_figure(plt, gaits):
    return small_multiples(plt, gaits, max(g.n for g in gaits), draw_angle, "angle [deg]",
                           link_label, ANGLES_TITLE)


def torques_figure(plt, gaits):
    return small_multiples(plt, gaits, max(g.n_tau for g in gaits), draw_torque, "torque [N m]",
                           joint_label, "Joint torques")


def forces_figure(plt, gaits):
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8.2, 7.6), sharex=True)
    draw_normal_forces(ax1, gaits)
    draw_friction(ax2, gaits)
    ax1.set_xlabel("")
    title(fig, "Contact forces", gaits)
    return fig, 0.09


def zmp_figure(plt, gaits):
    fig, ax = plt.subplots(figsize=(8.2, 5.4))
    draw_zmp(ax, gaits)
    title(fig, "ZMP", gaits)
    return fig, 0.14


def comparison_figure(plt, gaits):
    fig, axes = plt.subplots(2, 2, figsize=(13, 9.5))
    draw_all_angles(axes[0, 0], gaits)
    draw_all_torques(axes[0, 1], gaits)
    draw_normal_forces(axes[1, 0], gaits)
    draw_zmp(axes[1, 1], gaits)
    title(fig, "Gait comparison", gaits)
    return fig, 0.07


PICTURES = [("angles_overlay.png", angles_figure), ("torques_overlay.png", torques_figure),
            ("forces_overlay.png", forces_figure), ("zmp_overlay.png", zmp_figure),
            ("comparison.png", comparison_figure)]


def report(dirs, out_dir):
    """Reads everything first, so a broken input writes nothing."""
    gaits = [Gait(d, tag, ls) for d, tag, ls in zip(dirs, TAGS, LINE_NAMES)]
    text = table(dirs, [g.s for g in gaits])
    plt = pyplot()
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as e:
        raise InputError(f"{out_dir}: cannot create the folder ({e.strerror})") from e
    path = os.path.join(out_dir, "comparison.md")
    write_text(path, text)
    print(path)
    for name, make in PICTURES:
        fig, bottom = make(plt, gaits)
        save(fig, gaits, os.path.join(out_dir, name), bottom)


def is_gait(arg):
    return os.path.isfile(os.path.join(arg, "summary.json"))


def main(args):
    out = args[-1] if len(args) > 2 and (args[-1].endswith(".md") or not is_gait(args[-1])) else None
    dirs = args[:-1] if out else args
    if not 2 <= len(dirs) <= len(TAGS):
        sys.exit(__doc__)
    if out and (os.path.isdir(out) or not out.endswith(".md")):  # an existing folder is OUT_DIR
        report(dirs, out)
        return
    text = table(dirs)
    if out:
        write_text(out, text)
    print(text, end="")


if __name__ == "__main__":
    if not 3 <= len(sys.argv) <= 2 + len(TAGS):
        sys.exit(__doc__)
    try:
        main(sys.argv[1:])
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(os.EX_DATAERR)
