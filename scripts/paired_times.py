#!/usr/bin/env python3
"""Solve times of `gaitopt optimize` runs measured in pairs, so that a ratio means something on a
shared machine whose speed drifts from minute to minute: the cases run in turn (A B C A B C ...),
each run is a whole process, and each case's time is divided by the base case's time of the same
round before the medians are taken.

A case is LABEL=BINARY:CONFIG[:KEY=VALUE...] (the KEY=VALUE pairs are handed to --set). BINARY is
any gaitopt program, so a build of an older commit can be held against this one. Two times per
run: the solve (summary.json's wall_time_s, Ipopt with its callbacks) and the whole process
(start to exit, reading the config and writing the folder included), with the process's peak
resident memory. The first round is a warm-up and is not counted.

Usage: paired_times.py [--runs N] [--out FILE.md] CASE... (the first case is the base; FILE.md
gets a FILE.csv beside it)
"""

import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def parse_case(text):
    label, sep, rest = text.partition("=")
    parts = rest.split(":")
    if not sep or not label or len(parts) < 2 or not parts[0] or not parts[1]:
        raise argparse.ArgumentTypeError(f"a case is LABEL=BINARY:CONFIG[:KEY=VALUE...], got {text!r}")
    return {"label": label, "binary": parts[0], "config": parts[1], "sets": parts[2:]}


def solve_command(case):
    """The case's `gaitopt optimize` command line, without its output options."""
    command = [case["binary"], "optimize", "--config", case["config"]]
    for setting in case["sets"]:
        command += ["--set", setting]
    return command


def run_once(case, out_dir):
    """One whole `gaitopt optimize` process: solve s, process s, peak MiB, iterations, cost."""
    command = solve_command(case) + ["--out", str(out_dir), "--no-plots", "--quiet"]
    with tempfile.TemporaryFile(mode="w+") as err:
        start = time.perf_counter()
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err)
        _, status, usage = os.wait4(child.pid, 0)  # this child's own peak memory
        process_s = time.perf_counter() - start
        child.returncode = os.waitstatus_to_exitcode(status)
        if child.returncode != 0:
            err.seek(0)
            sys.exit(f"error: {case['label']}: {' '.join(command)} exited with "
                     f"{child.returncode}:\n{err.read().strip()}")
    summary = json.loads((out_dir / "summary.json").read_text())
    return {"solve": summary["wall_time_s"], "process": process_s,
            "peak": usage.ru_maxrss / 1024, "iterations": summary["iterations"],
            "cost": summary["cost"]}


def load_average():
    return " ".join(Path("/proc/loadavg").read_text().split()[:3])


def median_of(rounds, label, key, base=None):
    """The median of a case's figure, or of its ratio to the base case's in the same round."""
    return statistics.median(
        [r[label][key] / (r[base][key] if base else 1.0) for r in rounds])


def summary_rows(cases, rounds):
    """Per case: its counts from the last round and the medians (ratios to the first case)."""
    base = cases[0]["label"]
    rows = []
    for case in cases:
        label = case["label"]
        last = rounds[-1][label]
        rows.append({"case": label, "iterations": last["iterations"], "cost": last["cost"],
                     "solve_s": median_of(rounds, label, "solve"),
                     "process_s": median_of(rounds, label, "process"),
                     "peak_mib": median_of(rounds, label, "peak"),
                     "solve_ratio": median_of(rounds, label, "solve", base),
                     "process_ratio": median_of(rounds, label, "process", base)})
    return rows


def table(cases, rows, rounds, loads):
    lines = [f"Whole `gaitopt optimize` processes (`--no-plots`), the cases in turn, "
             f"{rounds} rounds after one warm-up; medians, and medians of the ratios to "
             f"{cases[0]['label']} taken round by round. Load average before and after: "
             f"{loads[0]}; {loads[1]}. The cases: "
             + "; ".join(f"{c['label']} = `{' '.join(solve_command(c))}`" for c in cases) + ".", "",
             "| case | iterations | cost J | solve s | process s | peak MiB | solve / base | "
             "process / base |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['case']} | {r['iterations']} | {r['cost']:.6g} | {r['solve_s']:.4f} | "
                     f"{r['process_s']:.4f} | {r['peak_mib']:.0f} | {r['solve_ratio']:.3f} | "
                     f"{r['process_ratio']:.3f} |")
    return "\n".join(lines) + "\n"


def write_csv(path, rows):
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", type=int, default=15, help="counted rounds (default 15)")
    parser.add_argument("--out", type=Path,
                        help="also write the table to this file, and its figures as CSV beside it "
                        "(the same name ending in .csv)")
    parser.add_argument("cases", nargs="+", type=parse_case, metavar="CASE")
    args = parser.parse_args()
    labels = [c["label"] for c in args.cases]
    if len(set(labels)) != len(labels):
        sys.exit("error: two cases share a label")
    if args.runs < 1:
        sys.exit("error: --runs must be at least 1")
    rounds = []
    loads = [load_average()]
    with tempfile.TemporaryDirectory() as scratch:
        for r in range(args.runs + 1):
            results = {c["label"]: run_once(c, Path(scratch) / c["label"]) for c in args.cases}
            if r > 0:
                rounds.append(results)
            what = "warm-up" if r == 0 else f"round {r} of {args.runs}"
            print(f"paired_times: {what} done", file=sys.stderr, flush=True)
    loads.append(load_average())
    rows = summary_rows(args.cases, rounds)
    text = table(args.cases, rows, len(rounds), loads)
    print(text, end="")
    if args.out:
        args.out.write_text(text)
        write_csv(args.out.with_suffix(".csv"), rows)


if __name__ == "__main__":
    main()
