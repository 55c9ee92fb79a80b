#!/usr/bin/env bash
# check_judge_convergence3.sh DISKVAL SCENARIO: three recorded runs of ODE at
# dt, dt/2, dt/4 (verify's first three levels: the softness scaled with the
# step, written by simulate) judged with --step give the order and the
# extrapolated discrepancy that verify's own errors at those three levels give,
# within 5%. Verify's four-level numbers come from its last three levels
# (dt/2..dt/8), a different triple, so the test compares like with like:
# Richardson over verify's first three errors, read at full precision from
# `suite --verify`'s verify.json (the same judging code, search_verify.c).
# Measured on tests/data/short_circle.ini: judge order 1.00, 8.270e-09 rad;
# verify's first three levels order 1.00017, 8.2706e-09 rad (its four-level
# estimate: order 1.00, 2.205e-09 rad); converges to the reference.
# Steps of another ratio (dt, dt/3, dt/9) still give order 1.
# Re-measure: the test prints every measured number (ctest -V -R NAME).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_convergence3.sh DISKVAL SCENARIO}
sc=${2:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
"$dv" suite --verify "$sc" --engines ode --out vout --quiet >/dev/null
"$dv" simulate "$sc" --engine ode --out base.csv --quiet
dt=$(jq -r .settings.timestep base.csv.json) soft=$(jq -r .settings.soft_cfm base.csv.json)
# runs at dt / ratio^i, their softness scaled alike; files in $files, steps in $steps
runs() {
  steps="" files=()
  for i in 0 1 2; do # to 9 digits, as verify sets them (search_verify.c)
    h=$(awk -v d="$dt" -v r="$2" -v i=$i 'BEGIN { printf "%.9g", d / r^i }')
    s=$(awk -v d="$soft" -v r="$2" -v i=$i 'BEGIN { printf "%.9g", d / r^i }')
    "$dv" simulate "$sc" --engine ode --set engines.ode.timestep="$h" \
      --set engines.ode.soft_cfm="$s" --out "$1_$i.csv" --quiet
    steps=$steps${steps:+,}$h files+=("$1_$i.csv")
  done
}
runs half 2
"$dv" judge "$sc" "${files[@]}" --step "$steps" --out out --quiet >judge.txt
code=$?
check '[ $code -eq 0 ]' "judge --step over 3 files: exit status $code"
check 'grep -q "converges to the reference" judge.txt' "$(grep order judge.txt)"
# "order P; extrapolated discrepancy X rad" of judge's report
field() { sed -n "s/.*order \([0-9.]*\); extrapolated discrepancy \([-0-9.e+]*\) rad.*/\\$2/p" "$1"; }
# verify's errors at dt, dt/2, dt/4: order log2(d1/d2), e(0) = e2 - d2 / (2^p - 1)
want_order=$(jq -r '.cases[0].errors as $e | (($e[0]-$e[1])/($e[1]-$e[2])) | log2' vout/verify.json)
want_e0=$(jq -r '.cases[0].errors as $e | (($e[0]-$e[1])/($e[1]-$e[2]) | log2) as $p
  | $e[2] - ($e[1]-$e[2]) / (pow(2; $p) - 1)' vout/verify.json)
echo "verify (4 levels): $(jq -r '.cases[0] | "order \(.order), e(0) \(.extrapolated)"' vout/verify.json)"
for k in 1 2; do
  want=$([ $k = 1 ] && echo "$want_order" || echo "$want_e0") got=$(field judge.txt $k)
  echo "$([ $k = 1 ] && echo order || echo extrapolated): verify's first 3 levels $want, judge's 3 files $got"
  check 'awk -v a="$want" -v b="$got" "BEGIN { d = a - b; if (d < 0) d = -d; exit !(b != \"\" && d <= 0.05 * (a < 0 ? -a : a)) }"' \
    "judge's $got is not within 5% of verify's $want"
done
# any ratio: dt, dt/3, dt/9 (ODE is first order: measured 1.00)
runs third 3
"$dv" judge "$sc" "${files[@]}" --step "$steps" --out out3 --quiet >judge3.txt
echo "ratio 3: $(grep order judge3.txt)"
got=$(field judge3.txt 1)
check 'awk -v b="$got" "BEGIN { exit !(b != \"\" && b > 0.95 && b < 1.05) }"' "ratio 3: order '$got', not 1"
# fewer than three steps are refused (a usage error)
"$dv" judge "$sc" half_0.csv half_1.csv --step "${steps%,*}" --out bad --quiet >/dev/null 2>bad.txt
check "[ $? -ne 0 ] && grep -q \"3 to 8\" bad.txt" "two files: $(cat bad.txt)"
exit $fail
