#!/usr/bin/env bash
# One case per class of bad input: each must exit with its documented code (2 bad
# input, 3 a gait that cannot be realised) and print one line naming the file, the key or line,
# the value and what was expected; no result folder may appear.
# Usage: bad_input_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
ROBOT="$ROOT/configs/robots/mu2004_five_link.yaml"
GAIT="$ROOT/configs/gaits/mu2004.yaml"
OCP="$ROOT/configs/ocp/rabbit_kelly2017.yaml"

# expect NAME CODE PATTERN: the last run exited CODE, its stderr matches the extended regular
# expression PATTERN, and it created no result folder.
expect() {
  [[ $RC -eq $2 ]] || fail "$1: expected exit $2, got $RC: $(cat "$TMP/err")"
  grep -Eq -- "$3" "$TMP/err" || fail "$1: message does not match '$3': $(cat "$TMP/err")"
  [[ ! -e "$TMP/out_dir" ]] || fail "$1: a result folder was created for bad input"
  echo "ok $1: $(head -n 1 "$TMP/err")"
}
poly() { run poly "$@" --out "$TMP/out_dir" --no-plots; }
# edit SOURCE NAME SED: a copy of SOURCE edited by SED as $TMP/NAME (relative paths made absolute).
edit() { sed -e "$3" -e "s|\.\./|$ROOT/configs/|" "$1" >"$TMP/$2"; }

# NaN and Inf in a YAML number.
edit "$ROBOT" nan.yaml '/stance_thigh/s/mass: 5.28/mass: .nan/'
poly --robot "$TMP/nan.yaml" --gait "$GAIT"
expect "NaN" 2 "nan.yaml:16: key 'links\[1\]\.mass': expected a finite number, got '\.nan'"
edit "$ROBOT" inf.yaml '/torso/s/inertia: 0.033/inertia: -.inf/'
poly --robot "$TMP/inf.yaml" --gait "$GAIT"
expect "Inf" 2 "inf.yaml:17: key 'links\[2\]\.inertia': expected a finite number, got '-\.inf'"

# Degrees where radians are expected, told apart by range.
edit "$GAIT" degrees.yaml 's/torso_angle: 0.0/torso_angle: 30/'
poly --robot "$ROBOT" --gait "$TMP/degrees.yaml"
expect "degrees" 2 "degrees.yaml:18: key 'torso_angle': expected an angle in \[-1.571, 1.571\] \[rad\] \(degrees\? 30 deg is 0.5236 rad\), got 30"

# Zero or negative physical quantities.
edit "$ROBOT" mass0.yaml '/torso/s/mass: 14.79/mass: 0/'
poly --robot "$TMP/mass0.yaml" --gait "$GAIT"
expect "zero mass" 2 "mass0.yaml:17: key 'links\[2\]\.mass': expected a number in \[0.001, 10000\] \[kg\], got 0"
edit "$ROBOT" length.yaml '/swing_shank/s/length: 0.332/length: -0.332/'
poly --robot "$TMP/length.yaml" --gait "$GAIT"
expect "negative length" 2 "length.yaml:19: key 'links\[4\]\.length': expected a number in \[0.001, 100\] \[m\], got -0.332"

# An unknown key (a typo) in a robot and in an OCP config.
edit "$ROBOT" typo.yaml 's/^friction:/frcition:/'
poly --robot "$TMP/typo.yaml" --gait "$GAIT"
expect "unknown key" 2 "typo.yaml:12: key 'frcition': unknown key; allowed here: .*friction"
edit "$OCP" ocp_typo.yaml 's/^scheme:/shceme:/'
run optimize --config "$TMP/ocp_typo.yaml" --out "$TMP/out_dir" --quiet --no-plots
expect "unknown OCP key" 2 "ocp_typo.yaml:14: key 'shceme': unknown key"

# A step the legs cannot reach: the polynomial gait (its first sample) and the OCP (up front).
edit "$GAIT" far.yaml 's/step_length: 0.35/step_length: 1.5/'
poly --robot "$ROBOT" --gait "$TMP/far.yaml"
expect "out of reach (poly)" 3 "far.yaml: gait 'mu2004' \(step_length 1.5 m\) cannot be realised by robot 'mu2004_five_link': .*leg cannot reach: hip-tip distance 1.4733 m outside the open range \(0.0300, 0.6340\) m"
edit "$OCP" ocp_far.yaml 's/^step_length: 0.5/step_length: 1.9/'
run optimize --config "$TMP/ocp_far.yaml" --out "$TMP/out_dir" --quiet --no-plots
expect "out of reach (optimize)" 3 "ocp_far.yaml: key 'step_length': 1.9 m is out of reach: the legs of robot 'rabbit' \(0.8 m each\) span less than 1.6 m"
[[ ! -e "$TMP/out_dir.failed" ]] || fail "out of reach (optimize): Ipopt was run"
# What the problem's builders cannot make is refused when the config is read, by key (exit 2;
# it was exit 1 with no file named): interior contact rows on a trapezoidal mesh, a knee bound on
# knee-less legs, the computed-torque law of the variants on a robot with a passive joint.
OCPS="$ROOT/configs/ocp"
run optimize --config "$OCPS/mu2004_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots \
  --set constraints.interior_contact=4 --set scheme=trapezoidal
expect "interior contact, trapezoidal" 2 "key 'constraints.interior_contact': needs scheme: hermite_simpson"
run optimize --config "$OCPS/compass_gait_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots \
  --set 'constraints.max_knee_flexion=[0.5, 0.5]'
expect "knee bound, no knees" 2 "key 'constraints.max_knee_flexion': a knee flexion bound, but the robot's legs have no knees"
run optimize --config "$OCPS/three_link_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots \
  --set 'variants=[{mass_scale: 1.1}]' --set variant_end_tolerance=0.1 \
  --set 'variant_feedback={law: computed_torque, kp: 400, kd: 40, dsp_kp: 300, dsp_kd: 30}'
expect "computed torque, passive ankle" 2 "key 'variant_feedback.law': computed_torque commands every joint, and the robot's joint 'stance_ankle' is passive"
run optimize --config "$OCPS/mu2004_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots \
  --set 'variants=[{mass_scale: 1.1}, {mass_scale: 1.1}]' --set variant_end_tolerance=0.1 \
  --set 'variant_feedback={law: joint_pd, kp: 100, kd: 10}'
expect "a variant twice" 2 "key 'variants\[1\]\.mass_scale': the same variant is given twice"
run optimize --config "$OCPS/mu2004_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots \
  --set step_duration=0.7
expect "step_duration, fixed phases" 2 "key 'step_duration': needs a phase of free duration"
# A count given as a fraction is refused, not cut (2.5 iterations ran as 2).
run optimize --config "$OCPS/mu2004_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots \
  --set solver.max_iterations=2.5
expect "fractional count" 2 "key 'solver.max_iterations': expected a whole number in \[1, 100000\]"
run optimize --config "$OCPS/mu2004_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots \
  --set solver.min_refinement_steps=11
expect "refinement steps" 2 "key 'solver.min_refinement_steps': expected a whole number in \[0, 10\]"
# A rate too low for the step is refused before the solve (it was refused after it).
run optimize --config "$OCPS/mu2004_walk.yaml" --out "$TMP/out_dir" --quiet --no-plots --rate 5 \
  --set solver.max_iterations=1
expect "rate too low (optimize)" 2 "5 Hz samples the 0.7 s step 4 time\(s\), fewer than the 10"
[[ ! -e "$TMP/out_dir.failed" ]] || fail "rate too low (optimize): Ipopt was run"

# A config copied away from configs/ocp/: its robot, named relative to its own folder, is not
# there; the error names the config, the key and where it looked.
cp "$OCP" "$TMP/copied.yaml"
run optimize --config "$TMP/copied.yaml" --out "$TMP/out_dir" --quiet --no-plots
expect "copied config" 2 "copied.yaml:[0-9]+: key 'robot': no file '../robots/rabbit.yaml' \(read relative to the config's folder: .*/robots/rabbit.yaml\)"

# Friction coefficient 0.
edit "$ROBOT" mu0.yaml 's/^friction: 0.6/friction: 0/'
poly --robot "$TMP/mu0.yaml" --gait "$GAIT"
expect "friction 0" 2 "mu0.yaml:12: key 'friction': expected a number in \[1e-06, 10\] \(Coulomb mu\), got 0"

# A phase of zero duration, in a gait and in an OCP config.
edit "$GAIT" dsp0.yaml 's/dsp_duration: 0.1/dsp_duration: 0/'
poly --robot "$ROBOT" --gait "$TMP/dsp0.yaml"
expect "zero DSP" 2 "dsp0.yaml:10: key 'dsp_duration': expected a number in \[0.001, 10\] \[s\], got 0"
edit "$OCP" ocp_dur0.yaml 's/duration: 0.7,/duration: 0,/'
run optimize --config "$TMP/ocp_dur0.yaml" --out "$TMP/out_dir" --quiet --no-plots
expect "zero OCP phase" 2 "ocp_dur0.yaml:13: key 'phases\[0\]\.duration': expected a number in \[0.01, 10\] \[s\], got 0"

# A key given twice: yaml-cpp would silently keep the first.
edit "$ROBOT" dup.yaml 's/^gravity: 9.81/gravity: 9.81\ngravity: 1.62/'
poly --robot "$TMP/dup.yaml" --gait "$GAIT"
expect "duplicate key" 2 "dup.yaml:12: key 'gravity': duplicate key, first given at line 11"
edit "$OCP" ocp_dup.yaml 's/^cost: {torque_squared: 1.0}/cost: {torque_squared: 1.0, torque_squared: 2.0}/'
run optimize --config "$TMP/ocp_dup.yaml" --out "$TMP/out_dir" --quiet --no-plots
expect "duplicate OCP key" 2 "ocp_dup.yaml:16: key 'cost.torque_squared': duplicate key, first given at line 16"

# Malformed trajectory CSVs (read as a warm start): a missing column, a word, a NaN.
run optimize --config "$OCP" --out "$TMP/good" --rate 100 --quiet --no-plots
[[ $RC -eq 0 ]] || fail "CSV: the reference solve exited $RC: $(cat "$TMP/err")"
mkdir -p "$TMP/no_column" "$TMP/word" "$TMP/nan_csv"
sed '1s/,tau2,/,/' "$TMP/good/trajectory.csv" >"$TMP/no_column/trajectory.csv"
sed '5s/^\([^,]*\),\([^,]*\),[^,]*,/\1,\2,abc,/' "$TMP/good/trajectory.csv" >"$TMP/word/trajectory.csv"
sed '5s/^\([^,]*\),\([^,]*\),[^,]*,/\1,\2,nan,/' "$TMP/good/trajectory.csv" >"$TMP/nan_csv/trajectory.csv"
warm() { run optimize --config "$OCP" --out "$TMP/out_dir" --warm-start "$TMP/$1" --quiet --no-plots; }
warm no_column
expect "CSV missing column" 2 "no_column/trajectory.csv:1: key 'tau2': missing column \(column 30 should be 'tau2'\)"
warm word
expect "CSV non-numeric" 2 "word/trajectory.csv:5: key 'theta1': expected a number, found 'abc'"
warm nan_csv
expect "CSV NaN" 2 "nan_csv/trajectory.csv:5: key 'theta1': non-finite value 'nan'"

# Command-line mistakes: an unknown flag, values out of range or not numbers.
poly --robot "$ROBOT" --gait "$GAIT" --bogus
expect "unknown flag" 2 "The following argument was not expected: --bogus"
# A mistyped command or required option is named, not only the one it left missing.
run optimise --config "$OCP"
expect "mistyped command" 2 "unknown command 'optimise'; the commands: .*optimize"
run optimize --confg "$OCP" --out "$TMP/out_dir"
expect "mistyped required option" 2 "not an option of optimize: --confg .*; --config is required"
# CLI11's "At Most 4 required but received 6", in plain words.
run compare "$TMP/a" "$TMP/b" "$TMP/c" "$TMP/d" "$TMP/e" --out "$TMP/out_dir"
expect "too many folders" 2 "FOLDERS: takes at most 4 values, got 5"
poly --robot "$ROBOT" --gait "$GAIT" --rate 0
expect "rate 0" 2 "--rate: expected a number in \[1, 1e\+06\] \[Hz\], got 0"
poly --robot "$ROBOT" --gait "$GAIT" --rate fast
expect "rate word" 2 "--rate: Failed parsing fast as a FLOAT"
run optimize --config "$TMP/missing.yaml" --out "$TMP/out_dir" --quiet --no-plots
expect "missing file" 2 "missing.yaml: file not found or not a regular file"

# One validation per quantity (config/quantities.hpp): a sweep or map value is refused as the
# option of the same quantity is, and all the grids of a run meet the memory budget. Each line:
# NAME | PATTERN (its stderr) | ARGUMENTS of gaitopt stability. Bounded by `timeout`: before these
# checks a bad grid walked (or allocated) for hours.
run poly --robot "$ROBOT" --gait "$GAIT" --out "$TMP/ref" --no-plots
[[ $RC -eq 0 ]] || fail "stability: the reference poly exited $RC: $(cat "$TMP/err")"
while IFS='|' read -r name pattern args; do
  read -ra argv <<<"$args"
  timeout 120 "$GAITOPT" stability --reference "$TMP/ref" --robot "$ROBOT" --out "$TMP/out_dir" \
    --steps 2 --quiet --no-plots "${argv[@]}" </dev/null >"$TMP/out" 2>"$TMP/err"
  RC=$?
  expect "$name" 2 "$pattern"
done <<'CASES'
sweep overflowing push|--sweep: key 'push': expected a number in \[-1000, 1000\] \[N s\], got -1e\+308| --sweep push=-1e308:1e308:3
sweep mass_error above its option's range|--sweep: key 'mass_error': expected a number in \[-0.5, 2\], got 5| --sweep mass_error=5
option of the same quantity, same words|--mass-error: expected a number in \[-0.5, 2\], got 5| --mass-error 5 --sweep push
sweep mass_error below -1|--sweep: key 'mass_error': expected a number in \[-0.5, 2\], got -2| --sweep mass_error=-2
sweep stiffness on its decades|--sweep: key 'stiffness': expected a number in \[100, 1e\+12\] \[N/m\^n\], got 1| --ground impedance --sweep stiffness=1:1e6:3
map axis out of range|--map: key 'gain_scale': expected a number in \[0.001, 1000\], got 0| --map friction=0.1:0.5:2,gain_scale=0:2:2
map of 10^6 x 10^6 points|--map push=-3:3:1000000,mass_error=-0.2:0.2:1000000: a grid of 1e\+12 points needs about .* GB| --map push=-3:3:1000000,mass_error=-0.2:0.2:1000000
sweeps summed over the budget|--sweep friction=0:1:1000000: a grid of 2e\+06 points needs about .* GB| --sweep push=-3:3:1000000 --sweep friction=0:1:1000000
CASES

# A push comes in step 2: a walk of one step never meets it and would report it survived.
run simulate --reference "$TMP/ref" --out "$TMP/out_dir" --steps 1 --push 5 --no-plots --quiet
expect "push after the walk's end" 2 "--push: the push comes in step 2 \(from mid single support\); a walk of 1 step\(s\) never meets it"
run stability --reference "$TMP/ref" --out "$TMP/out_dir" --steps 1 --sweep push=-1:1:3 --no-plots --quiet
expect "swept push after the walk's end" 2 "--sweep: key 'push': the push comes in step 2"

# A walk whose rows would not fit in memory is refused before it is walked (2000 steps on the
# LCP ground died in bad_alloc after the whole computation).
run simulate --reference "$TMP/ref" --out "$TMP/out_dir" --ground lcp --steps 5000 --no-plots --quiet
expect "walk beyond the memory budget" 2 "--steps: 5000 steps of 0.7 s at 1000 rows per second keep about 5.25 GB"

# Options of the rigid ground's impacts on a ground with its own contact law: once recorded in
# summary.json and walked without.
run simulate --reference "$TMP/ref" --out "$TMP/out_dir" --ground lcp --restitution 0.3 --no-plots --quiet
expect "restitution off the rigid ground" 2 "--restitution: the lcp ground has its own contact law"
run stability --reference "$TMP/ref" --out "$TMP/out_dir" --ground impedance --poincare --sweep push=-1:1:3 --no-plots --quiet
expect "Poincare map off the rigid ground" 2 "--poincare: the Poincare map is computed on the rigid ground only, not on the impedance ground"

# A state whose rates would overflow the energies to inf (printed as null), and angles of 1e308.
echo '{"theta": [0, 0, 0, 3, 3], "dtheta": [1e308, 0, 0, 0, 0]}' >"$TMP/fast.json"
run inspect --robot "$ROBOT" --state "$TMP/fast.json"
expect "state rate 1e308" 2 "fast.json: key 'dtheta\[0\]': expected a number in \[-1000, 1000\] \[rad/s\], got 1e\+308"
echo '{"theta": [1e308, 1e308, 1e308, 1e308, 1e308]}' >"$TMP/turns.json"
run inspect --robot "$ROBOT" --state "$TMP/turns.json"
expect "state angle 1e308" 2 "turns.json: key 'theta\[0\]': expected a number in \[-12.5664, 12.5664\] \[rad\], got 1e\+308"

# compare on malformed gait folders: exit 2 and one line naming the file (no traceback, no
# second line from gaitopt).
if "$PY" -c "import matplotlib" 2>/dev/null; then
  for name in binary bad_json no_zmp; do cp -r "$TMP/ref" "$TMP/$name"; done
  head -c 4096 "$GAITOPT" >"$TMP/binary/trajectory.csv"
  echo '{"status": ' >"$TMP/bad_json/summary.json"
  sed -i '1s/,zmp_x,/,zmp_y,/' "$TMP/no_zmp/trajectory.csv"
  while IFS='|' read -r name pattern; do
    run compare "$TMP/ref" "$TMP/$name" --out "$TMP/out_dir"
    expect "compare $name" 2 "^error: $pattern"
    [[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "compare $name: not one line: $(cat "$TMP/err")"
  done <<'CASES'
binary|.*/binary/trajectory.csv: not UTF-8 text \(.*\): a binary file\?$
bad_json|.*/bad_json/summary.json: not valid JSON
no_zmp|.*/no_zmp/trajectory.csv: missing column 'zmp_x'$
CASES
fi

echo "bad input CLI: all checks passed"
