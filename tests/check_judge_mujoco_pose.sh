#!/usr/bin/env bash
# check_judge_mujoco_pose.sh DISKVAL PLAIN_MUJOCO SCENARIO: a run of MuJoCo
# written by `simulate --engine mujoco` (a cylinder scene: MuJoCo's own
# collider), and the same motion written by a plain MuJoCo loop
# (examples/plain_mujoco_judge.c --run: the model and settings that run wrote
# in its .csv.json, its qpos and qvel in the pose form with velocities), both
# get compare's verdict for MuJoCo, and every number of the pose file's
# report.json entry (metrics, limits, margins, horizon, window) is within
# 1e-9 relative of compare's: energy_drift and slip_max too, since the file
# carries MuJoCo's own velocities. The simulate CSV (the state form) gets the
# same numbers but slip_max, not judged there (its rates assume rolling).
# Measured on tests/data/short_circle_cylinder.ini: the pose file 7.5e-12
# (horizon.early_errors.psi_dot; theta_max_err 4.4e-12: the pose's
# quaternion converted by diskval's own code, not MuJoCo's), the state file 0.
# Timing and cost fields (wall_*, steps) and the settings are not compared.
# Re-measure: the test prints every measured number (ctest -V -R NAME).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_mujoco_pose.sh DISKVAL PLAIN_MUJOCO SCENARIO}
plain=${2:?usage}
sc=${3:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
name=$(sed -n 's/^name *= *//p' "$sc" | head -1)
dt=$(sed -n 's/^output_dt *= *//p' "$sc" | head -1)
"$dv" simulate "$sc" --engine mujoco --out mjstate.csv --quiet
check '[ "$(jq -r .settings.geom mjstate.csv.json)" = cylinder ]' "the run is not MuJoCo's cylinder"
"$plain" "$sc" --run mjstate.csv.json --pose mjpose.csv --dt "$dt" >plain.txt
check '[ $? -le 1 ]' "the plain MuJoCo loop failed: $(cat plain.txt)"
"$dv" compare "$sc" --engines mujoco --out cmp --quiet >/dev/null
want=$(jq -r .engines.mujoco.outcome "cmp/$name/report.json")
# the largest relative difference of the numbers of engines.EB in B to compare's
# engines.mujoco, skipping keys matching SKIP; "missing KEY" for a number B lacks
maxrel() {
  jq -r -n --slurpfile a "cmp/$name/report.json" --slurpfile b "$1" --arg eb "$2" --arg skip "$3" '
    def leaves: [paths(numbers) as $p | {key: ($p | map(tostring) | join(".")), value: getpath($p)}]
                | from_entries;
    ($a[0].engines.mujoco | leaves) as $x | ($b[0].engines[$eb] | leaves) as $y |
    [$x | keys[] | select(test("wall|steps|^settings\\.|" + $skip) | not) | . as $k |
      if $y[$k] == null then "missing \($k)"
      else (($x[$k] - $y[$k]) | fabs) / ([($x[$k] | fabs), 1e-300] | max) end] |
    (map(select(type == "string")) | .[0]) // (map(select(type == "number")) | max)'
}
for form in mjstate mjpose; do
  "$dv" judge "$sc" $form.csv --out $form --quiet >/dev/null
  check '[ $? -eq 0 ]' "judge $form: exit status not 0"
  skip=$([ $form = mjstate ] && echo slip_max || echo '^$x^')
  rel=$(maxrel "$form/$name/report.json" $form "$skip")
  got=$(jq -r ".engines.$form.outcome" "$form/$name/report.json")
  echo "$form: outcome $got (compare: $want); largest relative difference to compare's numbers: $rel"
  check '[ "$want" = "$got" ]' "$form: outcome $got, compare's $want"
  check 'awk -v r="$rel" "BEGIN { exit !(r + 0 == r && r <= 1e-9) }"' "$form: $rel > 1e-9"
done
check 'jq -r .engines.mjstate.limits.slip_max.from "mjstate/$name/report.json" | grep -q "not judged"' \
  "the state file's slip_max: $(jq -c .engines.mjstate.limits.slip_max "mjstate/$name/report.json")"
exit $fail
