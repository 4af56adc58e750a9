#!/usr/bin/python3
"""Draws the pictures of a gait result folder (docs/design.md#the-export-contract), after
Mu (2004) ch. 3.

Usage: gait_plots.py RESULT_DIR
Reads RESULT_DIR/trajectory.csv (one step, stance tip B at the origin) and RESULT_DIR/summary.json
and writes into RESULT_DIR, printing one line per picture written:
  joint_angles.png  link angles and rates per physical link over two steps (Mu Fig. 3.3)
  paths.png         hip and tip positions over two steps, swing-tip path (Fig. 3.2)
  dsp_zmp.png       CoM, hip and ZMP in the double support phase (Fig. 3.4; needs DSP rows)
  forces.png        vertical tip forces and the friction they need (Fig. 3.5)
  torques.png       joint torques over the step
  zmp.png           ZMP (centre of pressure) against the heel and toe of the foot, both phases
  stick.png         stick diagram of the step (Fig. 3.6), about a dozen frames per phase
  overview.png      angles, positions, torques, swing clearance, forces, friction, ZMP against
                    the foot and the stick diagram on one page
Angles follow dynamics/conventions.hpp: u_i = (sin theta_i, cos theta_i), theta from the upward
vertical, clockwise positive. Step 2 is step 1 with the legs swapped (link i <-> link N+1-i, leg
links turned by pi, the torso unchanged), so both steps come from the one step in the file.
The foot (heel and toe around each tip) comes from summary.json's `foot` key, or else from the
robot file in configs/robots/ that the summary names; without either the tips are points.
A missing file, column or key, or a malformed value, ends the script with exit code 1.
"""
import math
import os
import sys

import matplotlib
import numpy as np

import plot_io
import plot_style as style
from plot_io import InputError
from robot_foot import POINT_FEET, robot_foot, support_region

plt = style.pyplot()

# Columns used besides t, phase, theta<i>, dtheta<i> and tau<j>.
TAIL_COLUMNS = ["fb_x", "fb_y", "fe_x", "fe_y", "zmp_x", "hip_x", "swing_x", "swing_y", "com_x",
                "com_y"]
SUMMARY_NUMBERS = ["step_length", "duration", "speed", "friction", "min_normal_force",
                   "max_friction_ratio", "min_zmp_margin", "energy_J", "cost_of_transport"]
# Link lengths must reproduce swing_x/swing_y from theta to this tolerance [m].
KINEMATICS_TOLERANCE = 1e-6
# Stick-diagram frames per phase (the DSP gets fewer: it is a sixth of the step or less).
SSP_FRAMES, DSP_FRAMES = 12, 4


# ---------------------------------------------------------------------------------------------
# Reading


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
        self.traj = plot_io.read_trajectory(csv_path, TAIL_COLUMNS)
        self.col, self.phase, self.n = self.traj.col, self.traj.phase, self.traj.n
        self.traj.require([f"dtheta{i}" for i in range(1, self.n + 1)]
                          + [f"tau{j}" for j in range(self.n)])
        summary_path = os.path.join(result_dir, "summary.json")
        self.s = read_summary(summary_path, self.n)
        self.t = self.traj.t
        self.theta = self.traj.stack("theta", 1, self.n)
        self.dtheta = self.traj.stack("dtheta", 1, self.n)
        self.tau = self.traj.stack("tau", 0, self.n)
        self.dsp = self.traj.dsp
        self.L = self.s["step_length"]
        self.T = self.s["duration"]
        self.t_touchdown = self.traj.t_touchdown
        self.torso = np.array([not link["continues"] for link in self.s["links"]])
        self.swap = np.arange(self.n)[::-1]
        if np.any(self.torso != self.torso[self.swap]):
            raise InputError("summary.json: key 'links': the torso (continues = false) must sit "
                             "in the middle of the chain for the leg swap")
        self.foot, self.foot_source = robot_foot(summary_path, self.s)
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

    def support(self):
        """(back, front) edges of the support region at every row [m from B]
        (robot_foot.support_region)."""
        return support_region(self.dsp, self.L, self.foot)

    def zmp_margin(self):
        """Distance of the ZMP inside the support region at every row [m], negative outside
        (what summary.json's min_zmp_margin is the minimum of)."""
        back, front = self.support()
        zmp = self.col["zmp_x"]
        return np.minimum(zmp - back, front - zmp)

    def joint_names(self):
        joints = self.s.get("joints")
        if (isinstance(joints, list) and len(joints) == self.n
                and all(isinstance(j, dict) and isinstance(j.get("name"), str) for j in joints)):
            return [j["name"].replace("_", " ") for j in joints]
        return [f"joint {j}" for j in range(self.n)]


# ---------------------------------------------------------------------------------------------
# Two steps from one: physical legs A (stance in step 1) and B


def physical_links(g):
    """Time (2 steps), angles [rad] and rates [rad/s] per physical link, and their labels.

    A leg link is shown pointing from its foot toward the hip: theta in stance, theta - pi in
    swing, so a link keeps its curve through the leg swap."""
    shift = np.where(g.torso, 0.0, math.pi)
    mid = (g.n - 1) / 2
    step1 = plot_io.wrap(g.theta - np.where(np.arange(g.n) > mid, shift, 0.0))
    step2 = plot_io.wrap(g.theta[:, g.swap] - np.where(np.arange(g.n) < mid, shift, 0.0))
    t = np.concatenate([g.t, g.t + g.T])
    names = [link["name"].replace("stance_", "").replace("swing_", "") for link in g.s["links"]]
    labels = [name if g.torso[i] else f"leg {'A' if i < mid else 'B'} {name}".removesuffix(" leg")
              for i, name in enumerate(names)]
    return t, np.vstack([step1, step2]), np.vstack([g.dtheta, g.dtheta[:, g.swap]]), labels


def link_colours(g):
    return style.link_colours(g.n, g.torso)


def jumps(g, angles, rates):
    """Largest change of any link's angle [deg] and rate [rad/s] at touchdown and at the swap."""
    k = len(g.t)
    if not g.dsp.any():
        pairs = {"touchdown and leg swap": (k - 1, k)}
    else:
        first = int(np.argmax(g.dsp))
        pairs = {"touchdown": (first - 1, first), "leg swap": (k - 1, k)}
    return {name: (math.degrees(np.max(np.abs(plot_io.wrap(angles[j] - angles[i])))),
                   np.max(np.abs(rates[j] - rates[i]))) for name, (i, j) in pairs.items()}


def mark_phases(ax, g, steps=2):
    """Shades DSP intervals, dashes touchdowns and dots step boundaries over `steps` steps."""
    for s in range(steps):
        offset = s * g.T
        if g.dsp.any():
            ax.axvspan(offset + g.t_touchdown, offset + g.t[-1], **style.DSP_SHADE,
                       label="DSP" if s == 0 else None)
        ax.axvline(offset + g.t_touchdown, color="k", ls="--", lw=0.8,
                   label="touchdown" if s == 0 else None)
        if s > 0:
            ax.axvline(offset, color="k", ls=":", lw=0.8, label="leg swap")


finish = style.finish


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
    finish(ax, "time [s]", "x (world) [m]", "Horizontal positions over two steps",
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


def torque_style(names, j):
    """Line style of joint j's torque: the swing hip's dashed where a stance hip is drawn too,
    whose torque is nearly the same through much of a step (Mu's gait: within 0.5 N m over
    its single support) and hid it exactly."""
    both = "stance hip" in names and "swing hip" in names
    return "--" if both and names[j] == "swing hip" else "-"


def draw_torques(ax, g, legend=True):
    """Joint torques tau0..tau{N-1} over the step, the largest |tau| of each joint marked."""
    names = g.joint_names()
    for j in range(g.n):
        line, = ax.plot(g.t, g.tau[:, j], color=f"C{j}", lw=1.6, ls=torque_style(names, j),
                        label=f"τ{j} {names[j]}")
        k = int(np.argmax(np.abs(g.tau[:, j])))
        ax.plot(g.t[k], g.tau[k, j], "o", color=line.get_color(), ms=4)
    ax.axhline(0, color="0.5", lw=0.8)
    mark_phases(ax, g, steps=1)
    ax.set_xlim(g.t[0], g.t[-1])
    total = g.s.get("torque_squared")
    cost = f", ∫Στ² dt = {total:.4g} N²m²s" if plot_io.is_number(total) else ""
    finish(ax, "time [s]", "joint torque [N m]", f"Joint torques (dots: peak |τ|){cost}",
           legend=legend, ncol=3, loc="best", fontsize=7)


def draw_clearance(ax, g):
    """Height of the swing tip E above the ground over the step, its apex marked; E is on the
    ground in the DSP."""
    y = g.col["swing_y"]
    ax.plot(g.t, 1000 * y, color=style.TIP_E, lw=1.8, label="swing tip E height")
    ax.axhline(0, color="0.4", lw=1.2, label="ground")
    k = int(np.argmax(y))
    ax.plot(g.t[k], 1000 * y[k], "o", color=style.TIP_E, ms=5)
    ax.annotate(f"apex {1000 * y[k]:.0f} mm at x = {g.col['swing_x'][k]:.3f} m",
                (g.t[k], 1000 * y[k]), xytext=(0, -14), textcoords="offset points",
                ha="center", fontsize=8)
    below = y < -1e-6
    if below.any():
        ax.fill_between(g.t, 1000 * y, 0, where=below, color=style.FAIL, alpha=0.3,
                        label=f"below the ground (down to {1000 * np.min(y):.1f} mm)")
    mark_phases(ax, g, steps=1)
    ax.set_xlim(g.t[0], g.t[-1])
    ax.set_ylim(min(-0.1 * 1000 * y[k], 1000 * np.min(y) * 1.2), 1000 * y[k] * 1.35)
    finish(ax, "time [s]", "swing tip height [mm]", "Swing-tip clearance", loc="upper right",
           ncol=2)


def note_place(ax, t):
    """(x in axes fraction, alignment) of a note about the point at time t: in the half of the
    axes away from the point, along the bottom (the legend holds the top). A fixed place in the
    lower left covered the ZMP curve exactly where it left the foot at the step's start."""
    lo, hi = ax.get_xlim()
    return (0.97, "right") if (t - lo) / (hi - lo) < 0.5 else (0.03, "left")


def draw_zmp_foot(ax, g):
    """ZMP (centre of pressure) x over the whole step against the support region: the foot
    [-heel, toe] around B in the SSP, B's heel to E's toe in the DSP. Where the ZMP leaves the
    support, the worst point is marked with its distance."""
    zmp = g.col["zmp_x"]
    back, front = g.support()
    has_foot = g.foot is not None and any(g.foot)
    what = "foot" if has_foot else "tip (point foot)"
    ax.fill_between(g.t, back, front, **style.SUPPORT_SHADE,
                    label=f"support: B's {what}; DSP: B to E")
    ax.plot(g.t, back, color="0.35", lw=1.1, label="heel of B" if has_foot else "tip B")
    ax.plot(g.t, front, color="0.35", lw=1.1, ls="--",
            label="toe of B, then of E" if has_foot else "tip B, then tip E")
    ax.plot(g.t, zmp, color=style.ZMP, lw=1.9, label="ZMP (CoP) x")
    margin = g.zmp_margin()
    k = int(np.argmin(margin))
    if margin[k] < 0:
        edge = "heel" if zmp[k] < back[k] else "toe"
        text = (f"ZMP leaves the {what} by {-margin[k]:.3f} m\n"
                f"(past the {edge}, t = {g.t[k]:.3f} s)")
        colour = style.FAIL
    elif np.ptp(back) == 0 and np.all(front - back < 1e-12) and np.all(np.abs(margin) < 1e-9):
        text = "ZMP on the point foot all step (no ankle torque)"
        colour = "0.3"
    else:
        text = f"closest to an edge: {1000 * margin[k]:.0f} mm"
        colour = "0.3"
    ax.plot(g.t[k], zmp[k], "o", color=style.ZMP, mfc="none", ms=10, mew=1.5)
    mark_phases(ax, g, steps=1)
    ax.set_xlim(g.t[0], g.t[-1])
    lo, hi = min(np.min(zmp), np.min(back)), max(np.max(zmp), np.max(front))
    span = max(hi - lo, 0.1)
    ax.set_ylim(lo - 0.15 * span, hi + 0.45 * span)
    x, ha = note_place(ax, g.t[k])
    ax.annotate(text, (g.t[k], zmp[k]), xytext=(x, 0.04), textcoords="axes fraction", ha=ha,
                fontsize=8, color=colour, bbox={"fc": "w", "ec": colour},
                arrowprops={"arrowstyle": "->", "color": colour})
    foot = ("" if g.foot is None else
            f"heel {g.foot[0]:g} m, toe {g.foot[1]:g} m ({g.foot_source})")
    finish(ax, "time [s]", "x (from B) [m]",
           f"ZMP against the support, both phases; min margin (summary) "
           f"{g.s['min_zmp_margin']:.3f} m\n{foot or g.foot_source}",
           loc="upper left", ncol=2)


def stick_frames(g):
    """Rows drawn in the stick diagram: SSP_FRAMES spread over the SSP, DSP_FRAMES over the
    DSP (each phase's first and last row included)."""
    picks = []
    for rows, count in ((np.flatnonzero(~g.dsp), SSP_FRAMES), (np.flatnonzero(g.dsp), DSP_FRAMES)):
        if len(rows):
            picks += [int(rows[int(round(x))])
                      for x in np.linspace(0, len(rows) - 1, min(count, len(rows)))]
    return list(dict.fromkeys(picks))


def draw_stick(ax, g):
    cmap, norm = style.time_colours(g.t[0], g.t[-1])
    picks = stick_frames(g)
    for k in picks:
        colour = cmap(norm(g.t[k]))
        proximal, distal = g.link_points(k)
        ls = "--" if g.dsp[k] else "-"
        for p, q in zip(proximal, distal):
            ax.plot([p[0], q[0]], [p[1], q[1]], ls=ls, color=colour, lw=1.5)
        ax.plot(g.col["com_x"][k], g.col["com_y"][k], "*", color=colour, ms=9)
    if g.foot is not None and any(g.foot):
        ax.plot([-g.foot[0], g.foot[1]], [0, 0], color="k", lw=4, solid_capstyle="butt",
                label="foot of B")
    ax.axhline(0, color="0.4", lw=1.2)
    ax.plot([], [], "k-", label="SSP")
    if g.dsp.any():  # a gait without a double support (RABBIT) draws no dashed frames
        ax.plot([], [], "k--", label="DSP")
    ax.plot([], [], "k*", ls="none", label="CoM")
    ax.set_aspect("equal")
    ax.figure.colorbar(matplotlib.cm.ScalarMappable(norm, cmap), ax=ax, label="time [s]",
                       shrink=0.8)
    n_dsp = int(np.sum(g.dsp[picks]))
    frames = f"{len(picks) - n_dsp} SSP" + (f" + {n_dsp} DSP" if n_dsp else "")
    finish(ax, "x [m]", "y [m]", f"Stick diagram (Mu Fig. 3.6), {frames} frames",
           loc="upper left", fontsize=7)


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
    fig.legend(*ax1.get_legend_handles_labels(), loc="lower center", ncol=4)
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


def zmp_figure(g):
    return plot_io.panel_figure(draw_zmp_foot, g, headline(g), (8.2, 5.2))


def torques_figure(g):
    return plot_io.panel_figure(draw_torques, g, headline(g), (8.2, 5.2))


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
    fig, axes = plt.subplots(4, 2, figsize=(12, 15.5),
                             gridspec_kw={"height_ratios": [1, 1, 1, 1.35]})
    draw_angles(axes[0, 0], g, legend=False)
    axes[0, 0].legend(ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.17))
    draw_positions(axes[0, 1], g)
    draw_torques(axes[1, 0], g)
    draw_clearance(axes[1, 1], g)
    draw_vertical_forces(axes[2, 0], g)
    draw_friction(axes[2, 1], g)
    draw_zmp_foot(axes[3, 0], g)
    draw_stick(axes[3, 1], g)
    fig.suptitle(headline(g))
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    return fig


def pictures(g):
    """(file name, figure maker) for every picture this gait has data for."""
    out = [("joint_angles.png", joint_angles_figure), ("paths.png", paths_figure)]
    if g.dsp.any():
        out.append(("dsp_zmp.png", dsp_zmp_figure))
    return out + [("forces.png", forces_figure),
                  ("torques.png", torques_figure),
                  ("zmp.png", zmp_figure),
                  ("stick.png", stick_figure),
                  ("overview.png", overview_figure)]


def main(result_dir):
    g = Gait(result_dir)  # without DSP rows (RABBIT, the compass gait) no dsp_zmp.png, by design
    if g.foot is None and g.foot_source != POINT_FEET:
        print(f"note: ZMP drawn against point tips: {g.foot_source}", file=sys.stderr)
    for name, make in pictures(g):
        path = os.path.join(result_dir, name)
        style.save(make(g), path, dpi=style.PAGE_DPI if name == "overview.png" else style.DPI)
        print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
