#!/usr/bin/env bash
# Issue 19 end to end: one case per failure listed under "Why". Output folders (never delete
# what is not ours, inputs, paths, locks, leftovers), no shell, checked writes on a full disk
# (a small tmpfs), resume under the same settings only, validated values, inputs that must
# match, no control bytes on the terminal. A case this machine cannot run (no root for the tmpfs
# or for nobody's process limit) is skipped visibly: see skipped() below.
# Usage: reliability_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
ROBOT="$ROOT/configs/robots/mu2004_five_link.yaml"
GAIT="$ROOT/configs/gaits/mu2004.yaml"
RABBIT="$ROOT/configs/robots/rabbit.yaml"
# KEEP_GOING=1 lists every failing case instead of stopping at the first (e.g. on an old binary).
fail() {
  echo "FAIL: $*" >&2
  FAILED=1
  [[ -n ${KEEP_GOING:-} ]] || exit 1
}
cd "$TMP" || exit 1
ln -s "$ROOT/configs" configs  # summary.json names its robot by configs/robots/NAME.yaml

# expect NAME CODE PATTERN: the last run exited CODE and its stderr matches PATTERN (ERE).
expect() {
  [[ $RC -eq $2 ]] || fail "$1: expected exit $2, got $RC: $(cat "$TMP/err")"
  grep -Eq -- "$3" "$TMP/err" || fail "$1: message does not match '$3': $(cat "$TMP/err")"
  echo "ok $1: $(head -n 1 "$TMP/err")"
}
# skipped REASON: a case that cannot run here; the script still runs the others and then ends
# with the skip code, so ctest counts it as skipped, not passed.
skipped() {
  echo "SKIP $*"
  SKIPPED+=$'\n  '"$*"
}
# same FILE SUM: FILE still has the checksum SUM (taken before the run).
same() { [[ $(md5sum <"$1") == "$2" ]] || fail "$1 changed"; }
sum() { md5sum <"$1"; }
poly() { run poly --robot "$ROBOT" --gait "$GAIT" --no-plots --rate "${RATE:-100}" "$@"; }
sim() { run simulate --steps 2 --no-poincare --no-plots --rate 50 --quiet "$@"; }
# A gait result to walk, and a copy of it for the cases that damage one.
poly --out "$TMP/gait"
[[ $RC -eq 0 ]] || fail "poly: $(cat "$TMP/err")"

# --- Data loss through --out ---------------------------------------------------------------
mkdir -p "$TMP/mine"
echo "my thesis" >"$TMP/mine/thesis.tex"
poly --out "$TMP/mine"
expect "out: a folder of foreign files is kept" 2 "holds files that gaitopt did not write"
[[ $(cat "$TMP/mine/thesis.tex") == "my thesis" ]] || fail "the user's file was lost"
echo "data" >"$TMP/plain"
poly --out "$TMP/plain"
expect "out: a regular file is kept" 2 "is a file, not a folder"
mkdir -p "$TMP/ocp"  # the config's ../robots and ../gaits resolve through the symlinks
ln -s "$ROOT/configs/robots" "$ROOT/configs/gaits" "$TMP/"
cp "$ROOT/configs/ocp/rabbit_kelly2017.yaml" "$TMP/ocp/rabbit.yaml"
s=$(sum "$TMP/ocp/rabbit.yaml")
run optimize --config "$TMP/ocp/rabbit.yaml" --out "$TMP/ocp/rabbit.yaml" --no-plots --quiet
expect "out: optimize --out its own --config" 2 "is, holds or is inside the input"
same "$TMP/ocp/rabbit.yaml" "$s"
s=$(sum "$TMP/gait/trajectory.csv")
sim --reference "$TMP/gait" --out "$TMP/gait/"
expect "out: simulate --out its --reference" 2 "is, holds or is inside the input"
mkdir -p "$TMP/lib"
echo '{}' >"$TMP/lib/library.json"
run interpolate --library "$TMP/lib" --speed 0.7 --step-length 0.5 --out "$TMP/lib" --no-plots
expect "out: interpolate --out its --library" 2 "is, holds or is inside the input"
[[ -f "$TMP/lib/library.json" ]] || fail "the library was deleted"
s2=$(sum "$TMP/gait/summary.json")
run stability --reference "$TMP/gait" --out "$TMP/gait" --sweep push=0:1:2 --steps 2 --no-plots \
  --quiet
expect "out: stability --out its --reference" 2 "is, holds or is inside the input"
same "$TMP/gait/summary.json" "$s2"
same "$TMP/gait/trajectory.csv" "$s"

# --- No shell ----------------------------------------------------------------------------------
evil="$TMP/x'\$(touch $TMP/PWNED)'y"
run poly --robot "$ROBOT" --gait "$GAIT" --rate 100 --out "$evil"
[[ $RC -eq 0 ]] || fail "poly into a quoted name: $(cat "$TMP/err")"
[[ ! -e "$TMP/PWNED" ]] || fail "shell injection: the command in --out ran"
[[ -f "$evil/trajectory.csv" ]] || fail "no result under the quoted name"
echo "ok no shell: --out with \$(touch PWNED) is only a name"

# --- Leftovers and paths -----------------------------------------------------------------------
dead=4194305  # above the kernel's pid_max: no live process has it
mkdir -p "$TMP/p.tmp-$dead" "$TMP/q.old-$dead"
cp -r "$TMP/gait/." "$TMP/q.old-$dead/"
poly --out "$TMP/p"
[[ $RC -eq 0 && ! -e "$TMP/p.tmp-$dead" ]] || fail "stale p.tmp-$dead not cleaned: $RC"
# A kill between the two renames left only q.old-PID: the next run (here one that then fails
# on a bad gait file) restores it as q.
run poly --robot "$ROBOT" --gait "$TMP/no-such-gait.yaml" --out "$TMP/q" --no-plots
[[ -f "$TMP/q/trajectory.csv" && ! -e "$TMP/q.old-$dead" ]] || fail "q.old-$dead not restored"
echo "ok leftovers: stale staging removed, orphaned previous result restored"
poly --out "$TMP/slash/"
[[ $RC -eq 0 && -f "$TMP/slash/trajectory.csv" ]] || fail "--out DIR/: $RC $(cat "$TMP/err")"
[[ -z $(find "$TMP/slash" -name '*.tmp-*') ]] || fail "--out DIR/ left a staging folder inside"
for bad in . "" / ./; do
  poly --out "$bad"
  expect "out: '$bad' refused" 2 "names no folder of its own"
done
[[ -z $(find "$TMP" -maxdepth 1 -name '.tmp-*') ]] || fail "a .tmp-PID folder was left in ."

# --- Resume that is right ----------------------------------------------------------------------
S="$TMP/sweep"
stab() { run stability --reference "${REF:-$TMP/gait}" --out "$S" --sweep push=0:1:2 --no-plots --quiet "$@"; }
stab --steps 2
[[ $RC -eq 0 ]] || fail "stability: $(cat "$TMP/err")"
stab --steps 3
expect "resume: other step count refused" 2 "steps_requested: folder 2, this run 3"
stab --steps 2 --controller sliding_mode
expect "resume: other controller refused" 2 'controller: folder "computed_torque", this run "sliding_mode"'
RATE=120 poly --out "$TMP/gait2"
REF="$TMP/gait2" stab --steps 2
expect "resume: other reference refused" 2 "reference_trajectory_fnv1a"
# A torn last line (a kill mid-write) is cut, not kept as a short row.
rows=$(wc -l <"$S/sweep_push.csv")
printf '0.5,2' >>"$S/sweep_push.csv"
stab --steps 2
[[ $RC -eq 0 && $(wc -l <"$S/sweep_push.csv") -eq $rows ]] || fail "torn line kept: $RC"
[[ $(tail -c 1 "$S/sweep_push.csv" | od -An -c | tr -d ' ') == '\n' ]] || fail "torn bytes left"
awk -F, 'NF != 9 { exit 1 }' "$S/sweep_push.csv" || fail "a short row in sweep_push.csv"
echo "ok resume: torn last line dropped"
# Two runs on one folder: the second is refused while the first holds the lock.
exec 9>"$S.lock"
flock -n 9 || fail "cannot take the lock for the test"
stab --steps 2
expect "lock: a second run on one folder refused" 2 "another gaitopt run .* is writing this folder"
exec 9>&-
rm -f "$S.lock"

# --- Bad values --------------------------------------------------------------------------------
run interpolate --library "$TMP/lib" --speed nan --step-length 0.5 --out "$TMP/i" --no-plots
expect "value: interpolate --speed nan" 2 "--speed: 'nan' is not a finite number"
RATE=nan poly --out "$TMP/v"
expect "value: poly --rate nan" 2 "--rate: 'nan' is not a finite number"
for opt in "--friction nan" "--push nan" "--push inf" "--gain-scale 1e999"; do
  # shellcheck disable=SC2086
  sim --reference "$TMP/gait" --out "$TMP/v" $opt
  expect "value: simulate $opt" 2 "${opt%% *}: .*(not a finite number|not in range)"
done
sed 's/mass: 5.28/mass: 1e308/' "$ROBOT" >"$TMP/heavy.yaml"
run poly --robot "$TMP/heavy.yaml" --gait "$GAIT" --no-plots --out "$TMP/v"
expect "value: mass 1e308" 2 "expected a number in \[0.001, 10000\] \[kg\]"
run impact-map --robot "$ROBOT" --approach-speed 1e308 --out "$TMP/v" --no-plots --quiet
expect "value: --approach-speed 1e308" 2 "--approach-speed: Value 1e308 not in range 0.001(0*) to 100"
run impact-map --robot "$ROBOT" --step-lengths 0.2:0.4:1000 --knee-bias 5:30:1000 --out "$TMP/v" \
  --no-plots --quiet
expect "value: impact map grid capped" 2 "a grid of 3.5e\+07 points needs about .* GB of memory"
printf 'name: huge\nocp: %s\ngrid:\n  speed: {from: 0.5, to: 1, count: 1000}\n  step_length: {from: 0.3, to: 0.6, count: 1000}\n  slope: {from: -0.1, to: 0.1, count: 1000}\n' \
  "$ROOT/configs/ocp/rabbit_kelly2017.yaml" >"$TMP/huge.yaml"
run library --config "$TMP/huge.yaml" --out "$TMP/v"
expect "value: library grid capped" 2 "a grid of 1e\+09 points needs about"
printf '{"theta": [0.1, -0.2, 0.3, 0.4, -0.1], "theta": [0, 0, 0, 0, 0]}' >"$TMP/dup.json"
run inspect --robot "$ROBOT" --state "$TMP/dup.json"
expect "value: duplicate JSON key" 2 "dup.json: key 'theta': the key appears twice"
run stability --reference "$TMP/gait" --out "$TMP/two" --sweep push=0:1:2 --steps 2 --jobs 64 \
  --no-plots --quiet
[[ $RC -eq 0 ]] && grep -q "with 2 job(s)" "$TMP/out" || fail "--jobs 64 not capped at 2 points"
echo "ok jobs: capped at the 2 points"
# A process limit that forbids threads: reported, not 'terminate called'. RLIMIT_NPROC binds
# only a non-root user, so the run drops to nobody. nobody cannot enter a checkout inside a 0700
# folder (/root, a mktemp -d), so the program, the libraries it loads from the build tree (ldd:
# libpardiso.so, which Ipopt's dlopen then finds loaded) and the robot file go to a folder of
# their own under /tmp, which every user can enter.
as_nobody() {
  LD_LIBRARY_PATH="$N/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    setpriv --reuid 65534 --regid 65534 --clear-groups "$@"
}
if command -v setpriv >/dev/null && [[ $(id -u) -eq 0 ]]; then
  N=$(mktemp -d /tmp/gaitopt-nobody.XXXXXX)
  trap 'rm -rf "$TMP" "$N"' EXIT
  mkdir "$N/lib" "$N/out"
  cp "$GAITOPT" "$ROBOT" "$N/"
  ldd "$GAITOPT" | awk '$2 == "=>" && $3 ~ /^\// && $3 !~ /^\/(usr\/)?lib/ {print $1, $3}' |
    while read -r name path; do cp "$path" "$N/lib/$name"; done
  chmod -R a+rX "$N"
  chown 65534:65534 "$N/out"
  if as_nobody "$N/gaitopt" --help >/dev/null 2>"$TMP/err"; then
    (ulimit -u 1; as_nobody "$N/gaitopt" impact-map --robot "$N/$(basename "$ROBOT")" --jobs 8 \
      --out "$N/out/map" --no-plots --quiet) >"$TMP/out" 2>"$TMP/err"
    RC=$?
    expect "threads: creation failure reported" 1 "cannot start worker thread"
    grep -q terminate "$TMP/err" && fail "terminate called"
  else
    skipped "threads: nobody cannot run the copied program: $(head -n 1 "$TMP/err")"
  fi
  rm -rf "$N"
else
  skipped "threads: needs root and setpriv"
fi

# --- Inputs that must match, messages, control bytes ---------------------------------------------
mkdir -p "$TMP/one"
cp "$TMP/gait/summary.json" "$TMP/one/"
head -n 2 "$TMP/gait/trajectory.csv" >"$TMP/one/trajectory.csv"
sim --reference "$TMP/one" --out "$TMP/v"
expect "match: one-row trajectory" 2 "1 row\(s\) on the grid, but t_i = i / 100 Hz .* makes [0-9]+: a truncated"
cp -r "$TMP/gait" "$TMP/gait.failed"
echo "failed" >"$TMP/gait.failed/FAILED.txt"
sim --reference "$TMP/gait.failed" --out "$TMP/v"
expect "match: a .failed reference" 2 "holds a failed solve"
sim --reference "$TMP/gait" --robot "$RABBIT" --out "$TMP/v"
expect "match: a gait of another robot" 2 "the gait is of robot 'mu2004_five_link', not of robot '.+'"
run poly --robot "$RABBIT" --gait "$ROOT/configs/gaits/rabbit_kelly2017.yaml" --out "$TMP/rg" \
  --no-plots --rate 100
if [[ $RC -eq 0 ]]; then
  sim --reference "$TMP/rg" --controller sliding_mode --out "$TMP/v"
  expect "match: RABBIT with sliding_mode" 2 "the sliding_mode controller .* needs an actuated stance ankle.*--controller hzd"
  grep -qi "computed.torque" "$TMP/err" && fail "the sliding_mode message talks about computed torque"
  # HZD is the controller for the passive ankle: the same check lets it through.
  sim --reference "$TMP/rg" --controller hzd --out "$TMP/v"
  grep -q "needs an actuated stance ankle" "$TMP/err" && fail "hzd refused for RABBIT: $(cat "$TMP/err")"
else
  skipped "RABBIT controller case: no RABBIT polynomial gait ($(head -n 1 "$TMP/err"))"
fi
mkdir -p "$TMP/ctl"
cp "$TMP/gait/summary.json" "$TMP/ctl/"
{ printf 't\033]0;PWNED\007,x\n'; tail -n +2 "$TMP/gait/trajectory.csv"; } >"$TMP/ctl/trajectory.csv"
sim --reference "$TMP/ctl" --out "$TMP/v"
[[ $RC -eq 2 ]] || fail "control bytes: expected exit 2, got $RC"
LC_ALL=C grep -q $'[\x01-\x08\x0b-\x1f\x7f]' "$TMP/err" && fail "control bytes echoed: $(od -c "$TMP/err" | head)"
echo "ok terminal: no control bytes from a CSV header"

# --- A full disk ---------------------------------------------------------------------------------
F="$TMP/full"
mkdir -p "$F"
if mount -t tmpfs -o size=4m tmpfs "$F" 2>/dev/null; then
  trap 'umount "$F" 2>/dev/null; rm -rf "$TMP"' EXIT
  sim --reference "$TMP/gait" --out "$F/walk"
  [[ $RC -eq 0 ]] || fail "simulate on the tmpfs: $(cat "$TMP/err")"
  s=$(sum "$F/walk/walk.csv")
  run stability --reference "$TMP/gait" --out "$F/sweep" --sweep push=0:1:2 --steps 2 --no-plots \
    --quiet
  dd if=/dev/zero of="$F/fill" bs=64k 2>/dev/null
  sim --reference "$TMP/gait" --out "$F/walk"
  expect "disk: simulate on a full disk" 1 "No space left on device"
  same "$F/walk/walk.csv" "$s"
  [[ -z $(find "$F" -maxdepth 1 -name 'walk.*-*') ]] || fail "staging left on the full disk"
  run stability --reference "$TMP/gait" --out "$F/sweep" --sweep push=0:1:2 --steps 2 --no-plots \
    --quiet
  expect "disk: stability on a full disk" 1 "No space left on device"
  run library --config "$ROOT/configs/library/mu2004_speed_step.yaml" --out "$F/lib" --jobs 1 --quiet
  expect "disk: library on a full disk" 1 "No space left on device"
  umount "$F"
else
  skipped "full disk: cannot mount a tmpfs here (not root?)"
fi
[[ -z ${FAILED:-} ]] || exit 1
if [[ -n ${SKIPPED:-} ]]; then
  printf 'every case that ran passed; skipped:%s\n' "$SKIPPED"
  exit "$SKIP_CODE"
fi
echo "all reliability cases passed"
