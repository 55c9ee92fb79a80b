#!/usr/bin/env bash
# check_horizon_nudge.sh DISKVAL SCENARIO_DIR: the horizon's nudged reference
# starts inside the lying-down limits, and a failed reference run is named
# with the scenario's file (issue 23, item 15).
#   - theta = 0.0100001, theta_dot = -0.1 (1e-7 rad above theta_limit, falling):
#     theta - 1e-3 would start past the limit, where the equations fail; the
#     nudge to that side is not made, compare runs (exit 1: not judged) and
#     simulate works as before;
#   - a reference that fails (a step budget of 1) names the file and the run.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_horizon_nudge.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_horizon_nudge.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
cat >low.ini <<'INI'
[scenario]
name = low
duration = 1
output_dt = 0.01
[disk]
radius = 0.1
mass = 1.0
[initial]
theta = 0.0100001
theta_dot = -0.1
INI
"$dv" simulate low.ini --engine reduced --out low.csv 2>stderr; code=$?
check '[ $code -eq 0 ]' "simulate: exit $code: $(cat stderr)"
"$dv" compare low.ini --out out >stdout 2>stderr; code=$?
check '[ $code -eq 1 ]' "compare: exit $code, want 1 (not judged): $(cat stdout stderr)"
check '! grep -q "GSL\|undefined" stderr' "compare: the nudged reference failed: $(cat stderr)"
check '[ "$(jq -r .pass out/low/report.json)" = false ]' "compare: no report, or it passes"

"$dv" compare "$sc/steady_circle.ini" --set engines.reduced.max_steps=1 --out out >stdout 2>stderr
code=$?
check '[ $code -eq 2 ]' "a failed reference: exit $code, want 2"
check 'grep -q "^diskval compare: $sc/steady_circle.ini: the reduced reference: .*step budget spent" stderr' \
  "a failed reference does not name the file and the run: $(cat stderr)"
exit $fail
