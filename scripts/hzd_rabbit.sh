#!/usr/bin/env bash
# RABBIT under HZD (sim/controllers/hzd_*.hpp): solves Kelly's torque-squared optimum
# (configs/ocp/rabbit_kelly2017.yaml), walks it 20 steps on rigid ground with
# `gaitopt simulate --controller hzd` (the Poincare maps: full and restricted), and draws the
# zero dynamics (results/walk_rabbit_hzd/hzd.png) from the walk's
# walk.csv.
# Usage: scripts/hzd_rabbit.sh BUILD_DIR   (run from the repository root)
set -euo pipefail
build=${1:-build}
bin="$build/apps/gaitopt"
gait=results/opt_rabbit  # its trajectory.csv (1 kHz) is not committed: made here if missing

if [[ ! -f "$gait/trajectory.csv" ]]; then
  "$bin" optimize --config configs/ocp/rabbit_kelly2017.yaml --out "$gait" --quiet
fi
"$bin" simulate --reference "$gait" --controller hzd --steps 20 --rate 200 --no-plots \
  --out results/walk_rabbit_hzd
/usr/bin/python3 plots/hzd_plots.py results/walk_rabbit_hzd
