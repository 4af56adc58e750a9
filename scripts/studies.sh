#!/usr/bin/env bash
# The body of `make studies`: each study of configs/studies/ (docs/design.md#studies) run by
# `gaitopt study` into OUT_DIR/NAME (a rerun resumes there), then the chart or table of those
# that have one: strike_study (plots/strike_study_chart.py), strike_cost, ensemble_candidates,
# sensitivity_penalty, ensemble_export, ensemble_walks and ensemble_walks_clipped
# (plots/walk_battery_table.py) and ensemble_front (plots/ensemble_front_chart.py, beside the
# default optimum, and the same table). The results/ folders the README cites hold curated copies
# of their tables.
# Each takes minutes (the solver robustness study about 7).
# Usage: scripts/studies.sh BUILD_DIR OUT_DIR [NAME...]   (from the repository root; all when no
#        NAME is given)
set -euo pipefail
build=${1:?usage: $0 BUILD_DIR OUT_DIR [NAME...]}
out=${2:?usage: $0 BUILD_DIR OUT_DIR [NAME...]}
shift 2
bin="$build/apps/gaitopt"
[[ -x "$bin" ]] || { echo "error: $bin not built" >&2; exit 1; }
names=("$@")
if [[ ${#names[@]} -eq 0 ]]; then
  for config in configs/studies/*.yaml; do names+=("$(basename "$config" .yaml)"); done
fi
for name in "${names[@]}"; do
  "$bin" study --config "configs/studies/$name.yaml" --out "$out/$name"
  case $name in
    strike_study) /usr/bin/python3 plots/strike_study_chart.py "$out/$name" "$out/$name" ;;
    strike_cost | ensemble_candidates | sensitivity_penalty | ensemble_export | ensemble_walks | \
      ensemble_walks_clipped)
      /usr/bin/python3 plots/walk_battery_table.py "$out/$name" ;;
    ensemble_front)
      "$bin" optimize --config configs/ocp/mu2004_walk.yaml --out "$out/default_optimum" \
        --no-plots --quiet >/dev/null
      /usr/bin/python3 plots/ensemble_front_chart.py "$out/$name" "$out/default_optimum"
      /usr/bin/python3 plots/walk_battery_table.py "$out/$name"
      ;;
  esac
done
