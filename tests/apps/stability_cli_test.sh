#!/usr/bin/env bash
# End-to-end checks of `gaitopt stability`: a friction sweep finds the slip boundary of the
# polynomial gait, the rows do not depend on the number of jobs, an interrupted sweep resumes
# without redoing finished points, a 2-D map is written, summarised and resumed, and bad maps
# are refused.
# Usage: stability_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
# The polynomial gait walks a robot with a heel long enough for its ankle torque.
LONG_HEEL="$ROOT/tests/apps/mu2004_five_link_long_heel.yaml"
cd "$ROOT" || fail "no repo root $ROOT"
# The reference: the polynomial gait, made here (results/ keeps no trajectory CSVs).
run poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004.yaml \
  --out "$TMP/poly" --no-plots
[[ $RC -eq 0 ]] || fail "poly exited $RC: $(cat "$TMP/err")"
ARGS=(--robot "$LONG_HEEL" --reference "$TMP/poly" --steps 2 --no-plots --quiet)

# (a) friction 0.2 .. 0.5: the gait's friction ratio peaks at 0.31; at 0.3 its stance tip slides
# a little (less than --max-slip, 1 cm) and the walk goes on, at 0.2 it slides further and fails.
run stability "${ARGS[@]}" --sweep friction=0.2:0.5:4 --jobs 2 --out "$TMP/a"
[[ $RC -eq 0 ]] || fail "(a) stability exited $RC: $(cat "$TMP/err")"
# The nominal, the robot's 0.6, is walked too: the interval grows from it, not from 0.5.
[[ $(wc -l <"$TMP/a/sweep_friction.csv") -eq 6 ]] || fail "(a) rows: $(cat "$TMP/a/sweep_friction.csv")"
check_json "(a) summary" "$TMP/a/summary.json" <<'PY'
s = d["sweeps"]["friction"]
assert s["nominal"] == 0.6 and s["values"] == 5, s
assert s["walks_from"] == 0.3 and s["walks_to"] == 0.6, s
assert s["fails_below"]["value"] == 0.2 and "slip" in s["fails_below"]["failure"], s
PY
grep -q "friction: walks from 0.3 to 0.6" "$TMP/out" || fail "(a) stdout: $(cat "$TMP/out")"
grep -qx "stability: wrote $TMP/a/summary.json, sweep_friction.csv" "$TMP/out" ||
  fail "(a) the last line does not list the files written: $(tail -n 1 "$TMP/out")"

# (b) one job gives the same rows (up to order and wall time).
run stability "${ARGS[@]}" --sweep friction=0.2:0.5:4 --jobs 1 --out "$TMP/b"
[[ $RC -eq 0 ]] || fail "(b) stability exited $RC"
strip() { cut -d, -f1-8 "$1" | sort; }
[[ "$(strip "$TMP/a/sweep_friction.csv")" == "$(strip "$TMP/b/sweep_friction.csv")" ]] ||
  fail "(b) --jobs 1 and 2 differ"

# (c) resume: drop one finished row and tear the last line, as a kill would; the rerun walks only
# the missing point and keeps the others.
head -n 3 "$TMP/a/sweep_friction.csv" >"$TMP/c.csv"
printf '0.5,2,2,0,"",0.0013' >>"$TMP/c.csv"
mkdir -p "$TMP/c" && mv "$TMP/c.csv" "$TMP/c/sweep_friction.csv"
cp "$TMP/a/.gaitopt-result" "$TMP/a/settings.json" "$TMP/c/"  # a killed run leaves them too
run stability "${ARGS[@]}" --sweep friction=0.2:0.5:4 --out "$TMP/c"
[[ $RC -eq 0 ]] || fail "(c) stability exited $RC: $(cat "$TMP/err")"
grep -q "3 points to walk (2 done before)" "$TMP/out" || fail "(c) no resume: $(cat "$TMP/out")"
check_json "(c) summary" "$TMP/c/summary.json" <<'PY'
assert d["sweeps"]["friction"]["values"] == 5 and d["sweeps"]["friction"]["walks_from"] == 0.3, d
PY
# A second rerun has nothing left to do.
run stability "${ARGS[@]}" --sweep friction=0.2:0.5:4 --out "$TMP/c"
grep -q "0 points to walk (5 done before)" "$TMP/out" || fail "(c) rerun: $(cat "$TMP/out")"

# (c2) rows edited by hand are walked again, not believed: a NaN error, a "fell" that its count
# contradicts; and a row for a value off the grid counts in no summary.
mkdir -p "$TMP/c2" && cp "$TMP/c/.gaitopt-result" "$TMP/c/settings.json" "$TMP/c2/"
"$PY" - "$TMP/c/sweep_friction.csv" "$TMP/c2/sweep_friction.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
h = rows[0]
walked = [r for r in rows[1:] if r[h.index("fell")] == "0"]
walked[0][h.index("max_tracking_error")] = "nan"
walked[1][h.index("fell")] = "1"
extra = list(walked[2]); extra[0] = "0.9"
csv.writer(open(sys.argv[2], "w", newline=""), lineterminator="\n").writerows(rows + [extra])
PY
run stability "${ARGS[@]}" --sweep friction=0.2:0.5:4 --out "$TMP/c2"
[[ $RC -eq 0 ]] || fail "(c2) stability exited $RC: $(cat "$TMP/err")"
grep -q "2 points to walk (3 done before)" "$TMP/out" || fail "(c2) edited rows kept: $(cat "$TMP/out")"
check_json "(c2) summary" "$TMP/c2/summary.json" <<'PY'
assert d["sweeps"]["friction"]["values"] == 5 and d["sweeps"]["friction"]["walks_from"] == 0.3, d
PY

# (d) a run killed mid-sweep keeps its finished rows and a rerun completes the sweep.
timeout -s KILL 2 "$GAITOPT" stability "${ARGS[@]}" --sweep gain_scale=0.5:2:8 --jobs 1 \
  --out "$TMP/d" >/dev/null 2>&1
run stability "${ARGS[@]}" --sweep gain_scale=0.5:2:8 --out "$TMP/d"
[[ $RC -eq 0 ]] || fail "(d) rerun exited $RC: $(cat "$TMP/err")"
check_json "(d) summary" "$TMP/d/summary.json" <<'PY'
assert d["sweeps"]["gain_scale"]["values"] == 9, d  # 8 and the nominal 1, between them
PY

# (d2) --set replaces a value of the robot file: the sweep's nominal is the friction set.
run stability "${ARGS[@]}" --sweep friction=0.3:0.5:2 --set robot.friction=0.45 --out "$TMP/d2"
[[ $RC -eq 0 ]] || fail "(d2) stability exited $RC: $(cat "$TMP/err")"
check_json "(d2) summary" "$TMP/d2/summary.json" <<'PY'
assert d["sweeps"]["friction"]["nominal"] == 0.45, d["sweeps"]["friction"]
assert d["config_overrides"] == ["robot.friction=0.45"], d.get("config_overrides")
PY

# (d3) the nominal of a sweep is the scenario's own value: --push 1 adds 1 to push=-0.5:0.5:3 and
# the interval grows from it; --help says so.
# Every option that shapes the rows is in summary.json, --friction too.
run stability "${ARGS[@]}" --push 1 --friction 0.5 --sweep push=-0.5:0.5:3 --out "$TMP/d3"
[[ $RC -eq 0 ]] || fail "(d3) stability exited $RC: $(cat "$TMP/err")"
check_json "(d3) summary" "$TMP/d3/summary.json" <<'PY'
s = d["sweeps"]["push"]
assert s["nominal"] == 1 and s["values"] == 4, s
assert d["friction"] == 0.5 and d["push_impulse_Ns"] == 1 and d["poincare"] is False, d
assert d["robot_file"].endswith("mu2004_five_link_long_heel.yaml") and d["slope_rad"] == 0, d
assert d["foot"]["heel"] > 0.05 and d["ground"] == "rigid" and d["gain_scale"] == 1, d
PY
check_json "(d3) the robot's friction" "$TMP/a/summary.json" <<'PY'
assert d["friction"] == 0.6, d.get("friction")
PY
"$GAITOPT" stability --help | tr -s ' \n' ' ' | grep -q "The nominal value, always walked and the centre of the walking interval, is the scenario's own: --push, --mass-error" ||
  fail "(d3) --help does not say what the nominal value is"

# (e) bad input: unknown parameter, malformed range, stiffness off the impedance ground.
run stability "${ARGS[@]}" --sweep wind --out "$TMP/e"
[[ $RC -eq 2 ]] && grep -q "unknown sweep parameter 'wind'" "$TMP/err" || fail "(e) $(cat "$TMP/err")"
run stability "${ARGS[@]}" --sweep push=-1:1:3 --max-slip 0 --out "$TMP/e"
[[ $RC -eq 2 ]] && grep -q -- "--max-slip: expected a number in (0, 1\] \[m\], got 0" "$TMP/err" ||
  fail "(e) --max-slip 0: $(cat "$TMP/err")"
run stability "${ARGS[@]}" --sweep friction=0.1:x:3 --out "$TMP/e"
[[ $RC -eq 2 ]] && grep -q "not a finite number" "$TMP/err" || fail "(e) range: $(cat "$TMP/err")"
run stability "${ARGS[@]}" --sweep stiffness=1e5:1e6:2 --out "$TMP/e"
[[ $RC -eq 2 ]] && grep -q "^error: --sweep: key 'stiffness': stiffness is swept on a compliant ground only (--ground impedance or --ground pad), not on the rigid ground" "$TMP/err" ||
  fail "(e) stiffness: $(cat "$TMP/err")"
# (e') both compliant grounds have a stiffness: the pad's is swept too, and the words say so.
run stability "${ARGS[@]}" --ground pad --sweep stiffness=1e5:1e6:2 --out "$TMP/e_pad"
[[ $RC -eq 0 ]] || fail "(e') stiffness on the pad exited $RC: $(cat "$TMP/err")"
check_json "(e') summary" "$TMP/e_pad/summary.json" <<'PY'
s = d["sweeps"]["stiffness"]
assert s["nominal"] == 3e5 and "impedance or pad" in s["meaning"], s
PY
"$GAITOPT" stability --help | grep -q "stiffness \[N/m^n\]: contact stiffness k of a compliant ground, damping scaled alike (impedance or pad" ||
  fail "(e') --help: $("$GAITOPT" stability --help | grep stiffness)"
# (e2) a range that does not run upwards is refused by one rule for --sweep and --map, exit 2
# naming the option and the parameter, before a folder is made: a == b with n > 1 (one point n
# times), a > b, n = 1 with a != b (b dropped).
for range in 0.5:0.5:3 1:-1:3 -1:1:1; do
  run stability "${ARGS[@]}" --sweep push=$range --out "$TMP/e2"
  [[ $RC -eq 2 ]] && grep -q "^error: --sweep: key 'push': '$range': " "$TMP/err" ||
    fail "(e2) --sweep push=$range exited $RC: $(cat "$TMP/err")"
  [[ ! -e "$TMP/e2" ]] || fail "(e2) --sweep push=$range made a folder"
done
run stability "${ARGS[@]}" --map push=1:-1:3,friction=0.2:0.6:3 --out "$TMP/e2"
[[ $RC -eq 2 ]] && grep -q "^error: --map: key 'push': '1:-1:3': 3 values need a < b" "$TMP/err" ||
  fail "(e2) --map push=1:-1:3 exited $RC: $(cat "$TMP/err")"
# (e3) an --out where no folder can be made (/proc takes no new entries, even from root): exit 2
# naming --out, not exit 1 naming OUT.lock, a file the user never gave.
if [[ -d /proc/self ]]; then
  run stability "${ARGS[@]}" --sweep push=-1:1:3 --out /proc/gaitopt_stability_test
  [[ $RC -eq 2 ]] && grep -q "^error: --out: '/proc/gaitopt_stability_test' cannot be created: " \
    "$TMP/err" && ! grep -q "\.lock" "$TMP/err" || fail "(e3) exited $RC: $(cat "$TMP/err")"
fi
# (f) a 2-D map: 3 x 3 points in map_push_friction.csv keyed by both values, the walking region
# in summary.json (friction 0.2 slips, as in (a)); a rerun walks nothing; the picture is drawn.
run stability "${ARGS[@]}" --map push=-0.5:0.5:3,friction=0.2:0.6:3 --out "$TMP/f"
[[ $RC -eq 0 ]] || fail "(f) stability exited $RC: $(cat "$TMP/err")"
[[ $(wc -l <"$TMP/f/map_push_friction.csv") -eq 10 ]] || fail "(f) rows: $(cat "$TMP/f/map_push_friction.csv")"
head -n 1 "$TMP/f/map_push_friction.csv" | grep -q '^push,friction,steps_completed,' ||
  fail "(f) header: $(head -n 1 "$TMP/f/map_push_friction.csv")"
check_json "(f) summary" "$TMP/f/summary.json" <<'PY'
m = d["maps"]["push_friction"]
assert m["points"] == 9 and m["a"]["name"] == "push" and m["b"]["nominal"] == 0.6, m
assert [r["push"] for r in m["per_row"]] == [-0.5, 0, 0.5], m
for r in m["per_row"]:
    assert r["walks_to"] in (None, 0.6) and r["walks_from"] != 0.2, r
assert 0 <= m["points_walked"] <= 6, m
PY
grep -q "map push_friction: .* of 9 points walk" "$TMP/out" || fail "(f) stdout: $(cat "$TMP/out")"
run stability "${ARGS[@]}" --map push=-0.5:0.5:3,friction=0.2:0.6:3 --out "$TMP/f"
grep -q "0 points to walk (9 done before)" "$TMP/out" || fail "(f) rerun: $(cat "$TMP/out")"
run stability --robot "$LONG_HEEL" --reference "$TMP/poly" --steps 2 --quiet \
  --map push=-0.5:0.5:3,friction=0.2:0.6:3 --out "$TMP/f"
[[ $RC -eq 0 && -s "$TMP/f/map_push_friction.png" ]] || fail "(f) picture: $(cat "$TMP/err")"

# (g) bad maps: one parameter, the same one twice, fewer than 2 values, an unknown name, nothing.
for bad in "push=-1:1:3" "push=-1:1:3,push=0:1:2" "push=-1:1:1,friction=0.2:0.6:3" \
  "push,wind=0:1:2"; do
  run stability "${ARGS[@]}" --map "$bad" --out "$TMP/g"
  [[ $RC -eq 2 ]] || fail "(g) --map $bad exited $RC"
done
run stability "${ARGS[@]}" --map "push=-1:1:3,push=0:1:2" --out "$TMP/g"
grep -q "the same parameter twice" "$TMP/err" || fail "(g) twice: $(cat "$TMP/err")"
run stability "${ARGS[@]}" --map "push=-1:1:1,friction=0.2:0.6:3" --out "$TMP/g"
grep -q "at least 2 values" "$TMP/err" || fail "(g) n < 2: $(cat "$TMP/err")"
run stability "${ARGS[@]}" --map "push=-1:1:3" --out "$TMP/g"
grep -q "expected two parameters" "$TMP/err" || fail "(g) one: $(cat "$TMP/err")"
run stability "${ARGS[@]}" --out "$TMP/g"
[[ $RC -eq 2 ]] && grep -q "give --sweep or --map" "$TMP/err" || fail "(g) none: $(cat "$TMP/err")"
# (i) a controller the gait does not fit (HZD needs an instantaneous double support): exit 2
# before anything is walked or written, as simulate refuses it, so a corrected rerun may use the
# same folder.
run stability "${ARGS[@]}" --controller hzd --sweep push=-1:1:3 --out "$TMP/hzd"
[[ $RC -eq 2 ]] && grep -q "^error: --controller hzd: .*needs a gait with an instantaneous double" \
  "$TMP/err" || fail "(i) exited $RC: $(cat "$TMP/err")"
[[ ! -e "$TMP/hzd" ]] || fail "(i) a folder was made for a refused controller"
echo "stability CLI: all checks passed"
