#!/usr/bin/python3
"""Draws the hybrid zero dynamics of a `gaitopt simulate --controller hzd` result folder.

Usage: hzd_plots.py RESULT_DIR
Reads RESULT_DIR/walk.csv and summary.json (its "hzd" block) and writes RESULT_DIR/hzd.png,
printing its path:
  left   the phase portrait (phi, phidot) of every step, phi = c . theta the phase variable of
         the virtual constraints; each step runs from phi+ to phi- and the impact jumps back
  right  the restricted Poincare map rho(zeta-) = delta^2 zeta- - V(phi-) (Westervelt, Grizzle,
         Koditschek 2003) against the identity, with its fixed point
A missing file, column or key, or a malformed value, ends the script with exit code 1.
"""
import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402

import plot_io  # noqa: E402

HZD_KEYS = ["phase_plus", "phase_minus", "restricted_multiplier", "v_zero_minus",
            "zeta_minus_fixed_point"]


def read_walk(path, weights):
    names = [f"theta{i + 1}" for i in range(len(weights))]
    data = plot_io.read_csv(path, "walk log", ["t", "step"] + names, min_rows=2)
    theta = np.column_stack([data[n] for n in names])
    return data["t"], data["step"], theta @ np.asarray(weights)


def phase_portrait(ax, t, step, phi, hzd):
    for k in np.unique(step):
        sel = step == k
        if sel.sum() < 3:
            continue
        ax.plot(phi[sel], np.gradient(phi[sel], t[sel]), lw=0.8)
    for key in ("phase_plus", "phase_minus"):
        ax.axvline(hzd[key], color="grey", lw=0.5, ls=":")
    ax.set_xlabel("phase variable phi [rad]")
    ax.set_ylabel("dphi/dt [rad/s]")
    ax.set_title("every step (colours) on one orbit", fontsize=9)


def restricted_map(ax, hzd):
    zeta = hzd["zeta_minus_fixed_point"]
    z = np.linspace(0, 2 * zeta, 50)
    ax.plot(z, hzd["restricted_multiplier"] * z - hzd["v_zero_minus"], label="rho(zeta-)")
    ax.plot(z, z, "k--", lw=0.7, label="identity")
    ax.plot([zeta], [zeta], "o", color="C3",
            label=f"fixed point, slope delta^2 = {hzd['restricted_multiplier']:.3f}")
    ax.set_xlabel("zeta- = sigma^2/2 at touchdown [(kg m^2/s)^2]")
    ax.set_ylabel("next zeta-")
    ax.legend(fontsize=8)
    ax.set_title("restricted Poincare map", fontsize=9)


def main(result_dir):
    summary_path = f"{result_dir}/summary.json"
    s = plot_io.read_json(summary_path)
    plot_io.require_keys(summary_path, s, ["hzd", "robot", "steps_completed"])
    hzd = s["hzd"]
    plot_io.require_numbers(summary_path, hzd, HZD_KEYS, prefix="hzd.")
    plot_io.require_type(summary_path, hzd, "phase_weights", list, "a list of numbers",
                         prefix="hzd.")
    t, step, phi = read_walk(f"{result_dir}/walk.csv", hzd["phase_weights"])
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    phase_portrait(axes[0], t, step, phi, hzd)
    restricted_map(axes[1], hzd)
    fig.suptitle(f"{s['robot']} under HZD: {s['steps_completed']} steps", fontsize=10)
    fig.tight_layout()
    out = f"{result_dir}/hzd.png"
    style.save(fig, out, dpi=style.PAGE_DPI)
    print(out)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
