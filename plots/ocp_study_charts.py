#!/usr/bin/python3
"""Charts and markdown tables of the collocation study (bench/ocp_study).

Usage: ocp_study_charts.py DIR
Reads the CSVs bench/ocp_study wrote into DIR (collocation.csv, derivatives.csv, guesses.csv;
at least one) and writes next to them, per study present:
  collocation: collocation_accuracy_time.png (re-simulated error against solve time),
               collocation_order.png (error against segments, fitted orders in the legend),
               collocation.md
  derivatives: derivatives.png (wall time per derivative mode, failures crossed), derivatives.md
  guesses:     guesses.png (success rate and median time per guess kind), guesses.md
Prints the paths written. Exit codes: 0 done, 2 bad input (missing or malformed CSV; the
message names the file, line and column).
"""
import os
import sys

import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402

import plot_io  # noqa: E402

# Points of the finest meshes the convergence order is fitted over (the asymptotic part).
FIT_POINTS = 4
# Theoretical orders (Betts 2010, sec. 4.5; Kelly 2017, sec. 4): global error at the end of the
# phase, and the local error of one segment (one order more).
GLOBAL_ORDER = {"trapezoidal": 2, "hermite_simpson": 4}
SCHEME_LABEL = {"trapezoidal": "trapezoidal", "hermite_simpson": "Hermite-Simpson"}
MARKER = {"rabbit": "o", "five_link": "s"}
STYLE = {"trapezoidal": "--", "hermite_simpson": "-"}
COLOR = {("rabbit", "trapezoidal"): "tab:orange", ("rabbit", "hermite_simpson"): "tab:blue",
         ("five_link", "trapezoidal"): "tab:red", ("five_link", "hermite_simpson"): "tab:green"}

COLLOCATION = ["robot", "scheme", "ssp_segments", "dsp_segments", "status", "iterations", "cost",
               "wall_s", "solves", "end_angle_error_rad", "end_rate_error_rad_s",
               "segment_angle_error_rad", "segment_rate_error_rad_s", "max_violation"]
DERIVATIVES = ["robot", "scheme", "ssp_segments", "dsp_segments", "hessian", "jacobian", "status",
               "converged", "iterations", "cost", "wall_s", "callbacks_s", "solves"]
GUESSES = ["robot", "guess", "noise_rad", "seed", "status", "converged", "iterations", "cost",
           "wall_s", "cost_gap"]
# A converged attempt within this relative cost of the reference optimum found the same one.
SAME_OPTIMUM = 1e-4



def save(fig, folder, name):
    """Writes `fig` to folder/name, closes it and prints the path."""
    fig.tight_layout()
    out = os.path.join(folder, name)
    style.save(fig, out)
    print(out)

def keys(rows, *names):
    """The distinct tuples of `names` columns, in order of appearance."""
    return list(dict.fromkeys(zip(*(rows[n] for n in names))))


def select(rows, **match):
    """Boolean mask of the rows whose columns equal the given values."""
    mask = np.ones(len(next(iter(rows.values()))), dtype=bool)
    for name, value in match.items():
        mask &= rows[name] == value
    return mask


def fitted_order(segments, error):
    """-slope of the least-squares line of log error against log segments over the finest
    FIT_POINTS meshes (NaN with fewer than two usable points)."""
    order = np.argsort(segments)
    n, e = segments[order][-FIT_POINTS:], error[order][-FIT_POINTS:]
    ok = e > 0
    if np.count_nonzero(ok) < 2:
        return float("nan")
    return -np.polyfit(np.log(n[ok]), np.log(e[ok]), 1)[0]


# -------------------------------------------------------------------------------------------
# Collocation


def robot_label(robot):
    return "RABBIT" if robot == "rabbit" else "five-link"


def plot_lines(ax, rows, x_name, column, robots, theory_shift, annotate):
    """One line per (robot, scheme) of `column` against `x_name`; returns the fitted orders."""
    orders = {}
    for robot, scheme in keys(rows, "robot", "scheme"):
        if robot not in robots:
            continue
        sel = select(rows, robot=robot, scheme=scheme)
        x, y, n = rows[x_name][sel], rows[column][sel], rows["ssp_segments"][sel]
        p = fitted_order(n, y)
        orders[(robot, scheme)] = p
        label = (f"{robot_label(robot)}, {SCHEME_LABEL[scheme]}: order {p:.2f} "
                 f"(theory {GLOBAL_ORDER[scheme] + theory_shift})")
        ax.loglog(x, y, STYLE[scheme], marker=MARKER[robot], color=COLOR[(robot, scheme)],
                  label=label)
        if annotate:
            for xi, yi, ni in zip(x, y, n):
                ax.annotate(f"{int(ni)}", (xi, yi), textcoords="offset points", xytext=(3, 3),
                            fontsize=7, color=COLOR[(robot, scheme)])
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    return orders


def collocation_charts(folder, rows):
    """The two collocation charts; returns {(metric, robot, scheme): fitted order}."""
    panels = [("end_angle_error_rad", ["rabbit"], 0,
               "end-of-SSP angle error, open-loop re-simulation [rad]\n(RABBIT; the five-link "
               "SSP is too unstable open loop: saturates at ~1 rad)"),
              ("segment_angle_error_rad", ["rabbit", "five_link"], 1,
               "max angle error after one segment, re-simulated\nfrom each segment start [rad]")]
    orders = {}
    for name, x_name, xlabel, annotate in [
            ("collocation_accuracy_time.png", "wall_s", "solve time (median) [s]", True),
            ("collocation_order.png", "ssp_segments", "SSP segments", False)]:
        fig, axes = plt.subplots(1, 2, figsize=(14, 6))
        for ax, (column, robots, shift, ylabel) in zip(axes, panels):
            for key, p in plot_lines(ax, rows, x_name, column, robots, shift, annotate).items():
                orders[(column,) + key] = p
            ax.set_xlabel(xlabel)
            ax.set_ylabel(ylabel)
        title = ("Accuracy against solve time (labels: SSP segments)" if annotate else
                 f"Accuracy against mesh (order: least-squares slope over the finest "
                 f"{FIT_POINTS} meshes)")
        fig.suptitle(f"{title}; optimal torques re-simulated by RKF 7(8) at 1e-12",
                     fontsize=11)
        save(fig, folder, name)
    return orders


def collocation_table(rows, orders):
    lines = ["| robot | scheme | SSP seg. | DSP seg. | status | iterations | cost J | "
             "solve s (median) | end angle err. rad | end rate err. rad/s | "
             "segment angle err. rad | segment rate err. rad/s |",
             "|---|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|"]
    for i in range(len(rows["robot"])):
        lines.append(
            f"| {robot_label(rows['robot'][i])} | {SCHEME_LABEL[rows['scheme'][i]]} | "
            f"{int(rows['ssp_segments'][i])} | {int(rows['dsp_segments'][i])} | "
            f"{rows['status'][i]} | {int(rows['iterations'][i])} | {rows['cost'][i]:.4f} | "
            f"{rows['wall_s'][i]:.3f} | {rows['end_angle_error_rad'][i]:.2e} | "
            f"{rows['end_rate_error_rad_s'][i]:.2e} | {rows['segment_angle_error_rad'][i]:.2e} | "
            f"{rows['segment_rate_error_rad_s'][i]:.2e} |")
    lines += ["", f"Fitted orders (least squares over the finest {FIT_POINTS} meshes):", "",
              "| error | robot | scheme | fitted order | theory |", "|---|---|---|---:|---:|"]
    for (column, robot, scheme), p in orders.items():
        glob = column == "end_angle_error_rad"
        theory = GLOBAL_ORDER[scheme] + (0 if glob else 1)
        lines.append(f"| {'end of SSP (global)' if glob else 'one segment (local)'} | "
                     f"{robot_label(robot)} | {SCHEME_LABEL[scheme]} | {p:.2f} | {theory} |")
    return "\n".join(lines) + "\n"


def collocation(folder, path):
    rows = plot_io.read_csv(path, "collocation study", COLLOCATION, strings=("robot", "scheme",
                                                                              "status"))
    plot_io.check_values(path, "scheme", rows["scheme"], tuple(GLOBAL_ORDER))
    plot_io.check_values(path, "robot", rows["robot"], tuple(MARKER))
    return collocation_table(rows, collocation_charts(folder, rows))


# -------------------------------------------------------------------------------------------
# Derivatives

MODE_LABEL = {("exact", "exact"): "exact Hessian + Jacobian",
              ("limited-memory", "exact"): "limited-memory Hessian",
              ("limited-memory", "finite-difference-values"): "limited-memory + FD Jacobian"}


def problem_label(robot, scheme, ssp, dsp):
    mesh = f"{int(ssp)}+{int(dsp)}" if dsp > 0 else f"{int(ssp)}"
    return f"{robot_label(robot)}\n{SCHEME_LABEL[scheme]} {mesh}"


def derivatives_chart(folder, rows):
    """Wall time per problem and derivative mode as points on a log axis (bars would start at
    an arbitrary floor there), one marker per mode; a solve that did not converge is a
    red-edged X labelled with its status."""
    problems = keys(rows, "robot", "scheme", "ssp_segments", "dsp_segments")
    modes = list(MODE_LABEL)
    markers = ["o", "s", "D", "^"]
    fig, ax = plt.subplots(figsize=(12, 5.6))
    width = 0.6 / max(len(modes) - 1, 1)
    for m, (hessian, jacobian) in enumerate(modes):
        for p, (robot, scheme, ssp, dsp) in enumerate(problems):
            sel = select(rows, robot=robot, scheme=scheme, ssp_segments=ssp, dsp_segments=dsp,
                         hessian=hessian, jacobian=jacobian)
            if not np.any(sel):
                continue
            i = int(np.argmax(sel))
            x = p + (m - (len(modes) - 1) / 2) * width
            ok = rows["converged"][i] == 1
            y = rows["wall_s"][i]
            ax.plot(x, y, markers[m % len(markers)] if ok else "X", color=f"C{m}", ms=9 if ok else 13,
                    mec="black" if ok else style.FAIL, mew=0.8 if ok else 2, ls="none",
                    label=MODE_LABEL[(hessian, jacobian)] if p == 0 else None)
            text = f"{int(rows['iterations'][i])} it."
            if not ok:
                text += f"\n{rows['status'][i].replace('_', ' ')}"
            ax.annotate(text, (x, y), textcoords="offset points", xytext=(0, 9), ha="center",
                        va="bottom", fontsize=7, color="black" if ok else style.FAIL)
    for p in range(1, len(problems)):
        ax.axvline(p - 0.5, color="0.8", lw=0.8)
    ax.plot([], [], "X", color="0.6", mec=style.FAIL, mew=2, ms=10, ls="none",
            label="did not converge (status above)")
    ax.set_yscale("log")
    ax.set_xlim(-0.5, len(problems) - 0.5)
    ax.set_xticks(range(len(problems)))
    ax.set_xticklabels([problem_label(*p) for p in problems], fontsize=8)
    ax.set_ylabel("wall time (median of the solves) [s]")
    ax.set_ylim(ax.get_ylim()[0] / 1.5, ax.get_ylim()[1] * 6)
    ax.grid(True, axis="y", which="both", alpha=0.3)
    ax.legend(loc="upper left")
    ax.set_title("Derivatives handed to Ipopt: wall time from the polynomial guess "
                 "(labels: iterations)")
    save(fig, folder, "derivatives.png")


def derivatives_table(rows):
    lines = ["| problem | SSP+DSP seg. | derivatives | status | iterations | cost J | "
             "wall s | callbacks s | solves | wall / exact |",
             "|---|---|---|---|---:|---:|---:|---:|---:|---:|"]
    exact = {}
    for i in range(len(rows["robot"])):
        problem = (rows["robot"][i], rows["scheme"][i], rows["ssp_segments"][i],
                   rows["dsp_segments"][i])
        mode = (rows["hessian"][i], rows["jacobian"][i])
        if mode == ("exact", "exact"):
            exact[problem] = rows["wall_s"][i]
        ratio = rows["wall_s"][i] / exact[problem] if problem in exact else float("nan")
        lines.append(
            f"| {robot_label(problem[0])}, {SCHEME_LABEL[problem[1]]} | {int(problem[2])}+"
            f"{int(problem[3])} | {MODE_LABEL.get(mode, '/'.join(mode))} | {rows['status'][i]} | "
            f"{int(rows['iterations'][i])} | {rows['cost'][i]:.4f} | {rows['wall_s'][i]:.3f} | "
            f"{rows['callbacks_s'][i]:.3f} | {int(rows['solves'][i])} | {ratio:.1f} |")
    return "\n".join(lines) + "\n"


def derivatives(folder, path):
    rows = plot_io.read_csv(path, "derivative study", DERIVATIVES,
                            strings=("robot", "scheme", "hessian", "jacobian", "status"))
    plot_io.check_values(path, "scheme", rows["scheme"], tuple(GLOBAL_ORDER))
    plot_io.check_values(path, "robot", rows["robot"], tuple(MARKER))
    derivatives_chart(folder, rows)
    return derivatives_table(rows)


# -------------------------------------------------------------------------------------------
# Initial guesses


def guess_kinds(rows):
    """(label, mask) per guess kind: polynomial, naive, then perturbed per noise level."""
    kinds = [(g, select(rows, guess=g)) for g in ("polynomial", "naive")]
    for noise in sorted(set(rows["noise_rad"][rows["guess"] == "perturbed"])):
        kinds.append((f"optimum ± {noise:g} rad",
                      select(rows, guess="perturbed") & (rows["noise_rad"] == noise)))
    return kinds


def guess_stats(rows, mask):
    """converged, same optimum, attempts, median iterations and wall time (all attempts)."""
    conv = mask & (rows["converged"] == 1)
    same = conv & (rows["cost_gap"] <= SAME_OPTIMUM)
    return (int(np.count_nonzero(conv)), int(np.count_nonzero(same)), int(np.count_nonzero(mask)),
            float(np.median(rows["iterations"][mask])), float(np.median(rows["wall_s"][mask])))


def guesses_chart(folder, rows):
    robots = list(dict.fromkeys(rows["robot"]))
    fig, (rate_ax, time_ax) = plt.subplots(1, 2, figsize=(14, 5.5))
    width = 0.8 / len(robots)
    labels = []
    for r, robot in enumerate(robots):
        kinds = guess_kinds({k: v[rows["robot"] == robot] for k, v in rows.items()})
        sub = {k: v[rows["robot"] == robot] for k, v in rows.items()}
        labels = [k for k, _ in kinds] if len(kinds) > len(labels) else labels
        for k, (label, mask) in enumerate(kinds):
            conv, same, n, _, wall = guess_stats(sub, mask)
            x = k + (r - (len(robots) - 1) / 2) * width
            kw = {"color": f"C{r}", "label": robot_label(robot) if k == 0 else None}
            # Converged attempts light, those that found the reference optimum solid over them.
            rate_ax.bar(x, conv / n, width, color=f"C{r}", alpha=0.35)
            rate_ax.bar(x, same / n, width, **kw)
            rate_ax.annotate(f"{same}/{conv}/{n}", (x, conv / n), textcoords="offset points",
                             xytext=(0, 3), ha="center", va="bottom", fontsize=7, rotation=90)
            time_ax.plot(x, wall, "o", ms=8, mec="black", mew=0.8, ls="none", **kw)
    for ax in (rate_ax, time_ax):
        ax.set_xticks(range(len(labels)))
        ax.set_xticklabels(labels, fontsize=8, rotation=20)
        ax.grid(True, axis="y", alpha=0.3)
        ax.legend(fontsize=8)
    rate_ax.set_ylim(0, 1.3)
    rate_ax.set_ylabel("fraction of attempts: solid same optimum, light converged elsewhere\n"
                       "(labels: same / converged / attempts)")
    time_ax.set_yscale("log")  # points, not bars: a bar on a log axis starts nowhere
    time_ax.set_xlim(-0.5, len(labels) - 0.5)
    time_ax.grid(True, axis="y", which="both", alpha=0.3)
    time_ax.set_ylabel("median wall time over all attempts [s]")
    fig.suptitle("Initial guesses: polynomial gait, straight line (Kelly 2017), perturbed optimum "
                 "(uniform angle noise, fixed seeds)", fontsize=11)
    save(fig, folder, "guesses.png")


def guesses_table(rows):
    lines = ["| robot | guess | converged / attempts | same optimum | median iterations | "
             "median wall s | failures (status) |",
             "|---|---|---:|---:|---:|---:|---|"]
    for robot in dict.fromkeys(rows["robot"]):
        sub = {k: v[rows["robot"] == robot] for k, v in rows.items()}
        for label, mask in guess_kinds(sub):
            conv, same, n, its, wall = guess_stats(sub, mask)
            failed = sub["status"][mask & (sub["converged"] != 1)]
            counts = {s: int(np.count_nonzero(failed == s)) for s in dict.fromkeys(failed)}
            why = ", ".join(f"{s} x{c}" for s, c in counts.items()) or "-"
            lines.append(f"| {robot_label(robot)} | {label} | {conv}/{n} | {same} | {its:.0f} | "
                         f"{wall:.3f} | {why} |")
    lines.append(f"\nSame optimum: converged with cost within {SAME_OPTIMUM:g} (relative) of "
                 "the optimum from the polynomial guess.")
    return "\n".join(lines) + "\n"


def guesses(folder, path):
    rows = plot_io.read_csv(path, "guess study", GUESSES, strings=("robot", "guess", "status"))
    plot_io.check_values(path, "guess", rows["guess"], ("polynomial", "naive", "perturbed"))
    plot_io.check_values(path, "robot", rows["robot"], tuple(MARKER))
    guesses_chart(folder, rows)
    return guesses_table(rows)


# -------------------------------------------------------------------------------------------

STUDIES = [("collocation", collocation), ("derivatives", derivatives), ("guesses", guesses)]


def main(folder):
    found = [(name, f) for name, f in STUDIES
             if os.path.exists(os.path.join(folder, f"{name}.csv"))]
    if not found:
        raise plot_io.InputError(f"{folder}: none of collocation.csv, derivatives.csv, "
                                 "guesses.csv")
    for name, study in found:
        table = study(folder, os.path.join(folder, f"{name}.csv"))
        out = os.path.join(folder, f"{name}.md")
        with style.replacing(out) as tmp, open(tmp, "w", encoding="utf-8") as f:
            f.write(table)
        print(out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    try:
        main(sys.argv[1])
    except plot_io.InputError as e:
        sys.exit(print(f"error: {e}", file=sys.stderr) or 2)
