#!/usr/bin/python3
"""Draws the impact-type map of `gaitopt impact-map` after Mu (2004) ch. 5.

Usage: impact_map.py RESULT_DIR
Reads RESULT_DIR/impact_map.csv and writes RESULT_DIR/impact_map.png, printing its path:
  top row     impact type over (S_L, alpha) at four knee biases sigma (Figs. 5.2, 5.3a-b)
  middle row  impact type over (sigma, alpha) at S_L 1.0 m and 1.8 m (Fig. 5.3c-d); |mu_S| contours
              in the single region (Fig. 5.7) and |mu_L|, |mu_R| contours in the double region
              (Fig. 5.4), both over (S_L, alpha) at one sigma
  bottom row  (when the CSV has lcp_type) what the complementarity law over both tips with
              Coulomb friction picks, at the top row's knee biases
S_L is Mu's step length, twice the tip distance `step_length` of the CSV
(docs/design.md#conventions).
A panel whose axes have fewer than two grid values is left out. A missing file or column, or a
malformed value, ends the script with exit code 1.
"""
import os

import matplotlib
import plot_style as style

plt = style.pyplot()
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import plot_io  # noqa: E402
from plot_io import InputError  # noqa: E402

TYPES = ["single", "double", "either", "neither"]
TYPE_COLOURS = ["#9ecae1", "#fd8d3c", "#74c476", "#969696"]
TYPE_LABELS = ["single", "double", "either (P_ly > 0 and ydot_b > 0)",
               "neither (P_ly < 0 and ydot_b < 0)"]
NUMBERS = ["mu_SL", "knee_bias_deg", "approach_angle_deg", "P_ly", "ydot_b", "mu_L", "mu_R",
           "mu_S"]
RATIO_LEVELS = [0.1, 0.2, 0.3, 0.5, 1.0, 2.0]
SIGMA_SLICES = [1, 15, 30, 45]  # deg, Figs. 5.2-5.3 and 5.6
SL_SLICES = [1.0, 1.8]  # m, Fig. 5.3(c), (d)


def read_map(path):
    """Returns (axes: the three sorted axis value arrays, cube: name -> array over the grid)."""
    header, data = plot_io.read_rows(path, "map")
    words = ["type"] + (["lcp_type"] if "lcp_type" in header else [])
    cols = plot_io.columns(path, header, data, NUMBERS + words, strings=set(words), finite=False)
    for word in words:
        plot_io.check_values(path, word, cols[word], TYPES)
        cols[word] = np.array([TYPES.index(t) for t in cols[word]], dtype=float)
    rows = len(cols["type"])
    axes = [np.unique(cols[name]) for name in NUMBERS[:3]]
    shape = tuple(len(a) for a in axes)
    if np.prod(shape) != rows:
        raise InputError(f"{path}: {rows} rows do not fill a {shape} grid")
    # Rows come with alpha fastest and step length slowest (gaits/impact/impact_map.hpp).
    return axes, {name: v.reshape(shape) for name, v in cols.items()}


def nearest(values, target):
    return int(np.argmin(np.abs(values - target)))


def slices(values, targets):
    """The grid indices nearest the targets, each once: on a coarse grid two targets can land on
    one value, whose panel would only repeat."""
    out = []
    for target in targets:
        k = nearest(values, target)
        if k not in out:
            out.append(k)
    return out


def type_panel(ax, x, y, types, xlabel, title):
    cmap = ListedColormap(TYPE_COLOURS)
    ax.pcolormesh(x, y, types.T, cmap=cmap, vmin=-0.5, vmax=3.5, shading="nearest")
    ax.set(xlabel=xlabel, ylabel="alpha [deg]", title=title)


def ratio_panel(ax, x, y, fields, title):
    """Contours of |ratio| where its impact type holds; fields = [(label, ratio, mask, colour)]."""
    if not any(mask.any() for _, _, mask, _ in fields):
        ax.text(0.5, 0.5, "no such impacts on this slice", transform=ax.transAxes,
                ha="center", va="center", fontsize=9, color="0.4")
    for label, ratio, mask, colour in fields:
        z = np.where(mask, np.abs(ratio), np.nan)
        ax.contourf(x, y, mask.T.astype(float), levels=[0.5, 1.5], colors=[colour], alpha=0.25)
        if np.isfinite(z).sum() >= 4:
            cs = ax.contour(x, y, z.T, levels=RATIO_LEVELS, colors=[colour], linewidths=1)
            ax.clabel(cs, fontsize=7, fmt=f"{label} %.1f")
    ax.set(xlabel="S_L [m]", ylabel="alpha [deg]", title=title)


def draw(axes, cube):
    sl, sigma, alpha = axes
    have = [len(a) >= 2 for a in axes]
    lcp = "lcp_type" in cube
    fig, grid = plt.subplots(3 if lcp else 2, 4, figsize=(17, 12.75 if lcp else 8.5),
                             squeeze=False)
    for ax in grid.flat:
        ax.set_visible(False)
    if have[0] and have[2]:
        for ax, k in zip(grid[0], slices(sigma, SIGMA_SLICES)):
            ax.set_visible(True)
            type_panel(ax, sl, alpha, cube["type"][:, k, :], "S_L [m]",
                       f"sigma = {sigma[k]:g} deg")
        for ax, k in zip(grid[2] if lcp else [], slices(sigma, SIGMA_SLICES)):
            ax.set_visible(True)
            type_panel(ax, sl, alpha, cube["lcp_type"][:, k, :], "S_L [m]",
                       f"complementarity law, sigma = {sigma[k]:g} deg")
        k = nearest(sigma, 20)
        single = cube["type"][:, k, :] == 0
        grid[1, 2].set_visible(True)
        ratio_panel(grid[1, 2], sl, alpha, [("mu_S", cube["mu_S"][:, k, :], single, "tab:blue")],
                    f"|mu_S| (single region), sigma = {sigma[k]:g} deg")
        k = nearest(sigma, 5)
        double = cube["type"][:, k, :] == 1
        grid[1, 3].set_visible(True)
        ratio_panel(grid[1, 3], sl, alpha,
                    [("mu_L", cube["mu_L"][:, k, :], double, "tab:red"),
                     ("mu_R", cube["mu_R"][:, k, :], double, "tab:purple")],
                    f"|mu_L|, |mu_R| (double), sigma = {sigma[k]:g} deg")
    if have[1] and have[2]:
        for ax, i in zip(grid[1, :2], slices(sl, SL_SLICES)):
            ax.set_visible(True)
            type_panel(ax, sigma, alpha, cube["type"][i, :, :], "sigma [deg]",
                       f"S_L = {sl[i]:g} m")
    counts = [int((cube["type"] == t).sum()) for t in range(4)]
    if lcp:
        counts = [f"{n}, law {int((cube['lcp_type'] == t).sum())}" for t, n in enumerate(counts)]
    fig.legend(handles=[Patch(color=c, label=f"{lab}: {n}") for c, lab, n in
                        zip(TYPE_COLOURS, TYPE_LABELS, counts)],
               loc="lower center", ncol=4, frameon=False)
    fig.suptitle("Impact type after Mu (2004) ch. 5: torso upright, hip centred (x_h = S_L/4)")
    fig.tight_layout(rect=(0, 0.04 if lcp else 0.05, 1, 0.96))
    return fig


def main(result_dir):
    axes, cube = read_map(os.path.join(result_dir, "impact_map.csv"))
    fig = draw(axes, cube)
    path = os.path.join(result_dir, "impact_map.png")
    style.save(fig, path)
    print(path)


if __name__ == "__main__":
    plot_io.run_main(main, __doc__)
