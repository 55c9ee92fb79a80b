#!/usr/bin/env bash
# check_judge_hostile.sh DISKVAL TO_POSE SCENARIO: files that must not pass.
# ODE's run of SCENARIO (0.3 s) written by simulate, and in the pose form,
# pass; these, made from them by awk, do not:
#   - the pose 1 m above the ground: lost contact (run_trajcheck.h: the
#     linked engines' limits, engine_watch.h); so is the pose lifted by twice
#     the limit (0.01 radii: 2 mm on this 0.1 m disk, under 0.01 m), and
#     lifted by half the limit it agrees, and so does a blip of 1.5 times the
#     limit for three rows (0.02 s, under the 0.05 s allowed); quaternions 9e-7
#     longer than unit (the reader takes 1e-6) judge as the unit pose, to 1e-12;
#   - the pose 0.5 m into the ground: diverged, "sank";
#   - x, y 100 m from the contact point, or phi garbage: refused, "the
#     contact point ... the columns disagree" (exit 2);
#   - psi not turning while psi_dot says it does, a theta_dot 20 rad/s off
#     theta's: refused, "turns by"; a pose whose velocities are all 0:
#     refused, "the columns disagree" (its centre moves, vx, vy say not);
#   - two rows between each pair of samples with theta 1 rad off (theta_dot
#     set so the steps agree with the rates): refused, "disagrees with the
#     rows at them" (the same run written every 1 ms, honest, agrees);
#   - the run slowed by 7% over 0.3 s (the reference's state at t - 0.1 t^2),
#     its energy column held at the start's: refused, "the energy is not the
#     energy of the state" (ODE's run cut to t..y,energy, honest, agrees);
#   - the pose's centre 3 mm off in x on every other row, its velocities
#     still rolling: refused, "the centre's x moves by";
#   - the reference's own output (simulate --engine reduced): not judged;
#     so is that output cut to t,theta,contact_x,contact_y or to t..y, or
#     written with 10 significant digits (what a file does not give is
#     derived, and does not count; what it gives counts to its digits), while
#     theta 1e-9 rad off on one row of it is another run, judged (agrees);
#     so is a sweep point of the reference at its tighter reference's settings;
#     its near copies are refused, "the columns disagree": x one row late
#     (the contact point 2.1e-3 r from where x puts it at its second row,
#     0.001 r allowed), phi's first step 1.9 times its rate's (the contact
#     point 0.015 r off), psi scaled by 1.2
#     or 1.12 (its steps' misses add up to 0.167 and 0.107 of its travel,
#     0.08 allowed, engine_watch.h); psi scaled by 1.05 (0.048) agrees;
#   - a convergence study (--step) of one file given three times, or of errors
#     that do not fall: not judged, exit 1, never "converges to the reference";
#     so is verify (and suite --verify, its JUnit case a failure) of an engine
#     whose errors are 0 at every step (Simbody's steady circle, when built).
# A run that failed at its first sample measured nothing: its metrics are
# "not measured" on stdout and in report.md, null in report.json, never 0,
# and no failure line compares a NaN with a limit.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_hostile.sh DISKVAL TO_POSE SCENARIO}
to_pose=${2:?usage}
sc=${3:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
short=(--set scenario.duration=0.3)
name=$(sed -n 's/^name *= *//p' "$sc" | head -1)
r=$(sed -n 's/^radius *= *//p' "$sc" | head -1)
"$dv" simulate "$sc" "${short[@]}" --engine ode --out "$work/run.csv" --quiet 2>/dev/null
cd "$work" || exit 2
"$dv" simulate "$sc" "${short[@]}" --engine reduced --out ref.csv --quiet 2>/dev/null
"$to_pose" "$r" 0 <run.csv >pose.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { $4 += 1 } 1' pose.csv >hover.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { $4 -= 0.5 } 1' pose.csv >sunk.csv
awk -F, -v OFS=, -v CONVFMT=%.17g -v d=0.02 -v r="$r" 'NR > 1 { $4 += d * r } 1' pose.csv >lifted.csv
awk -F, -v OFS=, -v CONVFMT=%.17g -v d=0.005 -v r="$r" 'NR > 1 { $4 += d * r } 1' pose.csv >raised.csv
awk -F, -v OFS=, -v CONVFMT=%.17g -v d=0.015 -v r="$r" 'NR >= 12 && NR <= 14 { $4 += d * r } 1' pose.csv >blip.csv
# every quaternion 9e-7 longer than unit (inside the 1e-6 the reader takes) judges as the pose
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { for (k = 5; k <= 8; k++) $k *= 1 + 9e-7 } 1' pose.csv >scaled.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 2 { $5 += 100; $6 += 100 } 1' run.csv >far.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 2 { $3 = 7 * $1 + 1 } 1' run.csv >phi_garbage.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 2 { $4 = 0 } 1' run.csv >psi_still.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 2 { $9 += 20 } 1' run.csv >theta_dot_off.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 2 { for (k = 9; k <= 14; k++) $k = 0 } 1' pose.csv >still_pose.csv
"$dv" simulate "$sc" "${short[@]}" --set scenario.output_dt=0.001 --engine ode --out dense.csv \
  --quiet 2>/dev/null
awk 'BEGIN { FS = OFS = ","; CONVFMT = OFMT = "%.17g" }
  NR == 1 { print "t,theta,phi,psi,x,y,theta_dot,phi_dot,psi_dot"; next }
  {
    if (NR > 2) {
      H = $1 - p[1]
      for (k = 1; k <= 2; k++) {
        for (c = 1; c <= 12; c++) m[c] = p[c] + ($c - p[c]) * k / 3
        m[2] += 1
        m[9] = k == 1 ? 6 / H - p[9] : -6 / H - $9
        print m[1], m[2], m[3], m[4], m[5], m[6], m[9], m[10], m[11]
      }
    }
    print $1, $2, $3, $4, $5, $6, $9, $10, $11
    for (c = 1; c <= 12; c++) p[c] = $c
  }' run.csv >between.csv
"$dv" simulate "$sc" "${short[@]}" --set scenario.output_dt=0.001 --engine reduced --out fine.csv \
  --quiet 2>/dev/null
awk 'BEGIN { FS = OFS = ","; CONVFMT = OFMT = "%.17g" }
  NR == 1 { next }
  { n++; for (c = 1; c <= 12; c++) v[n, c] = $c }
  END {
    print "t,theta,phi,psi,x,y,energy"
    for (k = 0; k <= 30; k++) {
      t = k * 0.01; w = t - 0.1 * t * t; i = int(w / 0.001) + 1; a = (w - v[i, 1]) / 0.001
      if (i >= n) { i = n - 1; a = 1 }
      out = t
      for (c = 2; c <= 6; c++) out = out OFS (v[i, c] + (v[i + 1, c] - v[i, c]) * a)
      print out, v[1, 12]
    }
  }' fine.csv >slowed.csv
cut -d, -f1-6,12 run.csv >ode_energy.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 2 && NR % 2 { $2 += 0.003 } 1' pose.csv >slide.csv
# near copies of the reference's own output: x one row late, phi's first step
# 1.9 times its rate's, psi scaled by 1.2 and 1.12 (refused) and by 1.05
# (inside the 0.08 of its travel its steps' misses may add up to, engine_watch.h: agrees)
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR == 2 { p = $5 } NR > 2 { t = $5; $5 = p; p = t } 1' ref.csv >ref_x_late.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR == 2 { p = $3 } NR == 3 { d = $3 - p } NR >= 3 { $3 += 0.9 * d } 1' \
  ref.csv >ref_phi_step.csv
# the contact point given 1.3 and 0.8 times the 1e-4 m its columns allow off (0.001 r, plus
# 1e-5 of its coordinates: under 6e-6 m here); psi's first step 0.5 rad off its rate
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { $7 += 1.3e-4 } 1' run.csv >contact_out.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { $7 += 0.8e-4 } 1' run.csv >contact_in.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 2 { $4 += 0.5 } 1' run.csv >psi_first_step.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { $4 *= 1.2 } 1' ref.csv >ref_psi_far.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { $4 *= 1.12 } 1' ref.csv >ref_psi_over.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR > 1 { $4 *= 1.05 } 1' ref.csv >ref_psi_near.csv
# the reference's own output with fewer columns, or fewer digits; and theta
# 1e-9 rad off on one row (run_judge.c: own_output)
cut -d, -f1,2,7,8 ref.csv >ref_min.csv
cut -d, -f1-6 ref.csv >ref_pose.csv
awk -F, -v OFS=, 'NR > 1 { for (k = 2; k <= NF; k++) $k = sprintf("%.10g", $k) } 1' ref.csv \
  >ref_digits.csv
awk -F, -v OFS=, -v CONVFMT=%.17g 'NR == 12 { $2 += 1e-9 } 1' ref.csv >ref_theta_near.csv
# judge FILE WANT_STATUS WANT_VERDICT FRAGMENT: exit status, outcome (or, for
# exit 2, the error line) and a failure saying FRAGMENT
judge() {
  local file=$1 want=$2 verdict=$3 fragment=$4
  "$dv" judge "$sc" "${short[@]}" "$file.csv" --out "out_$file" --quiet >"$file.out" 2>"$file.err"
  local code=$? report=out_$file/$name/report.json
  check '[ $code -eq $want ]' "$file: exit status $code, not $want ($(head -1 "$file.err"))"
  if [ "$want" -eq 2 ]; then
    check '[ "$(wc -l <"$file.err")" -eq 1 ] && grep -q -- "$fragment" "$file.err"' \
      "$file: not one line saying '$fragment': $(cat "$file.err")"
    check '[ ! -e "$report" ]' "$file: a report for a refused file"
    echo "$file: $(head -1 "$file.err" | cut -c1-200)"
    return
  fi
  local outcome failures
  outcome=$(jq -r ".engines.$file.outcome" "$report")
  failures=$(jq -r ".engines.$file.failures[]" "$report")
  check '[ "$outcome" = "$verdict" ]' "$file: $outcome, not $verdict"
  check '[[ "$failures" == *"$fragment"* ]]' "$file: no failure says '$fragment': $failures"
  echo "$file: $outcome; $(echo "$failures" | head -1 | cut -c1-200)"
}
judge run 0 agrees ""
judge pose 0 agrees ""
judge hover 1 "lost contact" "above the ground for"
judge lifted 1 "lost contact" "above the ground for"
judge raised 0 agrees ""
judge blip 0 agrees ""
judge scaled 0 agrees ""
for m in theta_max_err path_max_err; do
  a=$(jq -r ".engines.pose.$m" "out_pose/$name/report.json") b=$(jq -r ".engines.scaled.$m" "out_scaled/$name/report.json")
  check 'awk -v a="$a" -v b="$b" "BEGIN { exit !(a - b <= 1e-12 && b - a <= 1e-12) }"' \
    "quaternions 9e-7 long: $m $b, the unit pose's $a"
done
judge sunk 1 diverged "sank 0.5 m into the ground"
judge far 2 "" "the columns disagree"
judge phi_garbage 2 "" "the columns disagree"
judge psi_still 2 "" "psi turns by"
judge theta_dot_off 2 "" "theta turns by"
judge still_pose 2 "" "the columns disagree"
judge dense 0 agrees ""
judge between 2 "" "disagrees with the rows at them"
judge ode_energy 0 agrees ""
judge slowed 2 "" "the energy is not the energy of the state"
judge slide 2 "" "the centre's x moves by"
judge ref 1 "not judged" "the reference's own output"
judge ref_x_late 2 "" "the contact point .* the columns disagree"
judge ref_phi_step 2 "" "the contact point .* the columns disagree"
judge contact_out 2 "" "the contact point .* (0.0001.. m allowed): the columns disagree"
judge contact_in 0 agrees ""
judge psi_first_step 2 "" "psi turns by .* (off by 0.5 rad"
judge ref_psi_far 2 "" "psi's steps add up to"
judge ref_psi_over 2 "" "psi's steps add up to"
judge ref_psi_near 0 agrees ""
judge ref_min 1 "not judged" "the reference's own output"
judge ref_pose 1 "not judged" "the reference's own output"
judge ref_digits 1 "not judged" "the reference's own output"
judge ref_theta_near 0 agrees ""
# a convergence study of one file given three times, or of errors that do not
# fall (the reference's theta + 1, 2, 3 urad after t = 0.1 s: under the floor)
for k in 1 2 3; do
  awk -F, -v OFS=, -v CONVFMT=%.17g -v k=$k 'NR > 1 && $1 > 0.1 { $2 += k * 1e-6 } 1' ref.csv |
    cut -d, -f1,2,7-12 >near$k.csv
done
cp near1.csv again1.csv && cp near1.csv again2.csv
steps=(--step 1e-3,5e-4,2.5e-4)
"$dv" judge "$sc" "${short[@]}" near1.csv again1.csv again2.csv "${steps[@]}" --out same --quiet \
  >same.out 2>&1
code=$?
check '[ $code -eq 1 ] && grep -q "not judged: the trajectories at dt 0.001 and 0.0005 have the same" same.out' \
  "one file three times: exit status $code: $(grep -A1 convergence same.out)"
"$dv" judge "$sc" "${short[@]}" near1.csv near2.csv near3.csv "${steps[@]}" --out flat --quiet \
  >flat.out 2>&1
code=$?
check '[ $code -eq 1 ] && grep -q "not judged: the errors do not fall" flat.out' \
  "errors that do not fall: exit status $code: $(grep -A1 convergence flat.out)"
check '! grep -q "converges to the reference" same.out flat.out' "a study that shows nothing converges"
# verify shares that judging: errors of exactly 0 at dt..dt/8 show nothing
if "$dv" engines | grep -q '^simbody '; then
  "$dv" verify "$sc" "${short[@]}" --engines simbody --quiet >verify0.out 2>&1
  code=$?
  check '[ $code -eq 1 ] && grep -q "not judged: the trajectories at dt 0.001 and 0.0005 have the same" verify0.out' \
    "verify of errors 0: exit status $code: $(cat verify0.out)"
  mkdir -p suite0 && cp "$sc" suite0/
  "$dv" suite suite0 --verify "${short[@]}" --engines simbody --out suite0_out --junit suite0.xml \
    --jobs 1 --quiet >suite0.out 2>&1
  code=$?
  check '[ $code -eq 1 ] && grep -q "<failure message=\"not judged" suite0.xml' \
    "suite --verify of errors 0: exit status $code: $(cat suite0.out; cat suite0.xml)"
  check '! grep -q "converges to the reference" verify0.out suite0_out/verify.md' \
    "errors of 0 converge: $(cat verify0.out suite0_out/verify.md)"
fi
# a sweep point of the reference at the settings of the tighter reference it
# is measured against is that reference: not judged, not ok, no Pareto star
"$dv" sweep "$sc" "${short[@]}" --engine reduced --vary integrator=gsl-rk8pd-stepped \
  --vary rtol=1e-14 --vary atol=1e-16 --out sweep --quiet >sweep.out 2>&1
check 'grep -q "^reduced,gsl-rk8pd-stepped,1e-14,1e-16,.*,not judged,0$" sweep/sweep.csv' \
  "sweep: the tighter reference's own settings: $(tail -1 sweep/sweep.csv)"
check '[ "$(jq ".points[0].ok" sweep/sweep.json)" = false ]' "sweep: the point is ok"
for file in sunk hover; do
  check '! grep -qi "nan" "$file.out" out_$file/$name/report.md' \
    "$file: a NaN printed: $(grep -hi nan "$file.out" out_$file/$name/report.md | head -3)"
done
check 'grep -q "theta not measured  path not measured" sunk.out' "sunk: $(head -1 sunk.out)"
check '! grep -q "0.00e+00" sunk.out' "sunk: an unmeasured error printed as 0: $(head -1 sunk.out)"
check '[ "$(jq .engines.sunk.theta_max_err out_sunk/$name/report.json)" = null ]' \
  "sunk: theta_max_err $(jq .engines.sunk.theta_max_err out_sunk/$name/report.json), not null"
check 'grep -q "| theta_max_err | not measured |" out_sunk/$name/report.md' "sunk: report.md"
exit $fail
