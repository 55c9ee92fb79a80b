#!/usr/bin/env bash
# check_judge_perturbed.sh DISKVAL TO_POSE SCENARIO: judge fails a trajectory
# that is wrong, with the metric that shows it, or does not judge it.
# MuJoCo's run of SCENARIO (a steady circle, run for 3 s: --set scenario.duration=3)
# written by simulate passes, and so does the same run
#   - with every third row left out (irregular times: interpolated; measured:
#     path_max_err 1.0533e-3 against 1.0454e-3 m with every row),
#   - in the pose form without velocities (rates from the interpolant),
#   - with only t,theta,contact_x,contact_y (energy, heading, invariants and
#     slip not judged, and said so);
# it fails when perturbed by awk:
#   - theta + 0.05 rad after t = 1 s: theta_max_err = 0.05001 > 0.01 (the shift and MuJoCo's own 1e-5);
#   - the path drifting by 5% of the distance rolled (x and contact_x +
#     0.05 * 1.519 m/s * t): path_max_err over its limit (1% of the rolled);
#   - stopped at half the duration: not judged, "the file ends at t = 1.5 s"; so is
#     one two rows short of the end, "the file ends at t = 2.98 s"; one that ends
#     past the thin reference's validity window (small_c, 0.3 s of 0.5 s) agrees;
#   - lying down early (theta falling 2 rad/s from t = 2 s to the limit
#     0.01 rad): ended by event, "lies down where the reference does not".
# Re-measure: the test prints every measured number (ctest -V -R NAME).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_perturbed.sh DISKVAL TO_POSE SCENARIO}
to_pose=${2:?usage}
sc=${3:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
set3=(--set scenario.duration=3)
name=$(sed -n 's/^name *= *//p' "$sc" | head -1)
"$dv" simulate "$sc" "${set3[@]}" --engine mujoco --out "$work/run.csv" --quiet 2>/dev/null
cd "$work" || exit 2
awk 'NR <= 2 || NR % 3 != 0' run.csv >irregular.csv
"$to_pose" 0.1 0 --no-velocity <run.csv >pose_only.csv
cut -d, -f1,2,7,8 run.csv >minimal.csv
# theta alone perturbed: without phi, psi, x, y (with them, a theta that does not
# put the contact point where the file does is refused: run_trajcheck.h)
cut -d, -f1,2,7-12 run.csv >no_pose.csv
awk -F, -v OFS=, 'NR > 1 && $1 > 1 { $2 += 0.05 } 1' no_pose.csv >theta_shift.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { d = 0.05 * 1.519 * $1; $5 += d; $7 += d } 1' run.csv >path_drift.csv
awk -F, 'NR == 1 || $1 <= 1.5' run.csv >half.csv
head -n -2 run.csv >two_short.csv # its last two rows (0.02 s) left out
awk -F, -v OFS=, 'NR == 1 { print; next }
  $1 > 2 { $2 = 1 - 2 * ($1 - 2); if ($2 <= 0.01) { $2 = 0.01; print; exit } } { print }' \
  no_pose.csv >lies_down.csv
# judge FILE WANT_STATUS WANT_VERDICT FRAGMENT: exit status, outcome, a failure saying FRAGMENT
judge() {
  local file=$1 want=$2 verdict=$3 fragment=$4
  "$dv" judge "$sc" "${set3[@]}" "$file.csv" --out "out_$file" --quiet >/dev/null 2>"$file.err"
  local code=$? report=out_$file/$name/report.json
  check '[ $code -eq $want ]' "$file: exit status $code, not $want ($(head -1 "$file.err"))"
  local outcome failures
  outcome=$(jq -r ".engines.$file.outcome" "$report")
  failures=$(jq -r ".engines.$file.failures[]" "$report")
  check '[ "$outcome" = "$verdict" ]' "$file: $outcome, not $verdict"
  check '[[ "$failures" == *"$fragment"* ]]' "$file: no failure says '$fragment': $failures"
  echo "$file: $outcome; $(echo "$failures" | head -1 | cut -c1-160)"
}
judge run 0 agrees ""
judge irregular 0 agrees ""
judge pose_only 0 agrees ""
judge minimal 0 agrees ""
for m in energy_drift heading_period_err invariant_drift slip_max; do
  why=$(jq -r ".engines.minimal.limits.$m.from" "out_minimal/$name/report.json")
  check '[[ "$why" == "not judged: "* ]]' "minimal: $m: $why"
done
judge theta_shift 1 "exceeds tolerance" "theta_max_err = 0.050"
judge path_drift 1 "exceeds tolerance" "path_max_err = "
judge half 1 "not judged" "the file ends at t = 1.5 s"
judge two_short 1 "not judged" "the file ends at t = 2.98 s"
# a file that stops after the thin reference's validity window ends (small_c: rolling needs
# more friction than 2 from t = 0.25 s), before the scene does (0.5 s), covers all that is
# judged: it agrees, not "the file ends at"
small=$(dirname "$sc")/small_c.ini
"$dv" simulate "$small" --engine ode --out small_ode.csv --quiet 2>/dev/null
awk -F, 'NR == 1 || $1 <= 0.3 + 1e-9' small_ode.csv >small_cut.csv
"$dv" judge "$small" small_cut.csv --out out_small --quiet >small.out 2>&1
code=$?
check '[ $code -eq 0 ] && [ "$(jq -r .engines.small_cut.outcome out_small/small_c/report.json)" = agrees ]' \
  "a file past the validity window, short of the scene: exit $code: $(cat small.out)"
judge lies_down 1 "ended by event" "lies down where the reference does not"
exit $fail
