#!/usr/bin/env bash
# Issue 39, the hostile user: one table row per way a run could lose a user's data or write
# through a planted link. Each case runs in a folder of its own and says what it proves; a
# user's file ("victim") must come out of every case byte for byte as it went in.
# Resumes keyed by content are proved option by option in resume_key_cli_test.sh.
# Usage: adversarial_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
ROBOT="$ROOT/configs/robots/rabbit.yaml" # the optimisation cases: RABBIT solves fast
GAIT="$ROOT/configs/gaits/rabbit_kelly2017.yaml"
FIVE="$ROOT/configs/robots/mu2004_five_link.yaml" # the closed-loop cases: computed torque
FIVE_GAIT="$ROOT/configs/gaits/mu2004.yaml"
DEAD=4194305 # above the kernel's pid_max: no live process has it
export GAITOPT_SCRIPTS="$TMP/no_scripts" # no pictures: python would take longer than the runs
cd "$TMP" || exit 1
ln -s "$ROOT/configs" configs # summary.json names its robot by configs/robots/NAME.yaml

# A case prints "why" and returns non-zero on failure.
bad() {
  echo "  $*" >&2
  return 1
}
# code N: the last run exited N.
code() { [[ $RC -eq $1 ]] || bad "expected exit $1, got $RC: $(head -c 400 "$TMP/err")"; }
# says PATTERN: the last run's stderr matches PATTERN (ERE).
says() { grep -Eq -- "$1" "$TMP/err" || bad "message does not match '$1': $(head -c 400 "$TMP/err")"; }
# victim NAME: a user's file with known bytes; intact NAME: it still has them.
victim() { printf 'user data %s\n' "$1" >"$1"; }
intact() { [[ -f $1 && $(cat "$1") == "user data $1" ]] || bad "the user's file $1 was changed or lost"; }
poly() { run poly --robot "$FIVE" --gait "$FIVE_GAIT" --no-plots --rate 100 "$@"; }
sweep() { run stability --steps 2 --no-plots --quiet "$@"; }
# The RABBIT problem at 8 segments (about 0.1 s a solve) with its files named in `dir`.
ocp8() { # ocp8 FILE ROBOT GAIT
  sed "s|segments: 25|segments: 8|; s|^robot: .*|robot: $2|; s|^initial_guess: .*|initial_guess: $3|" \
    "$ROOT/configs/ocp/rabbit_kelly2017.yaml" >"$1"
}
poly --out gait # the reference of the closed-loop cases
[[ $RC -eq 0 ]] || fail "poly: $(cat "$TMP/err")"

# --- Paths named inside a config ---------------------------------------------------------------
case_config_inputs() {
  poly --out prev && code 0 || return 1
  cp "$ROBOT" prev/robot.yaml && cp "$GAIT" prev/gait.yaml
  ocp8 walk.yaml "$PWD/prev/robot.yaml" "$PWD/prev/gait.yaml"
  local r g
  r=$(md5sum <prev/robot.yaml) g=$(md5sum <prev/gait.yaml)
  run optimize --config walk.yaml --out prev --no-plots --quiet
  code 2 && says "'prev' is, holds or is inside the input '.*prev/(robot|gait).yaml'" || return 1
  [[ $(md5sum <prev/robot.yaml) == "$r" && $(md5sum <prev/gait.yaml) == "$g" ]] ||
    bad "the config's robot or gait file in prev was lost"
}
case_library_config_inputs() {
  mkdir lib && poly --out lib/held && code 0 || return 1
  cp "$ROBOT" lib/held/robot.yaml
  ocp8 base.yaml "$PWD/lib/held/robot.yaml" "$GAIT"
  printf 'name: l\nocp: base.yaml\ngrid:\n  speed: [0.7]\n' >lib.yaml
  run library --config lib.yaml --out lib/held --quiet
  code 2 && says "is, holds or is inside the input .*robot.yaml" && [[ -f lib/held/robot.yaml ]] ||
    bad "the library's robot file was lost"
}
case_out_inside_reference() {
  run simulate --reference gait --out gait/walk --steps 2 --no-plots --quiet
  code 2 && says "is inside the input 'gait'" && [[ ! -e gait/walk ]] || bad "wrote into the reference"
}
case_resumable_run_onto_another_result() {
  poly --out res && code 0 || return 1
  local before
  before=$(md5sum res/trajectory.csv res/summary.json)
  sweep --reference gait --sweep push=0:1:2 --out res
  code 2 && says "holds another gaitopt result \(it has no settings.json\)" || return 1
  [[ $(md5sum res/trajectory.csv res/summary.json) == "$before" && ! -e res/settings.json ]] ||
    bad "the stability run wrote into the gait result"
}
case_out_inside_another_result() {
  poly --out res && code 0 || return 1
  poly --out res/inner
  code 2 && says "lies inside the gaitopt result" && [[ ! -e res/inner ]] ||
    bad "a result was written where the next run on res would delete it"
}

# --- Files gaitopt creates: never through a link, never a user's file ---------------------------
case_lock_is_a_link() {
  victim notes && ln -s "$PWD/notes" res.lock
  poly --out res
  code 2 && says "res.lock is a symbolic link" && intact notes && [[ -L res.lock ]] ||
    bad "the planted link was followed or removed"
}
case_lock_is_a_users_file() {
  victim res.lock
  poly --out res
  code 2 && says "res.lock does not start with the line 'gaitopt folder lock'" && intact res.lock
}
case_lock_left_by_a_killed_run() {
  printf 'gaitopt folder lock\n%s\n' "$DEAD" >res.lock
  poly --out res
  code 0 && [[ ! -e res.lock && -f res/trajectory.csv ]] || bad "a stale lock of gaitopt's blocked"
}
case_report_temporary_is_a_link() {
  poly --out page && code 0 || return 1
  victim notes && ln -s "$PWD/notes" page/report.html.tmp
  run report page --no-gif
  code 0 && intact notes && [[ -L page/report.html.tmp && -s page/report.html ]] ||
    bad "report wrote through its planted temporary"
}
case_report_page_is_a_link() {
  poly --out page && code 0 || return 1
  victim notes && ln -s "$PWD/notes" page/report.html
  run report page --no-gif
  code 0 && intact notes && [[ ! -L page/report.html && -s page/report.html ]] ||
    bad "report wrote through a link at report.html"
}
case_staging_names_not_ours() {
  mkdir "res.tmp-$DEAD" && victim "res.tmp-$DEAD/thesis"
  ln -s "$PWD/users" "res.old-$DEAD" && mkdir users && victim users/paper
  poly --out res
  code 0 && intact "res.tmp-$DEAD/thesis" && intact users/paper && [[ -L res.old-$DEAD ]] ||
    bad "a dead pid's name on a user's folder or link was taken for gaitopt's leftover"
  grep -q "mu2004_five_link" res/summary.json || bad "res is not the new result (an .old- link restored?)"
}
case_staging_of_a_killed_run() {
  mkdir "res.tmp-$DEAD" && touch "res.tmp-$DEAD/.gaitopt-result" "res.tmp-$DEAD/trajectory.csv"
  poly --out res
  code 0 && [[ ! -e res.tmp-$DEAD ]] || bad "gaitopt's own staging of a dead run was left"
}
# Every file a stability run writes into its folder, each in turn a link to a user's file.
case_sweep_files_are_links() {
  local f
  for f in settings.json summary.json sweep_push.csv; do
    rm -rf s && sweep --reference gait --sweep push=0:1:2 --out s && code 0 || return 1
    rm s/"$f" && victim "notes_$f" && ln -s "$PWD/notes_$f" s/"$f"
    sweep --reference gait --sweep push=0:1:2 --out s
    intact "notes_$f" || return 1
    [[ $RC -ne 0 ]] || [[ ! -L s/$f ]] || bad "$f: exit 0 and the link still in place"
  done
}

# Every file of a library folder, each in turn a link to a user's file.
case_library_files_are_links() {
  ocp8 base.yaml "$ROBOT" "$GAIT"
  printf 'name: l\nocp: base.yaml\ngrid:\n  speed: [0.7]\n' >lib.yaml
  local f
  for f in library.json index.csv index.json; do
    rm -rf l && run library --config lib.yaml --out l --quiet && code 0 || return 1
    rm l/"$f" && victim "notes_$f" && ln -s "$PWD/notes_$f" l/"$f"
    run library --config lib.yaml --out l --quiet
    intact "notes_$f" || return 1
    [[ $RC -ne 0 ]] || [[ ! -L l/$f ]] || bad "$f: exit 0 and the link still in place"
  done
}
# The sources: every open(2) that creates a file refuses links (O_NOFOLLOW), no stream writes a
# file, and every plot script writes through plot_style.replacing (mkstemp + rename).
case_every_writer_in_the_sources() {
  local src=(apps io gaits ocp sim library report parallel dynamics config python)
  local found
  found=$(cd "$ROOT" && grep -rn --include='*.cpp' --include='*.hpp' -E '::open\(' "${src[@]}" |
    grep 'O_CREAT' | grep -v O_NOFOLLOW)
  [[ -z $found ]] || bad "open(2) creating a file without O_NOFOLLOW: $found"
  found=$(cd "$ROOT" && grep -rn --include='*.cpp' --include='*.hpp' -E 'std::ofstream|fopen\(' "${src[@]}")
  [[ -z $found ]] || bad "a stream writer outside io/output/checked_write: $found"
  found=$(cd "$ROOT" && grep -rn -E "open\(.*['\"][wa]b?['\"]" plots/*.py | grep -v 'replacing(')
  [[ -z $found ]] || bad "a plot script writes a file in place: $found"
}

# --- Kill and resume, two runs at once -----------------------------------------------------------
# A sweep killed (SIGKILL) while it writes rows, then resumed: every point once, no torn row.
case_kill_and_resume() {
  "$GAITOPT" stability --reference gait --sweep push=0:2:60 --steps 2 --jobs 1 --no-plots \
    --quiet --out k >/dev/null 2>&1 &
  local pid=$! n=0
  while [[ $n -lt 5 ]] && kill -0 "$pid" 2>/dev/null; do
    sleep 0.02
    n=$(($(wc -l <k/sweep_push.csv 2>/dev/null || echo 1) - 1))
  done
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  [[ $n -lt 60 ]] || bad "the sweep finished before it could be killed"
  sweep --reference gait --sweep push=0:2:60 --jobs 2 --out k
  code 0 || return 1
  [[ $(tail -n +2 k/sweep_push.csv | cut -d, -f1 | sort -u | wc -l) -eq 60 &&
    $(wc -l <k/sweep_push.csv) -eq 61 ]] || bad "rows after the resume: $(wc -l <k/sweep_push.csv)"
  awk -F, 'NR > 1 && NF != 9 { exit 1 }' k/sweep_push.csv || bad "a torn row is left"
}
# Two runs on one folder at once: the second is refused (exit 2) and the first finishes.
case_two_runs_at_once() {
  "$GAITOPT" stability --reference gait --sweep push=0:2:60 --steps 2 --jobs 1 --no-plots \
    --quiet --out c >/dev/null 2>&1 &
  local pid=$! n=0
  while [[ ! -e c.lock && $n -lt 500 ]]; do
    sleep 0.01
    n=$((n + 1))
  done
  sweep --reference gait --sweep push=0:2:60 --out c
  local second=$RC
  wait "$pid"
  local first=$?
  RC=$second && code 2 && says "another gaitopt run \(pid $pid\) is writing this folder" || return 1
  [[ $first -eq 0 && $(wc -l <c/sweep_push.csv) -eq 61 ]] || bad "the first run: exit $first"
}

# --- Every writer reports its failure ----------------------------------------------------------
# A library point whose folder does not fit on the disk: a failed point (converged=0, status
# error) and a failed run (exit 1), never "solved". Needs root for the small tmpfs.
case_library_on_a_nearly_full_disk() {
  if ! { mkdir disk && mount -t tmpfs -o size=96k tmpfs disk 2>/dev/null; }; then
    echo "  (cannot mount a tmpfs here: not root?)"
    return 77
  fi
  ocp8 base.yaml "$ROBOT" "$GAIT"
  printf 'name: l\nocp: %s\ngrid:\n  speed: [0.7]\n' "$PWD/base.yaml" >lib.yaml
  run library --config lib.yaml --out disk/lib --rate 4000 --jobs 1 --quiet
  local rows
  rows=$(cat disk/lib/index.csv 2>/dev/null)
  umount disk
  code 1 && says "No space left on device" || return 1
  grep -q ",error,0," <<<"$rows" || bad "no failed row in index.csv: $rows"
  ! grep -q ",1," <<<"$(tail -n +2 <<<"$rows")" || bad "a row says converged: $rows"
}

# A user replaces a result that holds another user's files (made by root): the new result is in
# place and the run succeeds; the old one it cannot remove is left with a warning naming it.
case_replacing_a_result_with_another_users_files() {
  local shared
  shared=$(mktemp -d /tmp/gaitopt-shared.XXXXXX) && chmod 777 "$shared" || return 1
  if [[ $(id -u) -ne 0 ]] || ! runuser -u nobody -- test -x "$GAITOPT" -a -r "$FIVE"; then
    rm -rf "$shared" && echo "  (needs root, and a build and configs that nobody can read)" && return 77
  fi
  "$GAITOPT" poly --robot "$FIVE" --gait "$FIVE_GAIT" --no-plots --rate 100 --out "$shared/prev" \
    >/dev/null 2>&1 || return 1
  runuser -u nobody -- "$GAITOPT" poly --robot "$FIVE" --gait "$FIVE_GAIT" --no-plots --rate 50 \
    --out "$shared/prev" >"$TMP/out" 2>"$TMP/err"
  RC=$?
  local rate left
  rate=$(grep -o '"sample_rate_hz": [0-9.]*' "$shared/prev/summary.json")
  left=$(ls -d "$shared"/prev.old-* 2>/dev/null)
  rm -rf "$shared"
  code 0 && says "warning: .*prev.old-[0-9]+: the replaced result could not be removed" || return 1
  [[ $rate == '"sample_rate_hz": 50.0' && -n $left ]] || bad "new result $rate, leftover '$left'"
}

CASES=(
  "paths: optimize --out a result folder holding the config's robot and gait|config_inputs"
  "paths: library --out a folder holding its OCP's robot|library_config_inputs"
  "paths: simulate --out inside its --reference|out_inside_reference"
  "paths: stability --out a gait result (rows would mix into it)|resumable_run_onto_another_result"
  "paths: --out inside another result, which its next run replaces|out_inside_another_result"
  "links: OUT.lock a symbolic link to a user's file|lock_is_a_link"
  "links: OUT.lock a user's own file|lock_is_a_users_file"
  "links: OUT.lock of a killed gaitopt run is taken|lock_left_by_a_killed_run"
  "links: report.html.tmp planted as a link|report_temporary_is_a_link"
  "links: report.html a link to a user's file|report_page_is_a_link"
  "links: OUT.tmp-PID / OUT.old-PID of a dead pid that gaitopt did not make|staging_names_not_ours"
  "links: OUT.tmp-PID that gaitopt made, of a dead pid, is removed|staging_of_a_killed_run"
  "links: every file of a stability folder a link|sweep_files_are_links"
  "links: every file of a library folder a link|library_files_are_links"
  "links: every writer in the sources refuses links|every_writer_in_the_sources"
  "kill: a sweep killed while writing, then resumed|kill_and_resume"
  "concurrency: two runs on one folder|two_runs_at_once"
  "writers: library on a nearly full disk|library_on_a_nearly_full_disk"
  "writers: a result holding another user's files is replaced with a warning|replacing_a_result_with_another_users_files"
)
passed=0 failed=0 skipped=0
for row in "${CASES[@]}"; do
  mkdir "$TMP/case" && pushd "$TMP/case" >/dev/null && ln -s "$TMP/gait" gait && ln -s "$TMP/configs" configs
  ("case_${row##*|}")
  rc=$?
  popd >/dev/null && rm -rf "$TMP/case"
  case $rc in
    0) echo "ok ${row%|*}" && passed=$((passed + 1)) ;;
    77) echo "skip ${row%|*}" && skipped=$((skipped + 1)) ;;
    *) echo "FAIL ${row%|*}" && failed=$((failed + 1)) ;;
  esac
done
echo "adversarial: $passed passed, $failed failed, $skipped skipped"
[[ $failed -eq 0 ]]
