"""One CSV row of a closed-loop walk: the given leading fields, then steps walked, the largest
tracking error, the largest slip and the failure (commas turned into semicolons) of the walk's
summary.json. Used by the study scripts that tabulate many walks (scripts/mu_cases.sh,
scripts/walk_table.sh).

usage: walk_row.py SUMMARY_JSON FIELD...
"""
import json
import sys

summary = json.load(open(sys.argv[1]))
failure = summary["failure"].replace(",", ";")
print(",".join(sys.argv[2:]) + f",{summary['steps_completed']},"
      f"{summary['max_tracking_error']:.3g},{summary.get('max_slip_m', 0):.3g},{failure}")
