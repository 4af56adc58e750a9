#!/usr/bin/env bash
# End-to-end checks of `gaitopt simulate`: the polynomial gait walks on each ground, the outputs
# and summary keys, a fall is a result (exit 0, fell: true), bad input exits 2 naming the problem.
# Usage: simulate_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
# The polynomial gait walks a robot with a heel long enough for its ankle torque.
LONG_HEEL="$ROOT/tests/apps/mu2004_five_link_long_heel.yaml"
cd "$ROOT" || fail "no repo root $ROOT"  # the reference folder names its robot under configs/
# The reference: the polynomial gait, made here (results/ keeps no trajectory CSVs).
REF="$TMP/poly"
run poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004.yaml \
  --out "$REF" --no-plots
[[ $RC -eq 0 ]] || fail "poly exited $RC: $(cat "$TMP/err")"

# (a) rigid ground, 2 steps: files, row counts, the planned steps, the summary keys.
run simulate --robot "$LONG_HEEL" --reference "$REF" --steps 2 --no-poincare --no-plots --out "$TMP/rigid"
[[ $RC -eq 0 ]] || fail "(a) simulate exited $RC: $(cat "$TMP/err")"
for f in walk.csv steps.csv stick.csv summary.json; do
  [[ -f "$TMP/rigid/$f" ]] || fail "(a) $f missing"
done
ls -d "$TMP"/rigid.tmp-* 2>/dev/null && fail "(a) staging folder left behind"
[[ $(wc -l <"$TMP/rigid/steps.csv") -eq 3 ]] || fail "(a) steps.csv: $(cat "$TMP/rigid/steps.csv")"
check_json "(a) summary" "$TMP/rigid/summary.json" <<'PY'
assert d["steps_completed"] == 2 and d["fell"] is False and d["failure"] == "", d
assert d["max_tracking_error"] < 2e-3, d["max_tracking_error"]  # 1.3e-3 rad measured
assert abs(d["mean_step_length"] - 0.35) < 1e-3, d["mean_step_length"]
assert abs(d["mean_step_duration"] - 0.7) < 3e-3, d["mean_step_duration"]
assert d["poincare_max_multiplier"] is None and d["ground"] == "rigid", d
assert d["robot"] == "mu2004_five_link" and d["friction"] == 0.6
assert 0 <= d["max_tip_penetration_m"] < 1e-6, d["max_tip_penetration_m"]  # 1e-6: touchdown's
PY
head -1 "$TMP/rigid/steps.csv" | grep -q ',failure,max_tip_penetration_m$' ||
  fail "(a) steps.csv header: $(head -1 "$TMP/rigid/steps.csv")"
grep -q "warning" "$TMP/out" && fail "(a) $(cat "$TMP/out")"
# walk.csv ends at the end of step 2 (t = 1.4 s) and its hip advances two steps.
"$PY" - "$TMP/rigid/walk.csv" <<'PY' || fail "(a) walk.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert abs(float(rows[-1]["t"]) - 1.4) < 5e-3, rows[-1]["t"]
assert {r["phase"] for r in rows} == {"SSP", "DSP"}
advance = float(rows[-1]["hip_x"]) - float(rows[0]["hip_x"])
assert abs(advance - 0.7) < 2e-3, advance
PY

# (b) the compliant and LCP grounds walk the same 2 steps, within a few mm of the rigid ones.
for ground in impedance lcp; do
  run simulate --robot "$LONG_HEEL" --reference "$REF" --steps 2 --ground "$ground" --no-plots --out "$TMP/$ground"
  [[ $RC -eq 0 ]] || fail "(b) $ground exited $RC: $(cat "$TMP/err")"
  check_json "(b) $ground summary" "$TMP/$ground/summary.json" <<'PY'
assert d["steps_completed"] == 2 and not d["fell"], d["failure"]
assert abs(d["mean_step_length"] - 0.35) < 5e-3, d["mean_step_length"]
assert d["poincare_max_multiplier"] is None  # the return map is the rigid model's
assert d["max_tip_penetration_m"] is None  # these grounds model a tip in the ground
PY
done

# (b2) in DART (a -DGAITOPT_DART=ON build): the same 2 steps on feet that are bodies, its
# pictures drawn, and a report page that animates it like any other walk.
run simulate --robot "$LONG_HEEL" --reference "$REF" --steps 2 --ground dart --no-poincare \
  --out "$TMP/dart"
if grep -q "needs a build with DART" "$TMP/err"; then
  echo "note: (b2) skipped: this build has no DART"
else
  [[ $RC -eq 0 ]] || fail "(b2) dart exited $RC: $(cat "$TMP/err")"
  grep -q "plotting failed" "$TMP/err" && fail "(b2) $(cat "$TMP/err")"
  check_json "(b2) dart summary" "$TMP/dart/summary.json" <<'PY'
assert d["steps_completed"] == 2 and not d["fell"], d["failure"]
assert abs(d["mean_step_length"] - 0.35) < 5e-3, d["mean_step_length"]
assert d["max_foot_tilt_rad"] < 1e-3, d["max_foot_tilt_rad"]  # 7.9e-5 rad measured
PY
  [[ -f "$TMP/dart/walk_overview.png" ]] || fail "(b2) no walk_overview.png"
  run report "$TMP/dart" --no-gif
  [[ $RC -eq 0 && -s "$TMP/dart/report.html" ]] || fail "(b2) report exited $RC: $(cat "$TMP/err")"
fi

# (c) Mu's uncertainty case 3 on the plant: the polynomial gait falls, which is a result.
run simulate --robot "$LONG_HEEL" --reference "$REF" --steps 3 --uncertainty-case 3 --no-plots --out "$TMP/case3"
[[ $RC -eq 0 ]] || fail "(c) a fall must exit 0, got $RC: $(cat "$TMP/err")"
check_json "(c) summary" "$TMP/case3/summary.json" <<'PY'
assert d["fell"] is True and d["steps_completed"] < 3 and d["failure"].startswith("step "), d
assert d["parameter_errors"] == {"mass": 1.0, "inertia": 1.0, "length": 0.4, "com": 0.4}
PY

# (c2) one point of a stability sweep walked on its own: --mass-error and --length-error replace
# the case's errors (here case 3's), so a failing sweep point can be looked at.
run simulate --robot "$LONG_HEEL" --reference "$REF" --steps 1 --uncertainty-case 3 \
  --mass-error -0.05 --length-error 0.025 --no-plots --no-poincare --out "$TMP/point"
[[ $RC -eq 0 ]] || fail "(c2) expected exit 0, got $RC: $(cat "$TMP/err")"
check_json "(c2) summary" "$TMP/point/summary.json" <<'PY'
assert d["parameter_errors"] == {"mass": -0.05, "inertia": -0.05, "length": 0.025, "com": 0.025}, d
PY

# (c2b) on the rigid ground a swing tip below it behind the stance tip is no contact (touchdown
# is ahead of it only): the walk goes on through the floor, measured and told, not failed. The
# polynomial gait under computed torque with the plant's masses doubled: 1.55 mm in step 1.
run simulate --robot "$LONG_HEEL" --reference "$REF" --steps 3 --controller computed_torque \
  --mass-error 1 --no-plots --no-poincare --out "$TMP/through"
[[ $RC -eq 0 ]] || fail "(c2b) expected exit 0, got $RC: $(cat "$TMP/err")"
grep -q "^simulate: warning: a swing tip went 1.5[0-9] mm below the ground (deepest in step 1), a contact the rigid ground does not model: the walk is not physical there$" \
  "$TMP/out" || fail "(c2b) no warning: $(cat "$TMP/out")"
check_json "(c2b) summary" "$TMP/through/summary.json" <<'PY'
assert 1e-3 < d["max_tip_penetration_m"] < 2e-3, d["max_tip_penetration_m"]
PY

# (c3) --set replaces values of the robot and ground files: the shipped robot given the long
# heel on the command line walks the steps its 5 cm heel fails, and summary.json records it.
run simulate --reference "$REF" --steps 2 --no-poincare --no-plots --out "$TMP/set" \
  --set robot.foot.heel=0.30 --set robot.foot.toe=0.15 --set ground.time_step=0.0005
[[ $RC -eq 0 ]] || fail "(c3) expected exit 0, got $RC: $(cat "$TMP/err")"
check_json "(c3) summary" "$TMP/set/summary.json" <<'PY'
assert d["steps_completed"] == 2 and not d["fell"], d["failure"]
assert d["config_overrides"] == ["robot.foot.heel=0.30", "robot.foot.toe=0.15",
                                 "ground.time_step=0.0005"], d["config_overrides"]
PY
run simulate --reference "$REF" --steps 2 --no-poincare --no-plots --out "$TMP/heel5"
check_json "(c3) the shipped heel" "$TMP/heel5/summary.json" <<'PY'
assert d["fell"] and d["steps_completed"] == 0, d["failure"]
PY

# (c4) a walk that ends at t = 0 has pictures too, and no "error:" on its exit 0: the polynomial
# gait's CoP is off the shipped heel at its first state (--cop-limit fail: one sample in
# walk.csv), and too long a time step diverges the impedance ground's first (no sample).
if "$PY" -c "import matplotlib" 2>/dev/null; then
  for at_zero in "--cop-limit fail" "--ground impedance --set ground.time_step=0.01"; do
    # shellcheck disable=SC2086  # the options are words
    run simulate --reference "$REF" --steps 3 --no-poincare --out "$TMP/at_zero" $at_zero
    [[ $RC -eq 0 ]] || fail "(c4) $at_zero: exit $RC: $(cat "$TMP/err")"
    grep -Eq "^(error|warning):" "$TMP/err" && fail "(c4) $at_zero: $(cat "$TMP/err")"
    for name in walk_stick walk_overview; do
      [[ -s "$TMP/at_zero/$name.png" ]] || fail "(c4) $at_zero: no $name.png"
    done
  done
  # The same command again replaces its own walk, pictures and all (they were once left off the
  # folder's list of written files, and the rerun was refused).
  run simulate --reference "$REF" --steps 3 --no-poincare --out "$TMP/at_zero" --cop-limit fail
  [[ $RC -eq 0 ]] || fail "(c4) rerun into the walk's own folder: exit $RC: $(cat "$TMP/err")"
  rm -rf "$TMP/at_zero"
else
  echo "note: (c4) skipped: no matplotlib"
fi

# (d) bad input: exit 2 with a message naming what is wrong, and the old result untouched.
bad() {
  local name=$1 pattern=$2
  shift 2
  run simulate --no-plots --out "$TMP/rigid" "$@"
  [[ $RC -eq 2 ]] || fail "($name) expected exit 2, got $RC: $(cat "$TMP/err")"
  grep -q -- "$pattern" "$TMP/err" || fail "($name) message lacks '$pattern': $(cat "$TMP/err")"
}
bad "no folder" "not a folder" --reference "$TMP/nowhere"
bad "unknown controller" "controller" --reference "$REF" --controller pid
sed 's/^stiffness: .*/stiffness: -1/' configs/grounds/impedance.yaml >"$TMP/ground.yaml"
bad "bad ground" "stiffness" --reference "$REF" --ground "$TMP/ground.yaml"
bad "--set scope" "robot.KEY or ground.KEY" --reference "$REF" --set heel=0.3
bad "--set robot range" "key 'foot.heel': expected a number >= 0" --reference "$REF" \
  --set robot.foot.heel=-1
bad "--set ground key" "key 'bogus': unknown key" --reference "$REF" --set ground.bogus=1
grep -q -- "--set ground.bogus=1" "$TMP/err" || fail "(--set) the message names what was typed: $(cat "$TMP/err")"
bad "case 4" "uncertainty-case" --reference "$REF" --uncertainty-case 4
bad "mass error below -50 %" "mass-error" --reference "$REF" --mass-error -0.9
bad "hzd with a DSP" "controller hzd.*double support" --reference "$REF" --controller hzd
# A slip limit of 0 ended every walk at t = 0 as a slip its summary gave as 0.
bad "--max-slip 0" "--max-slip: expected a number in (0, 1] \[m\], got 0" --reference "$REF" \
  --max-slip 0
[[ $(wc -l <"$TMP/rigid/steps.csv") -eq 3 ]] || fail "(d) a failed run touched the old result"
# (k) the knee-less walker under HZD on rigid ground: its swing tip meets the ground at the
# stance tip as the legs cross at mid-swing, where no frictional impact is consistent; the walk
# ends by a scuff, named as one, not by a failure of Coulomb's law.
run optimize --config "$ROOT/configs/ocp/three_link_walk.yaml" --out "$TMP/three" --rate 200 \
  --no-plots --quiet
run simulate --reference "$TMP/three" --controller hzd --steps 2 --no-poincare --no-plots \
  --out "$TMP/three_walk"
[[ $RC -eq 0 ]] || fail "(k) exited $RC: $(cat "$TMP/err")"
grep -q "0 of 2 steps then fell (step 1: the swing tip struck the ground .* ahead of the stance tip, 0 % of the planned 0.5 m step: a scuff" \
  "$TMP/out" || fail "(k) $(cat "$TMP/out")"
# A long walk says how far it is, a tenth of its steps at a time (3000 steps said nothing for
# 80 s): the HZD walk of RABBIT's optimum, 100 steps.
run optimize --config "$ROOT/configs/ocp/rabbit_kelly2017.yaml" --out "$TMP/rabbit" --rate 200 \
  --no-plots --quiet
run simulate --reference "$TMP/rabbit" --controller hzd --steps 100 --no-poincare \
  --no-plots --rate 10 --out "$TMP/long_walk"
[[ $RC -eq 0 ]] || fail "(k) long walk exited $RC: $(cat "$TMP/err")"
[[ $(grep -c "^simulate: step [0-9]* of 100, [0-9]* s$" "$TMP/out") -eq 9 ]] ||
  fail "(k) progress lines: $(cat "$TMP/out")"
# The passive compass gait walks down its 0.05 rad slope, and its walk says so.
run optimize --config "$ROOT/configs/ocp/compass_gait_passive.yaml" --out "$TMP/passive" \
  --rate 200 --no-plots --quiet
run simulate --reference "$TMP/passive" --controller hzd --steps 1 --no-poincare --no-plots \
  --out "$TMP/passive_walk"
check_json "(k) the walk's slope" "$TMP/passive_walk/summary.json" <<'PY'
assert d["slope_rad"] == -0.05, d.get("slope_rad")
PY
echo "simulate CLI: all checks passed"
