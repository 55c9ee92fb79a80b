#!/usr/bin/env bash
# check_judge_equivalence.sh DISKVAL TO_POSE SCENARIO: judge gives a recorded
# trajectory the verdict and metrics compare gives the linked engine.
#   - MuJoCo's run written by simulate (the state CSV) and judged: the same
#     verdict, and every number of its report.json entry (metrics, limits,
#     margins, horizon, window) within 1e-9 relative of compare's (measured
#     on tests/data/short_circle.ini: identical, 0); its slip is not judged
#     (the state form's rates assume rolling) and says so;
#   - the same motion in the pose form (centre + quaternion + the rolling
#     velocities, by TO_POSE): the same within 1e-9 (measured: 4.2e-12, the
#     quaternion's round trip), but energy_drift (its energy is from the
#     rolling velocities, not MuJoCo's own: 1.3% apart) and slip_max (0);
#   - ODE's and Bullet's runs in the state form: as MuJoCo's (measured: identical).
# Timing and cost fields (wall_*, steps) and the engine's settings are not compared.
# Re-measure: the test prints every measured number (ctest -V -R NAME).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_equivalence.sh DISKVAL TO_POSE SCENARIO}
to_pose=${2:?usage}
sc=${3:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(sed -n 's/^name *= *//p' "$sc" | head -1)
for engine in mujoco ode bullet; do
  "$dv" simulate "$sc" --engine $engine --out "$work/$engine.csv" --quiet 2>/dev/null
done
cp "$work/mujoco.csv" "$work/mj.csv"
radius=$(sed -n 's/^radius *= *//p' "$sc" | head -1)
"$to_pose" "$radius" 0 <"$work/mj.csv" >"$work/mjpose.csv"
"$dv" compare "$sc" --engines mujoco,ode,bullet --out "$work/cmp" --quiet >/dev/null
check '[ $? -eq 0 ]' "compare failed on $sc"
for form in mj mjpose; do
  "$dv" judge "$sc" "$work/$form.csv" --out "$work/$form" --junit "$work/$form.xml" --quiet >/dev/null
  check '[ $? -eq 0 ]' "judge $form: exit status not 0"
done
"$dv" judge "$sc" "$work/ode.csv" "$work/bullet.csv" --name f_ode,f_bullet --out "$work/others" \
  --quiet >/dev/null
check '[ $? -eq 0 ]' "judge ode, bullet: exit status not 0"
a=$work/cmp/$name/report.json
# the largest relative difference of the numbers under engines.EB of B against
# engines.EA of A, skipping keys matching SKIP; "missing KEY" for a number B lacks
maxrel() {
  jq -r -n --slurpfile a "$a" --slurpfile b "$1" --arg eb "$2" --arg skip "$3" --arg ea "$4" '
    def leaves: [paths(numbers) as $p | {key: ($p | map(tostring) | join(".")), value: getpath($p)}]
                | from_entries;
    ($a[0].engines[$ea] | leaves) as $x | ($b[0].engines[$eb] | leaves) as $y |
    [$x | keys[] | select(test("wall|steps|^settings\\.|" + $skip) | not) | . as $k |
      if $y[$k] == null then "missing \($k)"
      else (($x[$k] - $y[$k]) | fabs) / ([($x[$k] | fabs), 1e-300] | max) end] |
    (map(select(type == "string")) | .[0]) // (map(select(type == "number")) | max)'
}
for engine in ode bullet; do
  rel=$(maxrel "$work/others/$name/report.json" "f_$engine" slip_max $engine)
  echo "$engine: largest relative difference to compare's metrics: $rel (not compared: slip_max)"
  check 'awk -v r="$rel" "BEGIN { exit !(r + 0 == r && r <= 1e-9) }"' "$engine: $rel > 1e-9"
  want=$(jq -r ".engines.$engine.outcome" "$a") got=$(jq -r ".engines.f_$engine.outcome" "$work/others/$name/report.json")
  check '[ "$want" = "$got" ]' "$engine: outcome $got, compare's $want"
done
for form in mj mjpose; do
  b=$work/$form/$name/report.json
  skip='slip_max'
  [ $form = mjpose ] && skip='slip_max|energy_drift'
  rel=$(maxrel "$b" "$form" "$skip" mujoco)
  echo "$form: largest relative difference to compare's metrics: $rel (not compared: $skip)"
  check 'awk -v r="$rel" "BEGIN { exit !(r + 0 == r && r <= 1e-9) }"' "$form: $rel > 1e-9"
  for key in pass outcome; do
    want=$(jq -r ".engines.mujoco.$key" "$a") got=$(jq -r ".engines.$form.$key" "$b")
    check '[ "$want" = "$got" ]' "$form: $key $got, compare's $want"
  done
  if [ $form = mj ]; then # the pose form gives velocities: its slip is measured
    why=$(jq -r ".engines.$form.limits.slip_max.from" "$b")
    check '[[ "$why" == "not judged: "* ]]' "$form: slip_max: $why"
  fi
  check 'grep -q "<testcase classname=\"$name\" name=\"$form\"" "$work/$form.xml"' \
    "$form: no JUnit test case"
done
exit $fail
