"""Input checks shared by the plotting scripts in plots/.

Every problem with an input file is an InputError whose message starts with the file's path and
says what is wrong; run_main turns it into "error: <message>" on stderr and exit code 1.
Line numbers in messages count the header as line 1 (the C++ writers never put line breaks
inside a field).
"""
import csv
import json
import os
import sys

import numpy as np

NUMBER_WORDS = {2: "two", 3: "three"}

# A grid sample this close to a stored switch or end state is that instant [s]
# (gaits/trajectory/grid_export.cpp).
SWITCH_TOLERANCE_S = 1e-9
GRID_TOLERANCE_S = 1e-12  # a fixed-rate row's time against i / rate (trajectory_csv.cpp)


class InputError(Exception):
    """A missing or malformed input file; the message names the file and what is wrong."""


def not_text(path, error):
    """The InputError of a file that is not UTF-8 text (a binary file in place of a result)."""
    return InputError(f"{path}: not UTF-8 text ({error.reason}): a binary file?")


# ---------------------------------------------------------------------------------------------
# CSV


def read_rows(path, what, min_rows=1):
    """(header, data rows) of a CSV file; `what` names the file in the 'cannot read' message."""
    try:
        with open(path, encoding="utf-8", newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise InputError(f"{path}: cannot read the {what} ({e.strerror})") from e
    except UnicodeDecodeError as e:
        raise not_text(path, e) from None
    except csv.Error as e:  # a NUL byte: a binary file that happens to be valid UTF-8
        raise InputError(f"{path}: not a CSV text file ({e})") from None
    if len(rows) < 1 + min_rows:
        if min_rows == 1:
            raise InputError(f"{path}: no data rows")
        raise InputError(f"{path}: expected a header row and at least "
                         f"{NUMBER_WORDS.get(min_rows, min_rows)} data rows")
    return rows[0], rows[1:]


def require_columns(path, header, names):
    """Raises for the first of `names` missing from the header."""
    for name in names:
        if name not in header:
            raise InputError(f"{path}: missing column '{name}'")


def to_numbers(path, name, texts, finite=True, optional=False):
    """Float array of one column's texts.

    finite: reject nan and inf; optional: an empty field is NaN (not computed)."""
    values = np.empty(len(texts))
    for k, text in enumerate(texts):
        if optional and text == "":
            values[k] = np.nan
            continue
        try:
            values[k] = float(text)
        except ValueError:
            raise InputError(f"{path}:{k + 2}: column '{name}': expected a "
                             f"{'finite ' if finite else ''}number, found '{text}'") from None
        if finite and not np.isfinite(values[k]):
            raise InputError(f"{path}:{k + 2}: column '{name}': expected a finite number, "
                             f"found '{text}'")
    return values


def columns(path, header, rows, names, strings=(), optional=(), finite=True):
    """name -> array for each of `names`: str arrays for those in `strings`, floats otherwise
    (empty fields NaN for those in `optional`). Checks the columns exist and every row has the
    header's number of fields."""
    require_columns(path, header, names)
    for line, row in enumerate(rows, start=2):
        if len(row) != len(header):
            raise InputError(f"{path}:{line}: {len(row)} fields, the header has {len(header)}")
    out = {}
    for name in names:
        i = header.index(name)
        texts = [row[i] for row in rows]
        out[name] = (np.array(texts, dtype=str) if name in strings else
                     to_numbers(path, name, texts, finite=finite, optional=name in optional))
    return out


def read_csv(path, what, names, strings=(), optional=(), finite=True, min_rows=1):
    """read_rows then columns: name -> array for each of `names`."""
    header, rows = read_rows(path, what, min_rows)
    return columns(path, header, rows, names, strings, optional, finite)


def check_values(path, name, texts, allowed):
    """Raises for the first text of a string column that is not in `allowed`."""
    unknown = sorted(set(texts) - set(allowed))
    if unknown:
        raise InputError(f"{path}: column '{name}': unknown value '{unknown[0]}', expected "
                         f"{'/'.join(allowed)}")


def numbered_names(header, prefix, first=1):
    """The contiguous run prefix<first>, prefix<first+1>, ... of column names in the header
    (e.g. theta1..theta5); empty when prefix<first> is missing."""
    names = []
    while f"{prefix}{first + len(names)}" in header:
        names.append(f"{prefix}{first + len(names)}")
    return names


def check_phases(path, phase):
    """Raises unless the 'phase' texts are SSP rows first, then (optionally) DSP rows."""
    check_values(path, "phase", phase, ("SSP", "DSP"))
    if len(phase) and (phase[0] != "SSP"
                       or np.any((phase[:-1] == "DSP") & (phase[1:] == "SSP"))):
        raise InputError(f"{path}: column 'phase': expected SSP rows followed by DSP rows")


def check_increasing(path, name, values):
    """Raises where a column decreases (equal neighbours are fine)."""
    back = np.diff(values) < 0
    if np.any(back):
        line = int(np.argmax(back)) + 3
        raise InputError(f"{path}:{line}: column '{name}': time goes backwards"
                         if name == "t" else f"{path}:{line}: column '{name}': decreases")


# ---------------------------------------------------------------------------------------------
# trajectory.csv (docs/design.md#the-export-contract)


class Trajectory:
    """One step of a gait result folder's trajectory.csv.

    col: column name -> float array for every column but 'phase'; phase: str array (SSP rows,
    then DSP rows); n: links (theta1..thetaN); n_tau: joint torques (tau0..); t; dsp: bool array
    of the DSP rows; t_touchdown: the first DSP time (the last time without DSP rows)."""

    def __init__(self, path, header, col, phase, n, n_tau):
        self.path, self.header, self.col, self.phase = path, header, col, phase
        self.n, self.n_tau = n, n_tau
        self.t = col["t"]
        self.dsp = phase == "DSP"
        self.t_touchdown = self.t[self.dsp][0] if self.dsp.any() else self.t[-1]

    def require(self, names):
        """Raises for the first of `names` missing from the file (columns that depend on n)."""
        require_columns(self.path, self.header, names)

    def stack(self, prefix, first, count):
        """Columns prefix<first> .. prefix<first+count-1> side by side (rows x count)."""
        return np.column_stack([self.col[f"{prefix}{i}"] for i in range(first, first + count)])


def read_trajectory(path, need=()):
    """The one reader of trajectory.csv: a Trajectory of every column in the file.

    Requires t, phase, theta1..thetaN (N >= 2, the contiguous run from theta1) and the columns
    in `need`; every row must have the header's number of fields (a torn row is an error naming
    its line), every value but the phase a finite number, phase SSP rows then DSP rows, and t
    non-decreasing. The rows on the fixed-rate grid get back the switch and end states of the
    summary.json beside the file (switch_rows), so the step is the one the gait was sampled from."""
    header, rows = read_rows(path, "trajectory", min_rows=2)
    require_columns(path, header, ["t", "phase", "theta1"])
    thetas = numbered_names(header, "theta", 1)
    if len(thetas) < 2:
        raise InputError(f"{path}: missing column 'theta2' (a biped has at least two links)")
    require_columns(path, header, list(need))
    names = list(dict.fromkeys(name for name in header if name))
    col = columns(path, header, rows, names, strings={"phase"})
    phase = col.pop("phase")
    check_phases(path, phase)
    check_increasing(path, "t", col["t"])
    extra, rate = switch_rows(path, names)
    if extra:
        check_grid(path, col["t"], extra[-1]["t"], rate)
    col, phase = with_switch_rows(col, phase, extra)
    return Trajectory(path, header, col, phase, len(thetas),
                      len(numbered_names(header, "tau", 0)))


def switch_rows(path, names):
    """The rows a fixed-rate export keeps in the summary.json beside `path` (gaits/
    switch_states.hpp): each phase switch's 'before' and 'after' rows, then 'step_end', and the
    rate of the grid they were taken from (sample_rate_hz); no rows for a folder without them
    (its CSV repeats the switch time and ends at the period)."""
    summary = os.path.join(os.path.dirname(path), "summary.json")
    if not os.path.isfile(summary):
        return [], None
    s = read_json(summary)
    if "phase_switches" not in s:
        return [], None
    require_type(summary, s, "phase_switches", list, "a list")
    require_keys(summary, s, ["step_end"])
    keyed = [(f"phase_switches[{i}].{side}", sw.get(side) if isinstance(sw, dict) else None)
             for i, sw in enumerate(s["phase_switches"]) for side in ("before", "after")]
    keyed.append(("step_end", s["step_end"]))
    for key, row in keyed:
        if not isinstance(row, dict):
            raise InputError(f"{summary}: key '{key}': expected a trajectory.csv row object")
        require_numbers(summary, row, [n for n in names if n != "phase"], prefix=key + ".")
        check_values(summary, key + ".phase", [row.get("phase")], ("SSP", "DSP"))
    return [row for _, row in keyed], s.get("sample_rate_hz")


def check_grid(path, t, end, rate):
    """Rows with switch states must be the whole grid t_i = i / rate up to the step's end, as the
    C++ reader requires (gaits/trajectory/trajectory_csv.cpp): a file cut short would otherwise
    be read as a step that jumps from its last row to the stored end state."""
    summary = os.path.join(os.path.dirname(path), "summary.json")
    if not is_number(rate) or not rate > 0:
        raise InputError(f"{summary}: key 'sample_rate_hz': expected a rate > 0 [Hz], got {rate}")
    n = int(np.floor(end * rate))  # the largest i with i / rate <= end, as grid_export.cpp
    while (n + 1) / rate <= end:
        n += 1
    while n > 0 and n / rate > end:
        n -= 1
    if len(t) != n + 1:
        raise InputError(f"{path}: {len(t)} row(s) on the grid, but t_i = i / {rate:g} Hz up to "
                         f"the step's end at {end:g} s (summary.json) makes {n + 1}: a truncated "
                         "or edited file")
    off = np.flatnonzero(np.abs(t - np.arange(n + 1) / rate) > GRID_TOLERANCE_S)
    if off.size:
        i = int(off[0])
        raise InputError(f"{path}: line {i + 2}: key 't': time {t[i]:.17g} is not i / rate = "
                         f"{i} / {rate:g} Hz (summary.json)")


def with_switch_rows(col, phase, extra):
    """The columns with the `extra` rows put back in time order, as the C++ reader does: a grid
    row within 1e-9 s of one of them is dropped (the stored state stands for it), so the SSP
    rows end at the touchdown in the pre-impact state and the DSP rows start there in the
    post-impact state and end at the period."""
    if not extra:
        return col, phase
    t = col["t"]
    keep = np.ones(len(t), dtype=bool)
    for row in extra:
        keep &= np.abs(t - row["t"]) > SWITCH_TOLERANCE_S
    merged = {name: np.concatenate([values[keep], [float(row[name]) for row in extra]])
              for name, values in col.items()}
    order = np.argsort(merged["t"], kind="stable")  # a switch's two rows keep their order
    phases = np.concatenate([phase[keep], np.array([row["phase"] for row in extra], dtype=str)])
    return {name: values[order] for name, values in merged.items()}, phases[order]


def wrap(angle):
    """Angle wrapped to (-pi, pi]."""
    return -((-angle + np.pi) % (2 * np.pi) - np.pi)


# ---------------------------------------------------------------------------------------------
# summary.json


def read_json(path, what="summary"):
    """The JSON object in `path`."""
    try:
        with open(path, encoding="utf-8") as f:
            s = json.load(f)
    except OSError as e:
        raise InputError(f"{path}: cannot read the {what} ({e.strerror})") from e
    except UnicodeDecodeError as e:
        raise not_text(path, e) from None
    except json.JSONDecodeError as e:
        raise InputError(f"{path}: not valid JSON ({e})") from e
    if not isinstance(s, dict):
        raise InputError(f"{path}: expected a JSON object with the {what} keys")
    return s


def require_keys(path, s, keys, prefix=""):
    """Raises for the first of `keys` missing from the object `s`; prefix names where `s` sits
    in the file (e.g. 'sweeps.friction.')."""
    for key in keys:
        if key not in s:
            raise InputError(f"{path}: missing key '{prefix}{key}'")


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def require_numbers(path, s, keys, nullable=False, prefix=""):
    """Raises unless every key is present and a number (or null when nullable)."""
    require_keys(path, s, keys, prefix)
    for key in keys:
        if not (is_number(s[key]) or (nullable and s[key] is None)):
            raise InputError(f"{path}: key '{prefix}{key}': expected a number"
                             f"{' or null' if nullable else ''}, got {s[key]!r}")


def require_type(path, s, key, kind, label, prefix=""):
    """Raises unless key is present and an instance of `kind`; label says what was expected."""
    require_keys(path, s, [key], prefix)
    if not isinstance(s[key], kind):
        raise InputError(f"{path}: key '{prefix}{key}': expected {label}, got {s[key]!r}")


def read_multipliers(path, value):
    """poincare_multipliers as a complex array, or None when null."""
    if value is None:
        return None
    if not (isinstance(value, list) and all(isinstance(z, list) and len(z) == 2
                                            and all(is_number(v) for v in z)
                                            for z in value)):
        raise InputError(f"{path}: key 'poincare_multipliers': expected a list of [re, im] "
                         f"pairs or null")
    return np.array([complex(re_, im) for re_, im in value], dtype=complex)


# ---------------------------------------------------------------------------------------------
# Figures


def panel_figure(draw, data, title, figsize, fontsize=9):
    """A figure of one panel, drawn by draw(ax, data) under `title`. pyplot is imported here,
    after the calling script has chosen its backend."""
    import plot_style

    plt = plot_style.pyplot()

    fig, ax = plt.subplots(figsize=figsize)
    draw(ax, data)
    fig.suptitle(title, fontsize=fontsize)
    fig.tight_layout()
    return fig


# ---------------------------------------------------------------------------------------------
# Entry point


def run_main(main, usage, arguments=1):
    """Calls main(ARG, ...) with the command line's `arguments` arguments (a result folder, ...);
    usage (the script's docstring) when there are not as many, "error: <message>" and exit code
    1 on an InputError."""
    if len(sys.argv) != 1 + arguments:
        sys.exit(usage)
    try:
        main(*sys.argv[1:])
    except InputError as e:
        sys.exit(f"error: {e}")
