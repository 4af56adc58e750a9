#!/usr/bin/python3
"""Draws the pictures of a gait result folder (DESIGN.md sec. 5), after Mu (2004) ch. 3.

Usage: gait_plots.py RESULT_DIR
Reads RESULT_DIR/trajectory.csv (one step, stance tip B at the origin) and RESULT_DIR/summary.json
and writes into RESULT_DIR, printing one line per picture written:
  joint_angles.png  link angles and rates per physical link over two steps (Mu Fig. 3.3)
  paths.png         hip and tip positions over two steps, swing-tip path (Fig. 3.2)
  dsp_zmp.png       CoM, hip and ZMP in the double support phase (Fig. 3.4; needs DSP rows)
  forces.png        vertical tip forces and the friction they need (Fig. 3.5)
  stick.png         stick diagram of the step (Fig. 3.6)
  overview.png      the main panels of the above on one page
Angles follow dynamics/conventions.hpp: u_i = (sin theta_i, cos theta_i), theta from the upward
vertical, clockwise positive. Step 2 is step 1 with the legs swapped (link i <-> link N+1-i, leg
links turned by pi, the torso unchanged), so both steps come from the one step in the file.
A missing file, column or key, or a malformed value, ends the script with exit code 1.
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import plot_io  # noqa: E402
from plot_io import InputError  # noqa: E402

DPI = 110
DSP_SHADE = {"color": "tab:purple", "alpha": 0.12, "lw": 0}
# Columns used besides t, phase, theta<i> and dtheta<i>.
TAIL_COLUMNS = ["fb_x", "fb_y", "fe_x", "fe_y", "zmp_x", "hip_x", "swing_x", "swing_y", "com_x",
                "com_y"]
SUMMARY_NUMBERS = ["step_length", "duration", "speed", "friction", "min_normal_force",
                   "max_friction_ratio", "min_zmp_margin", "energy_J", "cost_of_transport"]
# Link lengths must reproduce swing_x/swing_y from theta to this tolerance [m].
KINEMATICS_TOLERANCE = 1e-6


# ---------------------------------------------------------------------------------------------
# Reading


def read_csv(path):
    """Returns (columns: name -> float array, phase: str array, n_links)."""
    header, rows = plot_io.read_rows(path, "trajectory", min_rows=2)
    n = sum(1 for name in header if re.fullmatch(r"theta[1-9][0-9]*", name))
    needed = (["t", "phase"] + [f"theta{i}" for i in range(1, n + 1)]
              + [f"dtheta{i}" for i in range(1, n + 1)] + TAIL_COLUMNS)
    plot_io.require_columns(path, header, needed)
    if n < 2:
        raise InputError(f"{path}: found {n} theta<i> columns, a biped has at least two links")
    cols = plot_io.columns(path, header, rows, needed, strings={"phase"})
    phase = cols.pop("phase")
    plot_io.check_phases(path, phase)
    plot_io.check_increasing(path, "t", cols["t"])
    return cols, phase, n


def read_summary(path, n):
    s = plot_io.read_json(path, "summary")
    plot_io.require_keys(path, s, ["robot", "links"] + SUMMARY_NUMBERS)
    plot_io.require_numbers(path, s, SUMMARY_NUMBERS)
    links = s["links"]
    if not isinstance(links, list) or len(links) != n:
        raise InputError(f"{path}: key 'links': expected a list of {n} links (one per theta "
                         f"column of the trajectory)")
    for i, link in enumerate(links):
        if not (isinstance(link, dict) and isinstance(link.get("name"), str)
                and isinstance(link.get("length"), (int, float))
                and isinstance(link.get("continues"), bool)):
            raise InputError(f"{path}: key 'links[{i}]': expected {{name, length, continues}}")
    return s


class Gait:
    """One step from the files, with what the pictures derive from it."""

    def __init__(self, result_dir):
        csv_path = os.path.join(result_dir, "trajectory.csv")
        self.col, self.phase, self.n = read_csv(csv_path)
        self.s = read_summary(os.path.join(result_dir, "summary.json"), self.n)
        self.t = self.col["t"]
        self.theta = np.column_stack([self.col[f"theta{i}"] for i in range(1, self.n + 1)])
        self.dtheta = np.column_stack([self.col[f"dtheta{i}"] for i in range(1, self.n + 1)])
        self.dsp = self.phase == "DSP"
        self.L = self.s["step_length"]
        self.T = self.s["duration"]
        self.t_touchdown = self.t[self.dsp][0] if self.dsp.any() else self.t[-1]
        self.torso = np.array([not link["continues"] for link in self.s["links"]])
        self.swap = np.arange(self.n)[::-1]
        if np.any(self.torso != self.torso[self.swap]):
            raise InputError("summary.json: key 'links': the torso (continues = false) must sit "
                             "in the middle of the chain for the leg swap")
        self.check_kinematics(csv_path)

    def link_points(self, k):
        """(proximal, distal) points of every link at row k, each n x 2 [m]."""
        u = np.column_stack([np.sin(self.theta[k]), np.cos(self.theta[k])])
        lengths = np.array([link["length"] for link in self.s["links"]], dtype=float)
        step = (~self.torso * lengths)[:, None] * u
        proximal = np.vstack([[0.0, 0.0], np.cumsum(step, axis=0)[:-1]])
        return proximal, proximal + lengths[:, None] * u

    def check_kinematics(self, csv_path):
        worst = max(np.hypot(*(self.link_points(k)[1][-1]
                               - (self.col["swing_x"][k], self.col["swing_y"][k])))
                    for k in range(len(self.t)))
        if worst > KINEMATICS_TOLERANCE:
            raise InputError(f"{csv_path}: swing_x/swing_y differ by up to {worst:.3g} m from the "
                             f"tip computed from theta and the summary's link lengths")

    def force_ratio(self, tip):
        """|F_x| / F_y at tip 'b' or 'e'; NaN where the tip is unloaded or (E) in the air."""
        fx, fy = self.col[f"f{tip}_x"], self.col[f"f{tip}_y"]
        loaded = (fy > 0) & (self.dsp if tip == "e" else True)
        return np.where(loaded, np.abs(fx) / np.where(loaded, fy, 1.0), np.nan)

    def weight(self):
        """m g [N] from cost_of_transport = energy_J / (m g step_length), or None."""
        cot = self.s["cost_of_transport"]
        return self.s["energy_J"] / (cot * self.L) if cot > 0 else None


# ---------------------------------------------------------------------------------------------
# Two steps from one: physical legs A (stance in step 1) and B


def wrap(angle):
    """Angle wrapped to (-pi, pi]."""
    return -((-angle + math.pi) % (2 * math.pi) - math.pi)


def physical_links(g):
    """Time (2 steps), angles [rad] and rates [rad/s] per physical link, and their labels.

    A leg link is shown pointing from its foot toward the hip: theta in stance, theta - pi in
    swing, so a link keeps its curve through the leg swap."""
    shift = np.where(g.torso, 0.0, math.pi)
    mid = (g.n - 1) / 2
    step1 = wrap(g.theta - np.where(np.arange(g.n) > mid, shift, 0.0))
    step2 = wrap(g.theta[:, g.swap] - np.where(np.arange(g.n) < mid, shift, 0.0))
    t = np.concatenate([g.t, g.t + g.T])
    names = [link["name"].replace("stance_", "").replace("swing_", "") for link in g.s["links"]]
    labels = [name if g.torso[i] else f"leg {'A' if i < mid else 'B'} {name}".removesuffix(" leg")
              for i, name in enumerate(names)]
    return t, np.vstack([step1, step2]), np.vstack([g.dtheta, g.dtheta[:, g.swap]]), labels


def link_colours(g):
    mid = (g.n - 1) / 2
    colours = []
    for i in range(g.n):
        depth = abs(i - mid) / max(mid, 1)  # 1 at the tips (shanks), smaller toward the hip
        cmap = plt.cm.Blues if i < mid else plt.cm.Oranges
        colours.append("0.25" if g.torso[i] or i == mid else cmap(0.45 + 0.5 * depth))
    return colours


def jumps(g, angles, rates):
    """Largest change of any link's angle [deg] and rate [rad/s] at touchdown and at the swap."""
    k = len(g.t)
    if not g.dsp.any():
        pairs = {"touchdown and leg swap": (k - 1, k)}
    else:
        first = int(np.argmax(g.dsp))
        pairs = {"touchdown": (first - 1, first), "leg swap": (k - 1, k)}
    return {name: (math.degrees(np.max(np.abs(wrap(angles[j] - angles[i])))),
                   np.max(np.abs(rates[j] - rates[i]))) for name, (i, j) in pairs.items()}


def mark_phases(ax, g, steps=2):
    """Shades DSP intervals, dashes touchdowns and dots step boundaries over `steps` steps."""
    for s in range(steps):
        offset = s * g.T
        if g.dsp.any():
            ax.axvspan(offset + g.t_touchdown, offset + g.t[-1], **DSP_SHADE,
                       label="DSP" if s == 0 else None)
        ax.axvline(offset + g.t_touchdown, color="k", ls="--", lw=0.8,
                   label="touchdown" if s == 0 else None)
        if s > 0:
            ax.axvline(offset, color="k", ls=":", lw=0.8, label="leg swap")


def finish(ax, xlabel, ylabel, title=None, legend=True, **legend_kw):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.4)
    if legend:
        ax.legend(fontsize=8, **legend_kw)


# ---------------------------------------------------------------------------------------------
# Panels (each draws on one axes)


def draw_angles(ax, g, legend=True):
    t, angles, _, labels = physical_links(g)
    for i, colour in enumerate(link_colours(g)):
        ax.plot(t, np.degrees(angles[:, i]), color=colour, lw=1.6, label=labels[i])
    mark_phases(ax, g)
    finish(ax, "time [s]", "link angle [deg]", "Link angles, foot toward hip (θ or θ − π)",
           legend=legend, ncol=3, loc="upper left")


def draw_rates(ax, g):
    t, _, rates, labels = physical_links(g)
    for i, colour in enumerate(link_colours(g)):
        ax.plot(t, rates[:, i], color=colour, lw=1.6, label=labels[i])
    mark_phases(ax, g)
    finish(ax, "time [s]", "link rate dθ/dt [rad/s]", "Link rates", legend=False)


def draw_positions(ax, g):
    """Horizontal positions in a world frame: step 1 origin at 0, step 2 at step_length."""
    t = np.concatenate([g.t, g.t + g.T])
    stance = np.zeros_like(g.t)
    ax.plot(t, np.concatenate([g.col["hip_x"], g.L + g.col["hip_x"]]), color="0.25", lw=1.8,
            label="hip")
    ax.plot(t, np.concatenate([stance, g.L + g.col["swing_x"]]), color="tab:blue", lw=1.6,
            label="foot A (stance, then swing)")
    ax.plot(t, np.concatenate([g.col["swing_x"], g.L + stance]), color="tab:orange", lw=1.6,
            label="foot B (swing, then stance)")
    mark_phases(ax, g)
    ax.set_xlim(0, 2 * g.T)
    finish(ax, "time [s]", "x (world) [m]", "(a) Horizontal positions over two steps",
           loc="upper left", ncol=2)


def draw_swing_path(ax, g):
    ssp = ~g.dsp
    x, y = g.col["swing_x"][ssp], g.col["swing_y"][ssp]
    ax.plot(x, y, color="tab:orange", lw=1.8, label="swing tip E (SSP)")
    ax.plot(x[[0, -1]], y[[0, -1]], "o", color="tab:orange", ms=5)
    k = int(np.argmax(y))
    ax.annotate(f"apex ({x[k]:.3f}, {y[k]:.3f}) m", (x[k], y[k]), xytext=(0, 8),
                textcoords="offset points", ha="center", fontsize=8)
    ax.axhline(0, color="0.5", lw=1)
    ax.plot(0, 0, "k^", ms=7, label="stance tip B")
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x [m]", "y [m]", "(b) Swing-tip path in the SSP (equal axes)", loc="upper left",
           ncol=2)


def draw_dsp_zmp(ax, g):
    d = g.dsp
    t = g.t[d]
    ax.axhspan(0, g.L, color="0.85", label="between the tips")
    for y, text in ((0, "B, trailing tip"), (g.L, "E, leading tip")):
        ax.annotate(text, (1, y), xycoords=("axes fraction", "data"), xytext=(-4, -11),
                    textcoords="offset points", ha="right", fontsize=8, color="0.3")
    for name, colour, label in (("com_x", "tab:green", "CoM x"), ("hip_x", "0.25", "hip x"),
                                ("zmp_x", "tab:red", "ZMP x")):
        ax.plot(t, g.col[name][d], color=colour, lw=1.8, label=label)
    zmp = g.col["zmp_x"][d]
    margin = np.minimum(zmp, g.L - zmp)
    k = int(np.argmin(margin))
    ax.plot(t[k], zmp[k], "o", color="tab:red", mfc="none", ms=9)
    ax.annotate(f"closest to a tip: {1000 * margin[k]:.0f} mm", (t[k], zmp[k]),
                xytext=(10, -16 if zmp[k] < g.L / 2 else 12), textcoords="offset points",
                fontsize=8, bbox={"fc": "w", "ec": "0.6"})
    ax.set_ylim(-0.2 * g.L, 1.45 * g.L)
    finish(ax, "time [s]", "x (from B) [m]",
           f"ZMP in the double support (Mu Fig. 3.4)\nmin ZMP margin over the step, feet "
           f"included (summary): {1000 * g.s['min_zmp_margin']:.0f} mm",
           loc="upper center", ncol=4)


def draw_vertical_forces(ax, g):
    ax.plot(g.t, g.col["fb_y"], color="tab:blue", lw=1.8, label="B (stance/trailing) $F_y$")
    if g.dsp.any():
        ax.plot(g.t[g.dsp], g.col["fe_y"][g.dsp], color="tab:orange", lw=1.8,
                label="E (leading) $F_y$")
        ax.plot(g.t[g.dsp], (g.col["fb_y"] + g.col["fe_y"])[g.dsp], color="0.4", lw=1,
                label="B + E")
    weight = g.weight()
    if weight:
        ax.axhline(weight, color="k", ls="--", lw=1, label=f"weight m g = {weight:.0f} N")
    ax.axhline(g.s["min_normal_force"], color="tab:red", ls=":", lw=1,
               label=f"min normal force {g.s['min_normal_force']:.0f} N")
    mark_phases(ax, g, steps=1)
    ax.set_ylim(bottom=min(0, np.min(g.col["fb_y"]), np.min(g.col["fe_y"][g.dsp], initial=0)))
    finish(ax, "time [s]", "vertical force [N]", "Vertical ground forces on the robot",
           loc="best", ncol=2)


def draw_friction(ax, g):
    rb, re_ = g.force_ratio("b"), g.force_ratio("e")
    ax.plot(g.t, rb, color="tab:blue", lw=1.8, label="B  $|F_x|/F_y$")
    if g.dsp.any():
        ax.plot(g.t, re_, color="tab:orange", lw=1.8, label="E  $|F_x|/F_y$ (DSP)")
    mu, worst = g.s["friction"], g.s["max_friction_ratio"]
    ax.axhline(mu, color="k", ls="--", lw=1.2, label=f"friction cone μ = {mu:g}")
    ax.axhline(worst, color="tab:red", ls=":", lw=1.2, label=f"max ratio (summary) {worst:.3g}")
    mark_phases(ax, g, steps=1)
    ax.set_ylim(0, 1.25 * max(mu, worst, np.nanmax(np.concatenate([rb, re_]))))
    finish(ax, "time [s]", "|F_x| / F_y [-]", "Friction needed at each loaded tip",
           loc="best", ncol=2)


def draw_stick(ax, g, frames=12):
    cmap = matplotlib.colors.ListedColormap(plt.cm.viridis_r(np.linspace(0.12, 1, 256)))
    norm = matplotlib.colors.Normalize(g.t[0], g.t[-1])
    picks = [int(np.argmin(np.abs(g.t - tk))) for tk in np.linspace(g.t[0], g.t[-1], frames)]
    for k in picks:
        colour = cmap(norm(g.t[k]))
        proximal, distal = g.link_points(k)
        ls = "--" if g.dsp[k] else "-"
        for p, q in zip(proximal, distal):
            ax.plot([p[0], q[0]], [p[1], q[1]], ls=ls, color=colour, lw=1.5)
        ax.plot(g.col["com_x"][k], g.col["com_y"][k], "*", color=colour, ms=9)
    ax.axhline(0, color="0.4", lw=1.2)
    ax.plot([], [], "k-", label="SSP")
    ax.plot([], [], "k--", label="DSP")
    ax.plot([], [], "k*", ls="none", label="CoM")
    ax.set_aspect("equal")
    ax.figure.colorbar(matplotlib.cm.ScalarMappable(norm, cmap), ax=ax, label="time [s]",
                       shrink=0.8)
    finish(ax, "x [m]", "y [m]", f"Stick diagram of the step (Mu Fig. 3.6), {frames} frames",
           loc="best")


# ---------------------------------------------------------------------------------------------
# Pictures


def headline(g):
    s = g.s
    return (f"{s['robot']}: step {g.L:g} m in {g.T:g} s ({s['speed']:.3g} m/s), "
            f"energy {s['energy_J']:.3g} J, cost of transport {s['cost_of_transport']:.3g}")


def joint_angles_figure(g):
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8.2, 8), sharex=True)
    draw_angles(ax1, g, legend=False)
    draw_rates(ax2, g)
    ax1.set_xlabel("")
    ax2.set_xlim(0, 2 * g.T)
    _, angles, rates, _ = physical_links(g)
    text = "; ".join(f"{name} {a:.2f}°, {r:.3f} rad/s"
                     for name, (a, r) in jumps(g, angles, rates).items())
    fig.suptitle(f"Link angles and rates of {g.s['robot']} over two steps (Mu Fig. 3.3), "
                 f"legs swapped in step 2\nContinuity, largest jump at {text}", fontsize=10)
    fig.legend(*ax1.get_legend_handles_labels(), loc="lower center", ncol=4, fontsize=8)
    fig.tight_layout(rect=(0, 0.055, 1, 1))
    return fig


def paths_figure(g):
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8.2, 6.8),
                                   gridspec_kw={"height_ratios": [1.6, 1]})
    draw_positions(ax1, g)
    draw_swing_path(ax2, g)
    fig.suptitle(f"Hip and tip paths (Mu Fig. 3.2)\n{headline(g)}", fontsize=10)
    fig.tight_layout()
    return fig


def dsp_zmp_figure(g):
    return plot_io.panel_figure(draw_dsp_zmp, g, headline(g), (8.2, 5.2))


def stick_figure(g):
    """The stick diagram on a figure shaped like the robot's sweep (equal axes)."""
    points = np.concatenate([np.vstack(g.link_points(k)) for k in range(len(g.t))])
    width, height = np.ptp(points[:, 0]), np.ptp(points[:, 1])
    return plot_io.panel_figure(draw_stick, g, headline(g),
                                (min(max(7 * width / height + 2, 5.5), 10), 7))


def forces_figure(g):
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8.2, 7.2), sharex=True)
    draw_vertical_forces(ax1, g)
    draw_friction(ax2, g)
    ax1.set_xlabel("")
    ax2.set_xlim(g.t[0], g.t[-1])
    fig.suptitle(f"Contact forces (Mu Fig. 3.5)\n{headline(g)}", fontsize=10)
    fig.tight_layout()
    return fig


def overview_figure(g):
    fig, axes = plt.subplots(3, 2, figsize=(12, 11))
    draw_angles(axes[0, 0], g, legend=False)
    axes[0, 0].legend(fontsize=8, ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.17))
    draw_positions(axes[0, 1], g)
    draw_vertical_forces(axes[1, 0], g)
    draw_friction(axes[1, 1], g)
    (draw_dsp_zmp if g.dsp.any() else draw_swing_path)(axes[2, 0], g)
    draw_stick(axes[2, 1], g)
    fig.suptitle(headline(g), fontsize=11)
    fig.tight_layout()
    return fig


def pictures(g):
    """(file name, figure maker) for every picture this gait has data for."""
    out = [("joint_angles.png", joint_angles_figure), ("paths.png", paths_figure)]
    if g.dsp.any():
        out.append(("dsp_zmp.png", dsp_zmp_figure))
    return out + [("forces.png", forces_figure),
                  ("stick.png", stick_figure),
                  ("overview.png", overview_figure)]


def main(result_dir):
    g = Gait(result_dir)
    if not g.dsp.any():
        print("dsp_zmp.png skipped: the trajectory has no DSP rows", file=sys.stderr)
    for name, make in pictures(g):
        fig = make(g)
        path = os.path.join(result_dir, name)
        fig.savefig(path, dpi=DPI)
        plt.close(fig)
        print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
