"""The look every picture of plots/ shares: backend, font sizes, resolution, colours.

A script calls pyplot() (once its input is checked, if importing matplotlib first would slow a
failure down) and draws with the colours named here, so a tip, a phase or a failure looks the
same in every picture. save(fig, path) writes at DPI and closes the figure.
"""
import contextlib
import os
import tempfile

DPI = 110
# Many-panel pages (a gait overview, the HZD pair) are drawn large and stored coarser.
PAGE_DPI = 90
# Font sizes and resolution for every figure (matplotlib rcParams).
RC = {
    "font.size": 10,
    "axes.titlesize": 10,
    "axes.labelsize": 10,
    "legend.fontsize": 8,
    "figure.titlesize": 11,
    "grid.alpha": 0.4,
    "savefig.dpi": DPI,
}

# Contact tips (docs/design.md#conventions): B the stance/trailing tip, E the swing/leading tip.
TIP_B = "tab:blue"
TIP_E = "tab:orange"
ZMP = "tab:red"
COM = "tab:green"
HIP = "0.25"
TORSO = "0.25"
# Outcomes: walked / converged against fell / failed; Poincare multipliers.
OK = "tab:green"
FAIL = "tab:red"
MULTIPLIER = "tab:purple"
TOUCHDOWN = "0.45"
# The double support phase, shaded on every time axis.
DSP_SHADE = {"color": "tab:purple", "alpha": 0.12, "lw": 0}
# The support region (foot or feet) behind a ZMP curve.
SUPPORT_SHADE = {"color": "0.85", "lw": 0}
# The stance foot from heel to toe behind the ZMP curves of several gaits (their line styles
# tell the gaits apart, so the foot is a band, not lines).
FOOT_SHADE = {"color": "tab:brown", "alpha": 0.12, "lw": 0}
WALK_SHADE = {"color": "tab:green", "alpha": 0.12, "lw": 0}


def pyplot():
    """matplotlib.pyplot on the file-only Agg backend with RC applied."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams.update(RC)
    return plt


def link_colours(n, torso=None):
    """One colour per link of an n-link chain from the stance tip: the stance side blue, the
    swing side orange, darker toward the tips; the middle link (and any link flagged in
    `torso`) grey."""
    import matplotlib.pyplot as plt

    mid = (n - 1) / 2
    colours = []
    for i in range(n):
        depth = abs(i - mid) / max(mid, 1)  # 1 at the tips (shanks), smaller toward the hip
        cmap = plt.cm.Blues if i < mid else plt.cm.Oranges
        grey = i == mid or (torso is not None and torso[i])
        colours.append(TORSO if grey else cmap(0.45 + 0.5 * depth))
    return colours


def time_colours(t0, t1):
    """(colormap, norm) over [t0, t1]: later frames darker."""
    import matplotlib
    import matplotlib.pyplot as plt
    import numpy as np

    cmap = matplotlib.colors.ListedColormap(plt.cm.viridis_r(np.linspace(0.12, 1, 256)))
    return cmap, matplotlib.colors.Normalize(t0, t1)


def finish(ax, xlabel, ylabel, title=None, legend=True, **legend_kw):
    """Axis labels, the title, a light grid and (unless legend is False) the legend."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)
    ax.grid(True, alpha=RC["grid.alpha"])
    if legend:
        ax.legend(**legend_kw)


def falls_column(ax, x):
    """Marks x < 0 as the column of points that fall on the nominal plant: a dotted line
    between it and the intervals (which start at 0, a gait walking the nominal plant only) and
    the tick "falls at ×1" in place of a number, so a fall is not read as an interval of 0."""
    ax.axvline(x / 2, color="0.6", lw=0.8, ls=":")
    lo, hi = ax.get_xlim()
    ticks = [t for t in ax.get_xticks() if 0 <= t <= hi]  # set_xticks would widen the axis
    ax.set_xticks([x] + ticks)
    ax.set_xticklabels(["falls\nat ×1"] + [f"{t:g}" for t in ticks])
    ax.set_xlim(min(lo, 1.5 * x), hi)


def remove_leftovers(folder, name):
    """Removes NAME.tmp-PID-* files of processes that no longer run: a run killed while it drew
    left them in a folder its rerun writes into again (a library's picture)."""
    prefix = name + ".tmp-"
    for entry in os.listdir(folder):
        pid = entry[len(prefix):].split("-", 1)[0] if entry.startswith(prefix) else ""
        if not pid.isdigit():
            continue
        try:
            os.kill(int(pid), 0)
        except (ProcessLookupError, OverflowError):  # gone, or no pid a process can have
            with contextlib.suppress(OSError):
                os.unlink(os.path.join(folder, entry))
        except PermissionError:
            pass  # alive, another user's


@contextlib.contextmanager
def replacing(path):
    """Yields a new file's path next to `path` and renames it over `path` when the block ends.

    The file is created by mkstemp (O_EXCL), so a link planted at `path` or at any temporary
    name is never written through: the rename replaces the link itself. Pictures of resumable
    folders (stability, library) are rewritten in place, where this matters."""
    folder, name = os.path.split(os.fspath(path))
    remove_leftovers(folder or ".", name)
    # The same extension: writers that pick the format by it (Pillow's GIF) still can.
    fd, tmp = tempfile.mkstemp(prefix=f"{name}.tmp-{os.getpid()}-",
                               suffix=os.path.splitext(name)[1], dir=folder or ".")
    os.close(fd)
    try:
        os.chmod(tmp, 0o644)
        yield tmp
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def save(fig, path, dpi=DPI):
    """Writes the figure and closes it; a PNG is then stored with a 256-colour palette (a
    third of the bytes of matplotlib's RGBA for line charts, no visible change), when Pillow
    is there."""
    import matplotlib.pyplot as plt

    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=dpi)
        if tmp.endswith(".png"):
            shrink_png(tmp)
    plt.close(fig)


def shrink_png(path):
    """Rewrites a PNG with an adaptive 256-colour palette; leaves it alone without Pillow."""
    try:
        from PIL import Image
    except ImportError:
        return
    with Image.open(path) as im:
        rgb = im.convert("RGB")
    rgb.quantize(colors=256).save(path, optimize=True)
