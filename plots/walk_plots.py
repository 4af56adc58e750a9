#!/usr/bin/python3
"""Draws the pictures of a `gaitopt simulate` result folder (a closed-loop walk).

Usage: walk_plots.py RESULT_DIR
Reads RESULT_DIR/walk.csv, steps.csv, stick.csv and summary.json and writes into RESULT_DIR,
printing one line per picture written:
  walk_stick.png     the whole walk as a stick diagram in the world frame, the fall marked
  tracking.png       tracking error theta - theta_ref per link over time
  torques.png        applied joint torques against the reference's, one panel per joint
  forces.png         normal and tangential ground forces at both tips, friction they need
  walk_overview.png  the main panels of the above on one page
  poincare.png       Poincare multipliers in the complex plane (only when summary.json has them)
A walk that ended before walk.csv's second sample has no time series: walk_stick.png and
walk_overview.png then show the robot where it stopped (or, without a sample, say why it ended).
walk.csv labels links relative to the current stance leg (theta1 is always the stance shank of a
five-link robot), angles follow dynamics/conventions.hpp (from the upward vertical, clockwise
positive), units are SI. A missing file, column or key, or a malformed value, ends the script
with exit code 1.
"""
import math
import os
import re
import sys
import textwrap

import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402

import multipliers_plot  # noqa: E402
import plot_io  # noqa: E402
from plot_io import InputError  # noqa: E402
from robot_foot import robot_foot  # noqa: E402

PHASES = ("SSP", "DSP")
IMPACTS = ("double", "single", "compliant", "lcp", "dart", "")
WALK_TAIL = ["fb_x", "fb_y", "fe_x", "fe_y", "hip_x", "hip_y"]
STEPS_COLUMNS = ["step", "ok", "impact", "ssp_duration", "dsp_duration", "advance",
                 "max_tracking_error", "failure"]
STICK_COLUMNS = ["t", "step", "link", "x0", "y0", "x1", "y1"]
SUMMARY_STRINGS = ["robot", "reference", "controller", "ground", "failure"]
# Link and joint names of the five-link robot (docs/design.md#conventions: tau0 stance ankle,
# tau1..tau4 knee, hip, hip, knee as Mu 2.39); other robots get numbered names.
FIVE_LINKS = ["stance shank", "stance thigh", "torso", "swing thigh", "swing shank"]
FIVE_JOINTS = ["stance ankle", "stance knee", "stance hip", "swing hip", "swing knee"]
# Single-support stick frames drawn over a whole walk (a dozen per phase for a short walk).
MAX_FRAMES = 60
# A tip pushing less than this on the ground counts as unloaded for the friction ratio [N].
LOADED_N = 1.0


# ---------------------------------------------------------------------------------------------
# Reading


def link_count(path, header):
    """N from the theta<i> columns of walk.csv (theta_ref<i> not counted)."""
    n = sum(1 for name in header if re.fullmatch(r"theta[1-9][0-9]*", name))
    if n < 2:
        raise InputError(f"{path}: found {n} theta<i> columns, a biped has at least two links")
    return n


def walk_columns(n):
    return (["t", "step", "phase", "stance_x", "stance_y"]
            + [f"theta{i}" for i in range(1, n + 1)] + [f"theta_ref{i}" for i in range(1, n + 1)]
            + [f"tau{j}" for j in range(n)] + [f"tau_ref{j}" for j in range(n)] + WALK_TAIL)


def check_step_numbers(path, steps, non_decreasing=True):
    """Step indices are whole numbers from 1 on, in order when non_decreasing."""
    bad = (steps < 1) | (steps != np.round(steps))
    if np.any(bad):
        k = int(np.argmax(bad))
        raise InputError(f"{path}:{k + 2}: column 'step': expected a step index 1, 2, ..., "
                         f"found {steps[k]:g}")
    if non_decreasing:
        plot_io.check_increasing(path, "step", steps)


def read_walk(path):
    """(columns: name -> array, phase: str array, n_links) of walk.csv; a walk that ended at its
    first time step has one row or none (short_walk_pictures)."""
    header, rows = plot_io.read_rows(path, "walk", min_rows=0)
    plot_io.require_columns(path, header, ["t", "step", "phase", "theta1"])
    n = link_count(path, header)
    cols = plot_io.columns(path, header, rows, walk_columns(n), strings={"phase"})
    phase = cols.pop("phase")
    plot_io.check_values(path, "phase", phase, PHASES)
    plot_io.check_increasing(path, "t", cols["t"])
    check_step_numbers(path, cols["step"])
    return cols, phase, n


def read_steps(path):
    """steps.csv: name -> array, one entry per step (ok as bool)."""
    cols = plot_io.read_csv(path, "steps", STEPS_COLUMNS, strings={"impact", "failure"},
                            finite=False)
    check_step_numbers(path, cols["step"])
    plot_io.check_values(path, "impact", cols["impact"], IMPACTS)
    if np.any((cols["ok"] != 0) & (cols["ok"] != 1)):
        raise InputError(f"{path}: column 'ok': expected 0 or 1")
    cols["ok"] = cols["ok"] == 1
    return cols


def read_stick(path, n):
    """stick.csv as a list of frames (t, step, starts n x 2, ends n x 2), in time order: each
    frame is a block of n rows with links 1..n (two frames may share a time)."""
    cols = plot_io.read_csv(path, "stick diagram", STICK_COLUMNS, min_rows=0)
    plot_io.check_increasing(path, "t", cols["t"])
    link = cols["link"]
    frames = []
    for first in range(0, len(link), n):
        rows = np.arange(first, min(first + n, len(link)))
        if len(rows) != n or np.any(link[rows] != np.arange(1, n + 1)):
            raise InputError(f"{path}:{first + 2}: column 'link': expected frames of {n} rows "
                             f"with links 1..{n} (walk.csv has {n} links)")
        frames.append((cols["t"][first], int(cols["step"][first]),
                       np.column_stack([cols["x0"][rows], cols["y0"][rows]]),
                       np.column_stack([cols["x1"][rows], cols["y1"][rows]])))
    return frames


def read_summary(path):
    s = plot_io.read_json(path, "summary")
    plot_io.require_keys(path, s, SUMMARY_STRINGS[:4] + [
        "steps_requested", "steps_completed", "fell", "failure", "max_tracking_error",
        "poincare_max_multiplier", "poincare_multipliers"])
    for key in SUMMARY_STRINGS:
        plot_io.require_type(path, s, key, str, "a string")
    plot_io.require_numbers(path, s, ["steps_requested", "steps_completed", "max_tracking_error"])
    plot_io.require_numbers(path, s, ["poincare_max_multiplier"], nullable=True)
    plot_io.require_type(path, s, "fell", bool, "true or false")
    if "friction" in s:
        plot_io.require_numbers(path, s, ["friction"])
    s["multipliers"] = plot_io.read_multipliers(path, s["poincare_multipliers"])
    return s


class Walk:
    """A simulated walk from the files, with what the pictures derive from it."""

    def __init__(self, result_dir):
        self.dir = result_dir
        self.col, self.phase, self.n = read_walk(os.path.join(result_dir, "walk.csv"))
        self.steps = read_steps(os.path.join(result_dir, "steps.csv"))
        self.frames = read_stick(os.path.join(result_dir, "stick.csv"), self.n)
        self.s = read_summary(os.path.join(result_dir, "summary.json"))
        self.foot = robot_foot(os.path.join(result_dir, "summary.json"), self.s)[0]
        self.t = self.col["t"]
        self.dsp = self.phase == "DSP"
        self.theta = self.stack("theta", 1)
        self.theta_ref = self.stack("theta_ref", 1)
        self.tau = self.stack("tau", 0)
        self.tau_ref = self.stack("tau_ref", 0)
        self.error = plot_io.wrap(self.theta - self.theta_ref)

    def stack(self, prefix, first):
        return np.column_stack([self.col[f"{prefix}{i}"] for i in range(first, first + self.n)])

    def link_names(self):
        return FIVE_LINKS if self.n == 5 else [f"link {i}" for i in range(1, self.n + 1)]

    def joint_names(self):
        return FIVE_JOINTS if self.n == 5 else [f"joint {j}" for j in range(self.n)]

    def step_starts(self):
        """(step index, first time) of every step after the first in walk.csv."""
        step = self.col["step"]
        starts = np.flatnonzero(np.diff(step) > 0) + 1
        return [(int(step[k]), self.t[k]) for k in starts]

    def dsp_intervals(self):
        """(start, end) times of the runs of DSP rows."""
        edges = np.diff(np.concatenate([[0], self.dsp.astype(int), [0]]))
        starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
        return [(self.t[a], self.t[b]) for a, b in zip(starts, ends)]

    def impact_before(self, step):
        """The impact that ended the step before `step` (steps.csv), '' when unknown."""
        k = np.flatnonzero(self.steps["step"] == step - 1)
        return str(self.steps["impact"][k[0]]) if len(k) else ""


# ---------------------------------------------------------------------------------------------
# Helpers


def link_colours(n):
    """Stance side blue, swing side orange, darker toward the tips; the middle link grey."""
    return style.link_colours(n)


def time_colours(w):
    """(colormap, norm) over the walk's time: later frames darker."""
    return style.time_colours(w.t[0], w.t[-1])


# At most this many step labels on a time axis: twenty side by side ran into each other and,
# drawn upright inside the axes, into the curves.
MAX_STEP_LABELS = 6


def labelled_steps(starts):
    """The (step, t) of `starts` that get a label: every k-th, at most MAX_STEP_LABELS."""
    stride = max(1, math.ceil(len(starts) / MAX_STEP_LABELS))
    return starts[::stride]


def mark_steps(ax, w, labels=True):
    """Shades DSP intervals and dots step starts; with `labels`, some step starts are labelled
    with the step number and the impact that began it above the axes, off the curves (the title
    moves up to make room); a red line at the end of a walk that fell."""
    for k, (a, b) in enumerate(w.dsp_intervals()):
        ax.axvspan(a, b, **style.DSP_SHADE, label="DSP" if k == 0 else None)
    starts = list(w.step_starts())
    for k, (step, t) in enumerate(starts):
        ax.axvline(t, color="k", ls=":", lw=0.8, label="step start" if k == 0 else None)
    if labels:
        for step, t in labelled_steps(starts):
            impact = w.impact_before(step)
            ax.annotate(f"step {step}" + (f" ({impact})" if impact else ""), (t, 1),
                        xycoords=("data", "axes fraction"), xytext=(0, 2),
                        textcoords="offset points", fontsize=7, color="0.3", ha="center",
                        va="bottom", annotation_clip=False)
    if w.s["fell"]:
        ax.axvline(w.t[-1], color="tab:red", lw=1.2, label="fall")


# How far below a time panel's bottom its legend starts [in]: clear of the tick labels and
# the x label, so the legend sits on no curve.
PANEL_LEGEND_DROP_IN = 0.55


def legend_below(ax, ncol):
    """The panel's legend under its x label: loc="best" still sat on the curves of a walk
    that fills every corner of the panel."""
    ax.legend(loc="upper center", ncol=ncol, fontsize=7,
              bbox_to_anchor=(0.5, -PANEL_LEGEND_DROP_IN / axes_height_in(ax)))


finish = style.finish


def fall_text(w, width=60):
    k = np.flatnonzero(~w.steps["ok"])
    step = int(w.steps["step"][k[0]]) if len(k) else int(w.col["step"][-1])
    text = f"fell in step {step} at t = {w.t[-1]:.3g} s"
    if w.s["failure"]:
        text += f": {w.s['failure']}"
    return textwrap.fill(text, width)


def headline(w):
    s = w.s
    outcome = (f"fell after {s['steps_completed']} of {s['steps_requested']} steps" if s["fell"]
               else f"{s['steps_completed']} of {s['steps_requested']} steps")
    return (f"{s['robot']}, {s['controller']} on {s['ground']} ground: {outcome}, "
            f"max tracking error {s['max_tracking_error']:.3g} rad")


# ---------------------------------------------------------------------------------------------
# Panels (each draws on one axes)


def frames_per_phase(w):
    """Stick frames drawn per (single, double) support phase: about a dozen in a short walk,
    fewer as the walk gets longer (MAX_FRAMES single-support frames in all)."""
    steps = max(1, len({step for _, step, _, _ in w.frames}))
    ssp = int(np.clip(MAX_FRAMES // steps, 2, 12))
    return ssp, max(1, ssp // 3)


def thin_frames(w):
    """The stick.csv frames drawn: per step and phase, frames_per_phase() spread evenly in
    time (the phase's first and last included)."""
    groups = {}
    for frame in w.frames:
        k = min(int(np.searchsorted(w.t, frame[0])), len(w.t) - 1)
        groups.setdefault((frame[1], bool(w.dsp[k])), []).append(frame)
    ssp, dsp = frames_per_phase(w)
    out = []
    for (_, in_dsp), frames in groups.items():
        count = min(dsp if in_dsp else ssp, len(frames))
        picks = np.unique(np.round(np.linspace(0, len(frames) - 1, count)).astype(int))
        out += [frames[i] for i in picks]
    return sorted(out, key=lambda f: f[0])


def draw_walk_stick(ax, w, colorbar=True):
    """Every stick.csv frame in the world frame coloured by time (DSP frames dashed), the hip
    path, each step's stance tip with the step number and the impact that began the step, the
    ground line and, if the walk fell, a red X at the last hip position with the failure."""
    cmap, norm = time_colours(w)
    frames = thin_frames(w)
    for t, _, starts, ends in frames:
        k = min(int(np.searchsorted(w.t, t)), len(w.t) - 1)
        ls = "--" if w.dsp[k] else "-"
        for p, q in zip(starts, ends):
            ax.plot([p[0], q[0]], [p[1], q[1]], ls=ls, color=cmap(norm(t)), lw=1.3)
    ax.plot(w.col["hip_x"], w.col["hip_y"], color="0.5", lw=0.8, label="hip path")
    ax.axhline(0, color="0.4", lw=1.2)
    first = np.concatenate([[True], np.diff(w.col["step"]) > 0])
    for x, y, step in zip(w.col["stance_x"][first], w.col["stance_y"][first],
                          w.col["step"][first]):
        impact = w.impact_before(step)
        if w.foot is not None:  # the stance foot, heel to toe
            ax.plot([x - w.foot[0], x + w.foot[1]], [y, y], color="k", lw=2.5,
                    solid_capstyle="butt")
        ax.plot(x, y, "k^", ms=6)
        ax.annotate(f"{int(step)}" + (f"\n{impact}" if impact else ""), (x, y),
                    xytext=(0, -9), textcoords="offset points", ha="center", va="top",
                    fontsize=7)
    if w.s["fell"]:
        x, y = w.col["hip_x"][-1], w.col["hip_y"][-1]
        ax.plot(x, y, "X", color="tab:red", ms=12, mec="k", label="fall (hip)")
        ax.annotate(fall_text(w, 45), (x, y), xytext=(0.99, 0.97), textcoords="axes fraction",
                    ha="right", va="top", fontsize=8, color="tab:red",
                    bbox={"fc": "w", "ec": "tab:red", "alpha": 0.9},
                    arrowprops={"arrowstyle": "->", "color": "tab:red"})
    ax.plot([], [], "k-", label="SSP")
    if w.dsp.any():  # a walk without a double support draws no dashed frames
        ax.plot([], [], "k--", label="DSP")
    ax.plot([], [], "k^", ls="none", label="stance tip: step (impact before)")
    if w.foot is not None:
        ax.plot([], [], "k-", lw=2.5, label=f"foot: heel {w.foot[0]:g} m, toe {w.foot[1]:g} m")
    ax.set_aspect("equal")
    ax.set_ylim(bottom=min(-0.12, ax.get_ylim()[0]))
    if colorbar and w.t[-1] > w.t[0]:  # one instant has no time scale
        ax.figure.colorbar(matplotlib.cm.ScalarMappable(norm, cmap), ax=ax, label="time [s]",
                           shrink=0.8, pad=0.01)
    ssp, dsp = frames_per_phase(w)
    finish(ax, "x (world) [m]", "y [m]",
           f"Stick diagram, {len(frames)} of {len(w.frames)} frames (≤ {ssp} per SSP"
           + (f", {dsp} per DSP)" if w.dsp.any() else ")"), loc="upper center",
           bbox_to_anchor=(0.5, -LEGEND_DROP_IN / axes_height_in(ax)), ncol=4)


# How far below the stick diagram its legend starts [in]: clear of the ticks, the step labels
# and the x label whatever the diagram's height (a long walk drawn to scale is a thin strip).
LEGEND_DROP_IN = 0.5


def axes_height_in(ax):
    """The drawn height of `ax` [in], after its aspect ratio is applied."""
    ax.apply_aspect()
    return ax.get_position().height * ax.figure.get_figheight()


def draw_tracking(ax, w, legend=True):
    """theta_i - theta_ref_i [deg] per link (wrapped), with step starts and DSP shading."""
    for i, (name, colour) in enumerate(zip(w.link_names(), link_colours(w.n))):
        ax.plot(w.t, np.degrees(w.error[:, i]), color=colour, lw=1.4, label=f"θ{i + 1} {name}")
    mark_steps(ax, w)
    worst = np.max(np.abs(w.error))
    ax.axhline(0, color="0.5", lw=0.8)
    finish(ax, "time [s]", "θ − θ_ref [deg]",
           f"Tracking error: max {w.s['max_tracking_error']:.3g} rad "
           f"({math.degrees(w.s['max_tracking_error']):.3g}°, summary); "
           f"{worst:.3g} rad in walk.csv", legend=False)
    ax.set_title(ax.get_title(), pad=14)  # above the step labels
    if legend:
        legend_below(ax, ncol=4)


def draw_torque(ax, w, j, colour="tab:blue"):
    """tau_j (solid) against tau_ref_j (dashed) [N m] on one axes."""
    ax.plot(w.t, w.tau_ref[:, j], color="k", ls="--", lw=1.1, label="reference")
    ax.plot(w.t, w.tau[:, j], color=colour, lw=1.4, label="applied")
    mark_steps(ax, w, labels=False)
    finish(ax, "time [s]", "torque [N m]", f"τ{j} {w.joint_names()[j]}", legend=j == 0,
           loc="best")


def draw_all_torques(ax, w):
    """Every joint's applied torque (solid) and reference (dashed) on one axes."""
    for j, colour in enumerate(link_colours(w.n)):
        ax.plot(w.t, w.tau_ref[:, j], color=colour, ls="--", lw=0.9)
        ax.plot(w.t, w.tau[:, j], color=colour, lw=1.4, label=f"τ{j} {w.joint_names()[j]}")
    mark_steps(ax, w, labels=False)
    finish(ax, "time [s]", "torque [N m]", "Joint torques (dashed: reference)", legend=False)
    legend_below(ax, ncol=4)


def draw_tip_forces(ax, w, axis, symbol, what):
    """One component ('y' normal, 'x' tangential) of the ground forces at B and E."""
    ax.plot(w.t, w.col[f"fb_{axis}"], color="tab:blue", lw=1.6, label=f"B (stance) ${symbol}$")
    ax.plot(w.t, w.col[f"fe_{axis}"], color="tab:orange", lw=1.6, label=f"E (swing) ${symbol}$")
    ax.axhline(0, color="0.5", lw=0.8)
    mark_steps(ax, w, labels=False)
    finish(ax, "time [s]", f"{what} force [N]", f"{what.capitalize()} ground forces", legend=False)
    legend_below(ax, ncol=4)


def draw_normal_forces(ax, w):
    """Normal (vertical) ground forces at the stance tip B and the swing tip E."""
    draw_tip_forces(ax, w, "y", "f_n", "normal")


def draw_tangential_forces(ax, w):
    """Tangential (horizontal) ground forces at B and E."""
    draw_tip_forces(ax, w, "x", "f_t", "tangential")


def friction_ratio(w, tip):
    """|f_t| / f_n at tip 'b' or 'e'; NaN where the tip carries less than LOADED_N."""
    ft, fn = w.col[f"f{tip}_x"], w.col[f"f{tip}_y"]
    loaded = fn > LOADED_N
    return np.where(loaded, np.abs(ft) / np.where(loaded, fn, 1.0), np.nan)


def draw_friction(ax, w):
    """The friction each loaded tip needs, against the robot's friction coefficient."""
    rb, re_ = friction_ratio(w, "b"), friction_ratio(w, "e")
    ax.plot(w.t, rb, color="tab:blue", lw=1.6, label="B  $|f_t|/f_n$")
    ax.plot(w.t, re_, color="tab:orange", lw=1.6, label="E  $|f_t|/f_n$")
    needed = np.concatenate([rb, re_])
    top = np.nanpercentile(needed, 99) if np.isfinite(needed).any() else 1.0
    mu = w.s.get("friction")
    if mu is not None:
        ax.axhline(mu, color="k", ls="--", lw=1.2, label=f"friction μ = {mu:g}")
        top = max(top, mu)
    mark_steps(ax, w, labels=False)
    ax.set_ylim(0, 1.25 * top)
    finish(ax, "time [s]", "|f_t| / f_n [-]",
           f"Friction needed where a tip carries more than {LOADED_N:g} N", legend=False)
    legend_below(ax, ncol=5)


def draw_poincare(ax, w):
    """Multipliers of the step-to-step (Poincare) map in the complex plane with the unit
    circle (multipliers_plot.draw_unit_circle): all inside means the cycle is locally stable."""
    z = w.s["multipliers"]
    multipliers_plot.draw_unit_circle(ax, [(f"multipliers ({len(z)})", z, style.MULTIPLIER,
                                            "o")])
    largest = w.s["poincare_max_multiplier"]
    verdict = "" if largest is None else (f": largest |λ| = {largest:.4g} "
                                          f"({'stable' if largest < 1 else 'unstable'})")
    ax.set_title(f"Poincaré multipliers ({len(z)}){verdict}")
    ax.legend(loc="upper left")


# ---------------------------------------------------------------------------------------------
# Pictures


def stick_figure(w):
    """The stick diagram on a figure shaped like the walk (equal axes)."""
    points = np.concatenate([np.vstack([a, b]) for _, _, a, b in w.frames])
    width = np.ptp(points[:, 0]) + 0.2
    height = max(np.ptp(points[:, 1]), np.max(points[:, 1])) + 0.3
    fig_w = min(max(5.5 * width / height + 2.5, 7), 18)
    return plot_io.panel_figure(draw_walk_stick, w, headline(w), (fig_w, 6.5))


def tracking_figure(w):
    return plot_io.panel_figure(draw_tracking, w, headline(w), (9, 5))


def torques_figure(w):
    """Small multiples: one panel per joint, applied against reference torque."""
    cols = 2 if w.n <= 4 else 3
    rows = math.ceil(w.n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.0 * rows + 0.6), sharex=True,
                             squeeze=False)
    for j, (ax, colour) in enumerate(zip(axes.flat, link_colours(w.n))):
        draw_torque(ax, w, j, colour)
        if j < w.n - cols:
            ax.set_xlabel("")
        else:  # the lowest panel of its column
            ax.xaxis.set_tick_params(labelbottom=True)
    for ax in axes.flat[w.n:]:
        ax.set_visible(False)
    fig.suptitle(f"Joint torques, applied (solid) and reference (dashed)\n{headline(w)}",
                 fontsize=10)
    fig.tight_layout()
    return fig


def forces_figure(w):
    fig, axes = plt.subplots(3, 1, figsize=(8.2, 9), sharex=True)
    draw_normal_forces(axes[0], w)
    draw_tangential_forces(axes[1], w)
    draw_friction(axes[2], w)
    for ax in axes[:2]:
        ax.set_xlabel("")
    axes[2].set_xlim(w.t[0], w.t[-1])
    fig.suptitle(f"Ground forces on the robot\n{headline(w)}", fontsize=10)
    fig.tight_layout()
    return fig


def overview_figure(w):
    """Stick diagram on top; tracking, torques, normal forces and friction below."""
    fig = plt.figure(figsize=(13, 12))
    grid = fig.add_gridspec(3, 2, height_ratios=[1.3, 1, 1])
    draw_walk_stick(fig.add_subplot(grid[0, :]), w, colorbar=False)
    draw_tracking(fig.add_subplot(grid[1, 0]), w)
    draw_normal_forces(fig.add_subplot(grid[1, 1]), w)
    draw_all_torques(fig.add_subplot(grid[2, 0]), w)
    draw_friction(fig.add_subplot(grid[2, 1]), w)
    fig.suptitle(headline(w), fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.98))  # the headline above the stick diagram's title
    return fig


def poincare_figure(w):
    return plot_io.panel_figure(draw_poincare, w, headline(w), (6, 6), fontsize=8)


def ended_figure(w):
    """A walk without a sample (it ended in its first time step): when and why, in words."""
    fig, ax = plt.subplots(figsize=(7, 3))
    ax.set_axis_off()
    ax.text(0.5, 0.5, textwrap.fill(f"The walk ended in its first time step, before walk.csv's "
                                    f"first sample: {w.s['failure'] or 'no failure given'}", 60),
            ha="center", va="center", fontsize=10, color="tab:red", transform=ax.transAxes)
    fig.suptitle(headline(w), fontsize=9)
    return fig


def short_walk_pictures(w):
    """(file name, figure maker) of a walk of fewer than two samples, which has no time series:
    the robot where it stopped, with why, as the stick diagram and the overview (a walk that
    failed at t = 0 got no picture, and an "error:" from a run that exited 0)."""
    make = stick_figure if w.frames else ended_figure
    return [("walk_stick.png", make), ("walk_overview.png", make)]


def pictures(w):
    """(file name, figure maker) for every picture this walk has data for."""
    if len(w.t) < 2:
        return short_walk_pictures(w)
    out = [("walk_stick.png", stick_figure), ("tracking.png", tracking_figure),
           ("torques.png", torques_figure), ("forces.png", forces_figure),
           ("walk_overview.png", overview_figure)]
    if w.s["multipliers"] is not None:
        out.append(("poincare.png", poincare_figure))
    return out


def main(result_dir):
    w = Walk(result_dir)
    # Without multipliers and without a failure the map was not asked for (--no-poincare).
    if w.s["multipliers"] is None and w.s.get("poincare_failure"):
        print(f"poincare.png skipped: {w.s['poincare_failure']}", file=sys.stderr)
    if len(w.t) < 2:
        samples = f"{len(w.t)} sample" + ("" if len(w.t) == 1 else "s")
        print(f"tracking.png, torques.png and forces.png skipped: walk.csv holds {samples}, no "
              "time series", file=sys.stderr)
    for name, make in pictures(w):
        fig = make(w)
        path = os.path.join(result_dir, name)
        style.save(fig, path)
        print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
