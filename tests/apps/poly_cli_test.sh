#!/usr/bin/env bash
# End-to-end checks of `gaitopt poly`: outputs, summary values, exit codes and --set.
# Usage: poly_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
ROBOT="$ROOT/configs/robots/mu2004_five_link.yaml"
GAIT="$ROOT/configs/gaits/mu2004.yaml"

# (a) the Mu gait at 200 Hz, no pictures: files, sample count and physics in summary.json.
run poly --robot "$ROBOT" --gait "$GAIT" --out "$TMP/poly" --rate 200 --no-plots
[[ $RC -eq 0 ]] || fail "(a) poly exited $RC: $(cat "$TMP/err")"
[[ -f "$TMP/poly/trajectory.csv" && -f "$TMP/poly/summary.json" ]] || fail "(a) outputs missing"
rows=$(($(wc -l <"$TMP/poly/trajectory.csv") - 1))
[[ $rows -eq 141 ]] || fail "(a) expected the 141 grid samples t_i = i / 200, i = 0..140, got $rows"
"$PY" - "$TMP/poly/trajectory.csv" <<'PY' || fail "(a) the CSV is not on the grid i / 200"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
t = [float(r["t"]) for r in rows]
assert all(abs(ti - i / 200) < 1e-12 for i, ti in enumerate(t)), "off the grid"
assert all(b > a for a, b in zip(t, t[1:])), "time not strictly increasing"
assert all(r["phase"] == ("SSP" if float(r["t"]) < 0.6 else "DSP") for r in rows), "phases"
PY
check_json "(a) summary values" "$TMP/poly/summary.json" <<'PY'
assert d["status"] == "designed" and d["robot"] == "mu2004_five_link"
assert abs(d["step_length"] - 0.35) < 1e-12 and abs(d["duration"] - 0.7) < 1e-12
assert [p["name"] for p in d["phases"]] == ["SSP", "DSP"]
assert d["min_normal_force"] > 0, d["min_normal_force"]
assert d["max_friction_ratio"] <= 0.4, d["max_friction_ratio"]
assert d["hip_plan"]["dsp_stability_margin"] > 0.35 * 0.35, d["hip_plan"]
assert d["max_defect"] < 1e-8, d["max_defect"]
assert d["periodicity_error"] < 1e-10, d["periodicity_error"]
assert d["impact_energy_loss_J"] < 1e-10, d["impact_energy_loss_J"]
assert abs(d["cost_of_transport"] - d["energy_J"] / (d["total_mass"] * 9.81 * 0.35)) < 1e-12
# the states the grid does not sample: the touchdown's two and the end's
assert d["sample_rate_hz"] == 200
[s] = d["phase_switches"]
assert s["t"] == 0.6 and s["before"]["phase"] == "SSP" and s["after"]["phase"] == "DSP", s["t"]
assert s["before"]["t"] == s["after"]["t"] == 0.6
assert d["step_end"]["t"] == d["duration"] and d["step_end"]["phase"] == "DSP"
# judged by the export contract as an optimum is: Mu's gait puts its centre of pressure behind
# the shipped 5 cm heel (its ZMP leaves the foot, docs/design.md), and 200 Hz is too coarse for
# the derivative checks
b = d["between_nodes"]
assert [x["check"] for x in b["breaches"]] == ["min_foot_cop_margin"], b["breaches"]
assert b["min_foot_cop_margin"] < -0.1 and b["min_normal_force"] > 0, b
assert b["unjudged"]["checks"] == ["max_rate_mismatch", "max_acceleration_mismatch"]
PY
grep -q "poly: warning: on the 200 Hz export foot B's centre of pressure leaves the foot" \
  "$TMP/err" || fail "(a) no warning of the breach: $(cat "$TMP/err")"

# (b) a gait file with a typo names the file and key; exit code 2.
sed 's/ssp_duration/ssp_duraton/' "$GAIT" >"$TMP/typo.yaml"
run poly --robot "$ROBOT" --gait "$TMP/typo.yaml" --out "$TMP/typo" --no-plots
[[ $RC -eq 2 ]] || fail "(b) expected exit 2, got $RC"
grep -q "typo.yaml:.*key 'ssp_duraton': unknown key" "$TMP/err" || fail "(b) message: $(cat "$TMP/err")"
[[ ! -e "$TMP/typo" ]] || fail "(b) an output folder was created for a bad input"

# (c) a hip higher than the legs reach: exit code 3, message with time and range.
sed 's/height: 0.59/height: 0.70/' "$GAIT" >"$TMP/high.yaml"
run poly --robot "$ROBOT" --gait "$TMP/high.yaml" --out "$TMP/high" --no-plots
[[ $RC -eq 3 ]] || fail "(c) expected exit 3, got $RC: $(cat "$TMP/err")"
grep -q "leg cannot reach" "$TMP/err" || fail "(c) message: $(cat "$TMP/err")"

# (d) a knee-less robot is refused clearly.
run poly --robot "$ROOT/configs/robots/compass_gait.yaml" --gait "$GAIT" --out "$TMP/cg" --no-plots
[[ $RC -ne 0 ]] && grep -q "needs legs of two links" "$TMP/err" || fail "(d) $(cat "$TMP/err")"
# (e) --set replaces a value of the gait config, recorded in summary.json; the same height as
# (c) on the command line is refused the same way, and a bad value exits 2 naming the --set.
run poly --robot "$ROBOT" --gait "$GAIT" --set step_length=0.3 --out "$TMP/set" --no-plots
[[ $RC -eq 0 ]] || fail "(e) exited $RC: $(cat "$TMP/err")"
check_json "(e) summary" "$TMP/set/summary.json" <<'PY'
assert abs(d["step_length"] - 0.3) < 1e-12, d["step_length"]
assert d["config_overrides"] == ["step_length=0.3"], d.get("config_overrides")
PY
run poly --robot "$ROBOT" --gait "$GAIT" --set hip.height=0.70 --out "$TMP/set_high" --no-plots
[[ $RC -eq 3 ]] && grep -q "leg cannot reach" "$TMP/err" || fail "(e) high: $RC $(cat "$TMP/err")"
run poly --robot "$ROBOT" --gait "$GAIT" --set step_length=long --out "$TMP/set_bad" --no-plots
[[ $RC -eq 2 ]] && grep -q "(--set step_length=long).*key 'step_length'" "$TMP/err" ||
  fail "(e) bad value: $RC $(cat "$TMP/err")"
[[ ! -e "$TMP/set_bad" ]] || fail "(e) a bad --set created its folder"
# (h) pictures asked for but not drawn (no plot scripts): the last line names no pictures.
GAITOPT_SCRIPTS="$TMP/no_scripts" run poly --robot "$ROBOT" --gait "$GAIT" --out "$TMP/nopics"
[[ $RC -eq 0 ]] || fail "(h) exited $RC: $(cat "$TMP/err")"
grep -q "plotting failed" "$TMP/err" || fail "(h) no warning: $(cat "$TMP/err")"
grep -q "summary.json$" "$TMP/out" && ! grep -q "and pictures" "$TMP/out" ||
  fail "(h) claims pictures: $(tail -n 1 "$TMP/out")"
# (g) poly for a robot whose legs have one link each: bad input (exit 2) naming the robot file.
run poly --robot "$ROOT/configs/robots/compass_gait.yaml" --gait "$ROOT/configs/gaits/mu2004.yaml" \
  --out "$TMP/p" --no-plots
[[ $RC -eq 2 ]] || fail "(g) poly on one-link legs: exit code $RC, expected 2"
grep -qF "compass_gait.yaml: the polynomial gait (Mu ch. 3) needs legs of two links" "$TMP/err" ||
  fail "(g) stderr: $(cat "$TMP/err")"
# (i) a gait five times as fast is written (exit 0) with a warning per bound it breaks: its
# stance tip pulls on the ground and its torques pass the robot file's limits. An apex far from
# mid-swing, where the swing tip's quintic dips below the ground (3.10-3.12), is refused.
run poly --robot "$ROBOT" --gait "$GAIT" --out "$TMP/fast" --no-plots --set ssp_duration=0.12 \
  --set dsp_duration=0.02
[[ $RC -eq 0 ]] || fail "(i) exited $RC: $(cat "$TMP/err")"
for what in "a tip in contact pulls on the ground (min_normal_force -5" \
  "a joint torque passes the robot file's torque_limit"; do
  grep -qF "poly: warning: on the 1000 Hz export $what" "$TMP/err" || fail "(i) $what: $(cat "$TMP/err")"
done
run poly --robot "$ROBOT" --gait "$GAIT" --out "$TMP/apex" --no-plots --set swing_apex.x=-0.2
[[ $RC -eq 2 ]] && grep -q "key 'swing_apex.x'.*the swing tip passes below the ground" "$TMP/err" ||
  fail "(i) apex far from mid-swing: $RC $(cat "$TMP/err")"
echo "poly CLI: all checks passed"
