#!/usr/bin/env bash
# check_judge_convergence.sh DISKVAL SCENARIO: judge --step over four recorded
# runs of ODE at dt, dt/2, dt/4, dt/8 (the softness scaled with the step, as
# verify refines them; written by simulate) gives verify's order and
# extrapolated discrepancy, within 5% (measured on tests/data/short_circle.ini:
# the same digits, order 1.00, 2.205e-09 rad, converges to the reference);
# and so do the same files carrying their step as a "# dt = H" line, without --step.
# Re-measure: the test prints every measured number (ctest -V -R NAME).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_convergence.sh DISKVAL SCENARIO}
sc=${2:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
"$dv" verify "$sc" --engines ode --quiet >verify.txt
"$dv" simulate "$sc" --engine ode --out base.csv --quiet
dt=$(jq -r .settings.timestep base.csv.json) soft=$(jq -r .settings.soft_cfm base.csv.json)
steps="" files=() steps_list=()
for i in 0 1 2 3; do # verify's levels, to its 9 digits (search_verify.c)
  h=$(awk -v d="$dt" -v i=$i 'BEGIN { printf "%.9g", d / 2^i }')
  s=$(awk -v d="$soft" -v i=$i 'BEGIN { printf "%.9g", d / 2^i }')
  "$dv" simulate "$sc" --engine ode --set engines.ode.timestep="$h" --set engines.ode.soft_cfm="$s" \
    --out "ode_$i.csv" --quiet
  steps=$steps${steps:+,}$h files+=("ode_$i.csv") steps_list+=("$h")
done
"$dv" judge "$sc" "${files[@]}" --step "$steps" --out out --quiet >judge.txt
code=$?
check '[ $code -eq 0 ]' "judge --step: exit status $code"
dt_files=()
for i in 0 1 2 3; do
  { echo "# dt = ${steps_list[$i]}"; cat "ode_$i.csv"; } >"dt_$i.csv"
  dt_files+=("dt_$i.csv")
done
"$dv" judge "$sc" "${dt_files[@]}" --out out_dt --quiet >judge_dt.txt
check '[ $? -eq 0 ]' "judge with dt lines: exit status not 0"
# "order P; extrapolated discrepancy X rad" of a report
field() { sed -n "s/.*order \([0-9.]*\); extrapolated discrepancy \([-0-9.e+]*\) rad.*/\\$2/p" "$1"; }
for out in judge.txt judge_dt.txt; do
  for k in 1 2; do
    want=$(field verify.txt $k) got=$(field $out $k)
    echo "$out: $([ $k = 1 ] && echo order || echo extrapolated): verify $want, judge $got"
    check 'awk -v a="$want" -v b="$got" "BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != \"\" && d <= 0.05 * (a < 0 ? -a : a)) }"' \
      "$out: judge's $got is not within 5% of verify's $want"
  done
  check 'grep -q "converges to the reference" $out' "$out: $(grep order $out)"
done
exit $fail
