#!/usr/bin/env bash
# Resumes keyed by content: every option of the resumable commands, read from their
# --help, either shapes the rows and is in the folder's key (a rerun that changes it is refused,
# exit 2, naming the key) or is listed here as not shaping them with the reason (a rerun that
# changes it resumes). An option missing from the tables fails the test, so a new option must
# be keyed or documented. impact-map is not resumable: every run writes its folder whole.
# Usage: resume_key_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
export GAITOPT_SCRIPTS="$TMP/no_scripts" # no pictures
cd "$TMP" || exit 1
ROBOT="$ROOT/configs/robots/mu2004_five_link.yaml"
GAIT="$ROOT/configs/gaits/mu2004.yaml"
FAILED=0

# rerun COMMAND BASE OPTION [VALUE]: `gaitopt COMMAND` with the options of the associative array
# BASE (option -> value, "" for a flag), OPTION set to VALUE (a flag when VALUE is absent).
rerun() {
  local command=$1 o
  local -n base=$2
  local -A args=()
  for o in "${!base[@]}"; do args[$o]=${base[$o]}; done
  [[ -z ${3:-} ]] || args[$3]=${4:-}
  local words=()
  for o in "${!args[@]}"; do
    words+=("$o")
    [[ -z ${args[$o]} ]] || words+=("${args[$o]}")
  done
  run "$command" "${words[@]}"
}

# The long options of `gaitopt COMMAND --help`, one a line.
options_of() {
  "$GAITOPT" "$1" --help | sed -nE 's/^  (-[a-zA-Z], ?)?(--[a-z][a-z0-9-]*).*/\2/p' | sort -u
}
# covered COMMAND TABLE...: every option of the help is a row of the tables and every row an option.
covered() {
  local command=$1 listed help
  shift
  listed=$(printf '%s\n' "$@" | sed 's/|.*//' | sort -u)
  help=$(options_of "$command")
  [[ -n $help ]] || { echo "FAIL $command: no options read from --help" && FAILED=1 && return; }
  while read -r o; do
    grep -qx -- "$o" <<<"$listed" || { echo "FAIL $command $o: neither keyed nor documented" && FAILED=1; }
  done <<<"$help"
  while read -r o; do
    grep -qx -- "$o" <<<"$help" || { echo "FAIL $command $o: in the table but not an option" && FAILED=1; }
  done <<<"$listed"
}
# refused NAME KEY: the last run was refused naming KEY and the rows were kept.
refused() {
  if [[ $RC -eq 2 ]] && grep -q -- "^  $2: folder" "$TMP/err"; then
    echo "ok keyed $1 ($2)"
  else
    echo "FAIL keyed $1: expected exit 2 naming $2, got $RC: $(head -c 300 "$TMP/err")" && FAILED=1
  fi
}
resumed() {
  if [[ $RC -eq 0 ]] && grep -q "$2" "$TMP/out"; then
    echo "ok not keyed $1"
  else
    echo "FAIL not keyed $1: expected a resume, got $RC: $(head -c 300 "$TMP/err")" && FAILED=1
  fi
}

# first_run COMMAND BASE ROWS: the run every rerun resumes; `rows` keeps its row file's checksum.
first_run() {
  rerun "$1" "$2"
  [[ $RC -eq 0 ]] || fail "$1: $(cat "$TMP/err")"
  rows=$(md5sum <"$3")
}
# prove COMMAND BASE KEYED FREE RESUMED: the tables cover the help; each KEYED row's change is
# refused naming its key; each FREE row's change (without --quiet) resumes, printing RESUMED.
prove() {
  local command=$1 base=$2 resumed_line=$5 row option value key
  local -n keyed=$3 free=$4
  covered "$command" "${keyed[@]}" "${free[@]}"
  for row in "${keyed[@]}"; do
    IFS='|' read -r option value key <<<"$row"
    rerun "$command" "$base" "$option" "$value"
    refused "$command $option" "$key"
  done
  local -n args=$base
  unset "args[--quiet]"
  for row in "${free[@]}"; do
    IFS='|' read -r option value _ <<<"$row"
    [[ $value != - ]] || continue
    rerun "$command" "$base" "$option" "$value"
    resumed "$command $option" "$resumed_line"
  done
  args[--quiet]=
}

# --- stability -----------------------------------------------------------------------------------
run poly --robot "$ROBOT" --gait "$GAIT" --no-plots --rate 100 --out gait
[[ $RC -eq 0 ]] || fail "poly: $(cat "$TMP/err")"
run poly --robot "$ROBOT" --gait "$GAIT" --no-plots --rate 200 --out gait200
cp "$ROBOT" robot.yaml && echo "# the same robot, another file" >>robot.yaml
declare -A BASE=([--reference]=gait [--robot]=$ROBOT [--controller]=sliding_mode
  [--sweep]=push=0:1:2 [--steps]=2 [--no-plots]= [--quiet]= [--out]=s)
first_run stability BASE s/sweep_push.csv
# OPTION|VALUE|KEY: the rerun sets OPTION to VALUE (a flag when empty) and must name KEY.
STABILITY_KEYED=(
  "--reference|gait200|reference_trajectory_fnv1a"
  "--robot|robot.yaml|robot_file_fnv1a"
  "--controller|computed_torque|controller"
  "--ground|impedance|ground"
  "--steps|3|steps_requested"
  "--uncertainty-case|2|uncertainty_case"
  "--uncertainty-on|controller|uncertainty_on"
  "--mass-error|0.1|parameter_errors"
  "--length-error|0.05|parameter_errors"
  "--friction|0.5|friction"
  "--push|1|push_impulse_Ns"
  "--gain-scale|2|gain_scale"
  "--max-slip|0.5|contact_rules"
  "--cop-limit|fail|contact_rules"
  "--restitution|0.1|contact_rules"
  "--sweep|push=0:1:3|sweeps"
  "--map|push,mass_error|maps"
  "--poincare||poincare"
  "--set|robot.friction=0.5|config_overrides"
)
# OPTION|VALUE|why it does not shape a row ("-" as VALUE: not rerun).
COMMON_FREE=(
  "--out|-|names the folder that is resumed"
  "--quiet||progress on the terminal"
  "--help|-|prints the help"
)
STABILITY_FREE=("${COMMON_FREE[@]}"
  "--jobs|1|threads: each row is walked alone, the same on any thread"
  "--no-plots||the picture is drawn from the rows"
)
prove stability BASE STABILITY_KEYED STABILITY_FREE "0 points to walk (2 done before)"
[[ $(md5sum <s/sweep_push.csv) == "$rows" ]] || { echo "FAIL stability: the rows changed" && FAILED=1; }
# The reference made again, the same gait with another wall time in its summary.json, resumes.
run poly --robot "$ROBOT" --gait "$GAIT" --no-plots --rate 100 --out gait
[[ $RC -eq 0 ]] || fail "poly again: $(cat "$TMP/err")"
rerun stability BASE
resumed "stability on its reference made again" "0 points to walk (2 done before)"

# --set is keyed by content, not by its text: reordered or written otherwise (0.10 for 0.1, 1e-3
# for 0.001) resumes; another value is refused naming config_overrides.
SETS=(--reference gait --robot "$ROBOT" --controller sliding_mode --sweep push=0:1:2 --steps 2
  --no-plots --quiet --out sets)
run stability "${SETS[@]}" --set robot.foot.heel=0.1 --set ground.time_step=0.001
[[ $RC -eq 0 ]] || fail "stability --set: $(cat "$TMP/err")"
run stability "${SETS[@]}" --set ground.time_step=0.001 --set robot.foot.heel=0.1
resumed "stability --set reordered" "0 points to walk (2 done before)"
run stability "${SETS[@]}" --set robot.foot.heel=0.10 --set ground.time_step=1e-3
resumed "stability --set written otherwise" "0 points to walk (2 done before)"
run stability "${SETS[@]}" --set robot.foot.heel=0.11 --set ground.time_step=0.001
refused "stability --set another value" config_overrides

# --- library -------------------------------------------------------------------------------------
sed "s|segments: 25|segments: 8|; s|\.\./|$ROOT/configs/|" "$ROOT/configs/ocp/rabbit_kelly2017.yaml" \
  >base.yaml
printf 'name: l\nocp: base.yaml\ngrid:\n  speed: [0.7]\n' >lib.yaml
cp lib.yaml lib_other.yaml && echo "# another file" >>lib_other.yaml
declare -A LBASE=([--config]=lib.yaml [--jobs]=1 [--quiet]= [--out]=l)
first_run library LBASE l/index.csv
LIBRARY_KEYED=(
  "--config|lib_other.yaml|library_config_fnv1a"
  "--rate|500|rate_hz"
  "--set|description=another|config_overrides"
)
LIBRARY_FREE=("${COMMON_FREE[@]}"
  "--jobs|2|threads: each point is solved alone, the same on any thread"
  "--retry-failed||which finished points are solved again, not how"
  "--plots||pictures of the point folders, drawn from their rows"
)
prove library LBASE LIBRARY_KEYED LIBRARY_FREE "^library: 0 points solved, 0 failed"
# The files named inside the configs, changed in place under the same paths.
sed -i 's/torque_squared: 1.0/torque_squared: 2.0/' base.yaml
rerun library LBASE
refused "library: the OCP file's cost weight changed in place" ocp_config_fnv1a
[[ $(md5sum <l/index.csv) == "$rows" ]] || { echo "FAIL library: the rows changed" && FAILED=1; }

# --- impact-map: not resumable ------------------------------------------------------------------
# Its folder is written whole by every run: a second run on other values leaves none of the
# first run's rows.
im() { run impact-map --robot "$ROBOT" --step-lengths "$1" --knee-bias 5:10:2 --no-plots --quiet --out im; }
im 0.2:0.3:2 && im 0.4:0.5:2
if [[ $RC -eq 0 ]] && ! cut -d, -f1 im/impact_map.csv | grep -qx "0.2\|0.3"; then
  echo "ok impact-map writes its folder whole"
else
  echo "FAIL impact-map: $RC, rows of the first run left: $(cut -d, -f1 im/impact_map.csv | sort -u | head)"
  FAILED=1
fi

[[ $FAILED -eq 0 ]] || exit 1
echo "every option of stability and library is keyed or documented"
