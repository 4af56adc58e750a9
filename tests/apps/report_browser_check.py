#!/usr/bin/python3
"""Loads a `gaitopt report` page in headless Chromium and checks what a person would see.

Usage: report_browser_check.py PAGE WORK_DIR [T1 T2]
  1. the page at #t=T1 renders with no console error and reports its state in the title
     ("gaitopt report: ready t=... frame=... x=... phase=...");
  2. screenshots at #t=T1 and #t=T2 (default 0.1 and 0.5 s) both show the robot: at least
     MIN_LINK_PIXELS pixels of each link colour of the page's stick figure;
  3. the robot moved: the link pixels of the two screenshots differ in at least MIN_MOVED_PIXELS
     pixels, and the centre of the figure (the title's x) advanced by at least MIN_ADVANCE_M
     (a walk at about 0.5 m/s covers about 0.2 m in 0.4 s).
The screenshots stay in WORK_DIR (t1.png, t2.png). Exit 0 when all hold, 1 otherwise.
Chromium is started with an argument vector, never through a shell.
"""
import html
import pathlib
import re
import subprocess
import sys

import matplotlib.image
import numpy as np

# The link colours of report/report_template.html (COLORS), as 0..255 RGB.
LINK_COLORS = ["#1f77b4", "#2ca02c", "#d62728", "#ff7f0e", "#9467bd"]
MIN_LINK_PIXELS = 150
MIN_MOVED_PIXELS = 300
MIN_ADVANCE_M = 0.1
TITLE = re.compile(r"gaitopt report: ready t=([0-9.]+) frame=(\d+) x=(-?[0-9.]+) phase=(SSP|DSP)")


def chromium(work, *args):
    cmd = ["chromium", "--headless", "--disable-gpu", "--no-sandbox", "--hide-scrollbars",
           "--enable-logging=stderr", "--v=0", f"--user-data-dir={work / 'profile'}",
           "--window-size=1000,760", "--virtual-time-budget=3000", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, check=False)


def console_errors(stderr):
    """Console messages of the page that are errors (Chromium logs them as CONSOLE lines)."""
    return [line for line in stderr.splitlines()
            if "CONSOLE" in line and re.search(r"Uncaught|Error|error", line)]


def state_at(url, work):
    r = chromium(work, "--dump-dom", url)
    errors = console_errors(r.stderr)
    if r.returncode != 0 or errors:
        sys.exit(f"FAIL: {url}: exit {r.returncode}, console errors {errors}\n{r.stderr[-2000:]}")
    m = re.search(r"<title>(.*?)</title>", r.stdout, re.S)
    title = html.unescape(m.group(1)) if m else ""
    state = TITLE.search(title)
    if not state:
        sys.exit(f"FAIL: {url}: the page did not report ready, title '{title}'")
    return float(state.group(1)), float(state.group(3))


def screenshot(url, path, work):
    r = chromium(work, f"--screenshot={path}", url)
    if r.returncode != 0 or not path.is_file() or console_errors(r.stderr):
        sys.exit(f"FAIL: screenshot of {url}: exit {r.returncode}\n{r.stderr[-2000:]}")
    return (matplotlib.image.imread(str(path))[:, :, :3] * 255).round().astype(int)


def link_masks(image):
    masks = []
    for color in LINK_COLORS:
        rgb = np.array([int(color[i:i + 2], 16) for i in (1, 3, 5)])
        masks.append(np.all(np.abs(image - rgb) <= 8, axis=2))
    return masks


def main(page, work, t1="0.1", t2="0.5"):
    work = pathlib.Path(work)
    url = pathlib.Path(page).resolve().as_uri()
    time1, x1 = state_at(f"{url}#t={t1}", work)
    time2, x2 = state_at(f"{url}#t={t2}", work)
    if abs(time1 - float(t1)) > 1e-3 or abs(time2 - float(t2)) > 1e-3:
        sys.exit(f"FAIL: the page shows t={time1}, {time2} for #t={t1}, #t={t2}")
    masks = [link_masks(screenshot(f"{url}#t={t}", work / name, work))
             for t, name in ((t1, "t1.png"), (t2, "t2.png"))]
    for shot, m in zip((t1, t2), masks):
        counts = [int(k.sum()) for k in m]
        if min(counts) < MIN_LINK_PIXELS:
            sys.exit(f"FAIL: the screenshot at t={shot} does not show every link: pixels {counts}")
    moved = sum(int(np.logical_xor(a, b).sum()) for a, b in zip(*masks))
    if moved < MIN_MOVED_PIXELS or x2 - x1 < MIN_ADVANCE_M:
        sys.exit(f"FAIL: the robot did not move: {moved} link pixels changed, "
                 f"centre x {x1:.3f} -> {x2:.3f} m")
    print(f"report page: ready, {moved} link pixels changed between t={t1} and t={t2} s, "
          f"centre x {x1:.3f} -> {x2:.3f} m")


if __name__ == "__main__":
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__)
    main(*sys.argv[1:])
