#!/usr/bin/env bash
# The five-link optima walked in the DART physics engine (configs/grounds/dart.yaml, a build with
# -DGAITOPT_DART=ON): the torque-squared optimum (configs/ocp/mu2004_walk.yaml, lands at rest),
# the strike optimum (configs/ocp/mu2004_walk_strike.yaml) and the gait designed to be walked
# (configs/ocp/mu2004_walk_robust.yaml), on plants 0.9, 1.0 and 1.1 times the model's mass
# (scripts/walk_table.sh). Writes OUT/dart_walks.csv and OUT/dart_walks.md.
# Usage: scripts/dart_walks.sh BUILD_DIR OUT_DIR   (from the repository root)
set -euo pipefail
build=${1:?usage: $0 BUILD_DIR OUT_DIR}
out=${2:?usage: $0 BUILD_DIR OUT_DIR}
bash scripts/walk_table.sh "$build" "$out" dart_walks dart "-0.1 0 0.1" \
  mu2004_walk mu2004_walk_strike mu2004_walk_robust
