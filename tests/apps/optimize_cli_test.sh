#!/usr/bin/env bash
# End-to-end checks of `gaitopt optimize`: RABBIT (Kelly 2017's robot), outputs and exit codes.
# Usage: optimize_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
CONFIG="$ROOT/configs/ocp/rabbit_kelly2017.yaml"

# (a) the benchmark solves; the summary carries the solver's figures; the CSV is dense.
run optimize --config "$CONFIG" --out "$TMP/opt" --rate 200 --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(a) optimize exited $RC: $(cat "$TMP/err")"
grep -q "Solve_Succeeded" "$TMP/out" || fail "(a) no status line: $(cat "$TMP/out")"
rows=$(($(wc -l <"$TMP/opt/trajectory.csv") - 1))
[[ $rows -eq 141 ]] || fail "(a) expected 141 rows at 200 Hz over 0.7 s, got $rows"
check_json "(a) summary" "$TMP/opt/summary.json" <<'PY'
assert d["status"] == "Solve_Succeeded", d["status"]
# A regression figure, not a published one: this config's own optimum (0.5 m in 0.7 s), which
# issue 34 holds at 390.79. Kelly's published 263.70 (a 0.4 m step in 0.6 s) is checked by
# RabbitKelly2017.ShortStepCostMatchesThePublishedGpopsValue.
assert abs(d["cost"] - 390.79) < 0.005, d["cost"]
# 8 iterations with the multipliers started mu-based (13 when started constant); a margin for other BLAS
assert d["iterations"] <= 10, d["iterations"]
assert d["iterations"] > 0 and d["wall_time_s"] > d["callback_time_s"] > 0
assert d["max_violation"] < 1e-6, d["max_violation"]
assert d["impact_energy_loss_J"] > 0, d["impact_energy_loss_J"]
assert max(abs(t) for t in d["peak_torque"][1:]) <= 100 + 1e-6 and d["peak_torque"][0] == 0
# RABBIT's point feet stay loaded inside mu between the points, and its swing tip above ground
assert d["between_nodes"]["breaches"] == [], d["between_nodes"]["breaches"]
# At 200 Hz the derivative checks are not judged, and the summary says so rather than let an
# empty breach list stand for them.
u = d["between_nodes"]["unjudged"]
assert u["checks"] == ["max_rate_mismatch", "max_acceleration_mismatch"], u
assert "1000 Hz" in u["why"] and "200 Hz" in u["why"], u
PY
! grep -q "warning" "$TMP/err" || fail "(a) a warning for an export that keeps its bounds: $(cat "$TMP/err")"
grep -q "not judged on this export: max_rate_mismatch, max_acceleration_mismatch" "$TMP/out" ||
  fail "(a) the unjudged checks not named: $(cat "$TMP/out")"

# (b) a config with a typo: exit 2, file and key named, no output folder.
sed 's/step_length:/step_lenght:/' "$CONFIG" >"$TMP/typo.yaml"
sed -i "s|\.\./|$ROOT/configs/|" "$TMP/typo.yaml"
run optimize --config "$TMP/typo.yaml" --out "$TMP/typo" --quiet --no-plots
[[ $RC -eq 2 ]] || fail "(b) expected exit 2, got $RC: $(cat "$TMP/err")"
grep -q "typo.yaml.*key 'step_lenght': unknown key" "$TMP/err" || fail "(b) $(cat "$TMP/err")"
[[ ! -e "$TMP/typo" ]] || fail "(b) an output folder was created for a bad input"

# (c) an iteration limit too small to converge: exit 4, nothing in DIR, last iterate in DIR.failed.
sed "s|max_iterations: 500|max_iterations: 2|; s|\.\./|$ROOT/configs/|" "$CONFIG" >"$TMP/short.yaml"
run optimize --config "$TMP/short.yaml" --out "$TMP/short" --quiet --no-plots
[[ $RC -eq 4 ]] || fail "(c) expected exit 4, got $RC"
grep -q "Maximum_Iterations_Exceeded" "$TMP/err" || fail "(c) $(cat "$TMP/err")"
[[ ! -e "$TMP/short" && -f "$TMP/short.failed/summary.json" ]] || fail "(c) outputs misplaced"
# (a2) an ipopt.opt in the working directory does not reach the solver (every setting comes
# from the config and is echoed in summary.json): one allowed iteration would fail the solve.
mkdir -p "$TMP/cwd" && printf 'max_iter 1\n' >"$TMP/cwd/ipopt.opt"
(cd "$TMP/cwd" && run optimize --config "$CONFIG" --out "$TMP/opt_cwd" --quiet --no-plots &&
  echo "$RC" >"$TMP/cwd/rc")
[[ $(cat "$TMP/cwd/rc") -eq 0 ]] || fail "(a2) ipopt.opt in the working directory was read"
# (d) on the five-link problem a warm start from a previous result reaches the same optimum in
# fewer iterations (measured: 12 against 15).
FIVE="$ROOT/configs/ocp/mu2004_walk.yaml"
run optimize --config "$FIVE" --out "$TMP/cold5" --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(d) cold start exited $RC: $(cat "$TMP/err")"
# (d1) the default's export keeps every contact bound of the export contract: its DSP, collocated
# in Mu's reduced coordinates, holds the leading tip on its point between the points too. Its one
# breach is the robot file's joint velocity limit, which the config does not ask of the joints
# (rate_limit bounds the links): the swing knee turns at 1.36 times 10 rad/s. Asked of them
# (constraints.joint_velocity_limits), the optimum keeps it, for 7 % more cost. The same problem
# with the DSP collocated in theta lets the tip drift too (0.59 mm, results/dsp_coordinates.md),
# warned of even under --quiet and listed in summary.json.
check_json "(d1) breaches" "$TMP/cold5/summary.json" <<'PY'
b = d["between_nodes"]
assert [x["check"] for x in b["breaches"]] == ["max_joint_rate_use"], b["breaches"]
assert 1.3 < b["max_joint_rate_use"] < 1.4 and b["max_dsp_tip_drift"] <= 1e-9, b
PY
grep -q "warning: on the 1000 Hz export a joint turns faster than the robot file's velocity_limit" \
  "$TMP/err" || fail "(d1) no joint-rate warning: $(cat "$TMP/err")"
run optimize --config "$FIVE" --out "$TMP/joints5" --quiet --no-plots \
  --set constraints.joint_velocity_limits=true
[[ $RC -eq 0 ]] || fail "(d1) joint limits exited $RC: $(cat "$TMP/err")"
check_json "(d1) joint limits" "$TMP/joints5/summary.json" <<'PY'
b = d["between_nodes"]
assert b["breaches"] == [] and b["max_joint_rate_use"] <= 1.01, b
PY
run optimize --config "$FIVE" --out "$TMP/theta5" --quiet --no-plots \
  --set constraints.dsp_reduced_coordinates=false --set 'phases[1].first_segment=null'
[[ $RC -eq 0 ]] || fail "(d1) theta exited $RC: $(cat "$TMP/err")"
grep -q "warning: on the 1000 Hz export the double support's leading tip.*max_dsp_tip_drift" \
  "$TMP/err" || fail "(d1) no drift warning: $(cat "$TMP/err")"
check_json "(d1) breaches" "$TMP/theta5/summary.json" <<'PY'
b = d["between_nodes"]["breaches"]
assert [x["check"] for x in b] == ["max_dsp_tip_drift", "max_joint_rate_use"], b
assert b[0]["value"] > 1e-4 and b[0]["bound"] == 1e-6, b
PY
run optimize --config "$FIVE" --out "$TMP/warm5" --warm-start "$TMP/cold5" --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(d) warm start exited $RC: $(cat "$TMP/err")"
"$PY" - "$TMP/cold5/summary.json" "$TMP/warm5/summary.json" "$TMP/theta5/summary.json" \
  <<'PY' || fail "(d) warm start"
import json, sys
cold, warm, theta = (json.load(open(f)) for f in sys.argv[1:4])
assert abs(warm["cost"] - cold["cost"]) < 1e-4 * cold["cost"], (warm["cost"], cold["cost"])
# Pinning the tip at every point, not only its acceleration, can only cost more, and little: the
# reduced form's optimum lies within 1 % above theta's (measured 0.8 %). 15 iterations measured
# (27 with Ipopt's default multiplier start); a margin for other BLAS.
assert theta["cost"] < cold["cost"] < 1.01 * theta["cost"], (cold["cost"], theta["cost"])
assert cold["iterations"] <= 18, cold["iterations"]
assert warm["iterations"] < cold["iterations"], (warm["iterations"], cold["iterations"])
PY
# (e) every shipped OCP config converges.
for config in "$ROOT"/configs/ocp/*.yaml; do
  name=$(basename "$config" .yaml)
  # The ensemble (three coupled models, about 20 s in Release and minutes under the sanitizers)
  # is solved and walked by tests/sim/ensemble_walk_test.cpp in optimised builds.
  [[ $name == *_ensemble ]] && continue
  run optimize --config "$config" --out "$TMP/shipped_$name" --quiet --no-plots
  [[ $RC -eq 0 ]] || fail "(e) $name exited $RC: $(cat "$TMP/err")"
  # No shipped config pins a linear solver (issue 34), and gaitopt's KKT solver makes its own
  # factorizations: it leaves MUMPS under 5 % of them.
  check_json "(e) $name: MUMPS fallbacks" "$TMP/shipped_$name/summary.json" <<'PY'
k = d["kkt"]
assert k["linear_solver"] == "ldl" and k["mumps_fallback_share"] < 0.05, k
PY
done
check_json "(e) free durations" "$TMP/shipped_mu2004_walk_cot/summary.json" <<'PY'
ssp, dsp = (p["duration"] for p in d["phases"])
assert abs(ssp + dsp - 0.7) < 1e-9 and 0.45 <= ssp <= 0.65 and 0.05 <= dsp <= 0.25, d["phases"]
assert d["cost_type"] == "cost_of_transport"
# Its 1 kHz export is exact between the points (issue 34): the DSP's tip stays on its point, the
# rates and accelerations are the derivatives of the angles and rates, and the work the optimiser
# counts is the work the export does (the interior split, ocp/problem/interior_work.hpp; the
# optimum of quarter-point splits read with the points' quadratic rate hid 29 % of it).
b = d["between_nodes"]
assert b["rate_hz"] == 1000 and b["max_dsp_tip_drift"] <= 1e-6, b
assert "unjudged" not in b, b  # every check is judged at 1 kHz
assert b["max_rate_mismatch"] <= 0.002 and b["max_acceleration_mismatch"] <= 0.01, b
counted = sum(v for k, v in d["cost_terms"]["terms"].items() if "abs_work" in k)
assert abs(counted - d["cost_of_transport"]) <= 0.05 * d["cost_of_transport"], (counted, d["cost_of_transport"])
PY

# (f) mesh refinement: the summary's history shows the worst segment error falling below the
# requested tolerance on a mesh finer than the configured one.
sed "s|^solver:|mesh_refinement: {tolerance: 5.0e-5, max_rounds: 4}\nsolver:|; s|\.\./|$ROOT/configs/|" \
  "$CONFIG" >"$TMP/refine.yaml"
run optimize --config "$TMP/refine.yaml" --out "$TMP/refine" --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(f) exited $RC: $(cat "$TMP/err")"
check_json "(f) mesh history" "$TMP/refine/summary.json" <<'PY'
h = d["mesh_history"]
assert len(h) >= 2, h
errors = [r["max_segment_error_Nms"] for r in h]
assert all(b < a for a, b in zip(errors, errors[1:])), errors
assert errors[-1] <= 5.0e-5 and h[-1]["segments"][0] > 25, h
assert d["iterations"] == sum(r["iterations"] for r in h)
PY

# (g) a result folder re-solves to the same cost from its summary.json and config alone: the
# config with its solver block replaced by the summary's `solver` echo (every setting, defaults
# filled in; the refinement rounds' settings are fixed by the code and only echoed).
"$PY" - "$TMP/opt/summary.json" "$TMP/resolve.yaml" <<'PY' || fail "(g) config from summary"
import json, os, sys, yaml
summary = json.load(open(sys.argv[1]))
config = yaml.safe_load(open(summary["config"]))
here = os.path.dirname(os.path.abspath(summary["config"]))
for key in ("robot", "initial_guess"):
    config[key] = os.path.normpath(os.path.join(here, config[key]))
config["solver"] = {k: v for k, v in summary["solver"].items() if not k.startswith("refinement")}
json.dump(config, open(sys.argv[2], "w"))  # JSON is YAML
PY
run optimize --config "$TMP/resolve.yaml" --out "$TMP/resolve" --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(g) re-solve exited $RC: $(cat "$TMP/err")"
"$PY" - "$TMP/opt/summary.json" "$TMP/resolve/summary.json" <<'PY' || fail "(g) re-solve"
import json, sys
first, again = (json.load(open(f)) for f in sys.argv[1:3])
assert abs(again["cost"] - first["cost"]) <= 1e-9 * first["cost"], (again["cost"], first["cost"])
assert again["iterations"] == first["iterations"], (again["iterations"], first["iterations"])
assert again["solver"] == first["solver"], (again["solver"], first["solver"])
PY
# (h) --set replaces config values as an edit of the file would (the same optimum), records them
# in summary.json, and is checked as the file is: the friction bound holds at mu - margin.
C="$ROOT/configs/ocp/mu2004_walk.yaml"
run optimize --config "$C" --set 'phases[0].segments=24' --set constraints.friction_margin=0.2 \
  --out "$TMP/set" --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(h) --set exited $RC: $(cat "$TMP/err")"
sed "s|\.\./|$ROOT/configs/|; s/\({name: SSP, .*segments: \)30}/\124}/; s/friction_margin: [0-9.]*/friction_margin: 0.2/" \
  "$C" >"$TMP/edited.yaml"
grep -q "segments: 24}" "$TMP/edited.yaml" && grep -q "friction_margin: 0.2" "$TMP/edited.yaml" ||
  fail "(h) the edited copy lacks the edits"
run optimize --config "$TMP/edited.yaml" --out "$TMP/edited" --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(h) edited config exited $RC: $(cat "$TMP/err")"
"$PY" - "$TMP/set/summary.json" "$TMP/edited/summary.json" <<'PY' || fail "(h) --set"
import json, sys
s, e = (json.load(open(f)) for f in sys.argv[1:3])
assert s["config_overrides"] == ["phases[0].segments=24", "constraints.friction_margin=0.2"], s
assert "config_overrides" not in e, e.keys()
assert s["mesh_history"][0]["segments"][0] == 24, s["mesh_history"]
assert abs(s["cost"] - e["cost"]) <= 1e-9 * e["cost"], (s["cost"], e["cost"])
assert s["max_friction_ratio"] <= s["friction"] - 0.2 + 1e-6, s["max_friction_ratio"]
PY
run optimize --config "$C" --set 'phases[0].segments=0' --out "$TMP/v" --quiet --no-plots
[[ $RC -eq 2 ]] && grep -q -- "--set phases\[0\].segments=0.*expected a whole number in \[1, 1000\]" "$TMP/err" ||
  fail "(h) a bad --set value: exit $RC: $(cat "$TMP/err")"
run optimize --config "$C" --set 'phases[2].segments=8' --out "$TMP/v" --quiet --no-plots
[[ $RC -eq 2 ]] && grep -q "there is no list item \[2\] there: the list has 2 item(s), \[0\] to \[1\]" "$TMP/err" ||
  fail "(h) --set past a list's end: exit $RC: $(cat "$TMP/err")"
[[ ! -e $TMP/v ]] || fail "(h) a refused --set wrote a folder"

# (i) two steps in one period (`--set steps=2`, docs/design.md#the-problems-shape): the passive
# compass gait stays passive, and the summary says the folder holds the nominal's first step.
run optimize --config "$ROOT/configs/ocp/compass_gait_passive.yaml" --set steps=2 \
  --out "$TMP/two" --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(i) steps=2 exited $RC: $(cat "$TMP/err")"
check_json "(i) two steps" "$TMP/two/summary.json" <<'PY'
assert d["nlp"]["shape"] == {"steps": 2, "variants": 1, "exported": "the nominal's first step"}, d["nlp"]
assert d["cost"] < 1e-8, d["cost"]
# the passive step of configs/ocp/compass_gait_passive.yaml (Newton shooting): 0.621817212397 s
assert abs(d["duration"] - 0.621817212397) < 1e-3, d["duration"]
PY
# The compass-gait walk's tip lands grazing: 2.8 m/s along the ground, none into it. It still
# strikes (its impulse stops the tip), so the summary names the impact, not a landing at rest.
run optimize --config "$ROOT/configs/ocp/compass_gait_walk.yaml" --out "$TMP/grazing" --rate 200 \
  --quiet --no-plots
[[ $RC -eq 0 ]] || fail "grazing strike: exited $RC: $(cat "$TMP/err")"
check_json "grazing strike" "$TMP/grazing/summary.json" <<'PY'
s = d["strike"]
assert s["tip_velocity"][0] > 2 and abs(s["normal_velocity"]) < 1e-6, s
assert s["impact_admitted"] == "single", s["impact_admitted"]
PY
echo "optimize CLI: all checks passed"
