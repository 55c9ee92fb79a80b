#!/usr/bin/env bash
# check_judge_between.sh DISKVAL BETWEEN_ROWS SCENARIO: judge's allowance for rows between the
# sample times. The reference's own run of SCENARIO every 1 ms, judged at its output_dt:
#   - honest, it is not refused, and not judged: its every sample is the reference's (the
#     rows at the sample times are those of the reference's run at output_dt, digit for digit);
#   - its rows between the samples moved off the Akima interpolant to 0.999 T + 1.5 |a - b|
#     (T: half the theta limit, run_judge.h; a, b: Akima and Steffen, by between_rows with
#     GSL): inside the allowance of 2 |a - b| beyond T, it is still not refused (not judged:
#     the samples, at the rows it leaves, are still the reference's);
#   - moved to T + 2.5 |a - b|: outside it, refused, "disagrees with the rows at them".
# The scene is cut to 2 s and sampled every 0.02 s. Then the same run with a row every 0.05 s,
# sampled every 0.01 s: interpolating between its rows is uncertain by 0.019 rad in theta,
# 0.028 m in the contact point (measured: judge says so). Each is held against a tenth of its
# own limit: under a theta limit of 0.05 rad and a path limit of 2 m it is too sparse in
# theta; under 2 rad and 0.05 m, in the contact point. And the state form with every
# third row left out, each rate interpolated at the samples between rows, agrees.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_between.sh DISKVAL BETWEEN_ROWS SCENARIO}
between=${2:?usage}
sc=${3:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
name=$(sed -n 's/^name *= *//p' "$sc" | head -1)
dt=0.02
# the energy, invariants and turning points, from rates derived through the moved rows, are
# lifted: the allowance alone decides here (judge_hostile judges a file's energy; the moved
# rows' rates place the turns 0.022 rad off, measured)
short=(--set scenario.duration=2 --set scenario.output_dt=$dt --set tolerance.energy_drift=100
  --set tolerance.invariant_drift=100 --set tolerance.theta_turning_err=100
  --set tolerance.turning_lag=100)
"$dv" simulate "$sc" --set scenario.duration=2 --set scenario.output_dt=0.001 --engine reduced \
  --out dense.csv --quiet 2>/dev/null
cut -d, -f1-6 dense.csv >honest.csv
"$dv" judge "$sc" "${short[@]}" honest.csv --out out_honest --quiet >honest.out 2>honest.err
code=$?
# not refused (exit 2), and the reference's own output: not judged (exit 1), never a pass
own() { # NAME: exit 1, not judged as the reference's own output
  jq -e --arg n "$1" '.engines[$n] | .outcome == "not judged" and
    any(.failures[]; contains("the reference'"'"'s own output"))' "out_$1/$name/report.json" >/dev/null
}
check '[ $code -eq 1 ] && own honest' "honest: exit $code: $(cat honest.err)"
limit=$(jq -r ".engines.honest.limits.theta_max_err | .limit - .spread" "out_honest/$name/report.json")
T=$(awk -v l="$limit" 'BEGIN { printf "%.17g", 0.5 * l }') # DV_JUDGE_BETWEEN_SHARE
"$between" $dt "$(awk -v t="$T" 'BEGIN { printf "%.17g", 0.999 * t }')" 1.5 <dense.csv >inside.csv
"$between" $dt "$T" 2.5 <dense.csv >outside.csv
"$dv" judge "$sc" "${short[@]}" inside.csv --out out_inside --quiet >inside.out 2>inside.err
code=$?
check '[ $code -eq 1 ] && own inside' "rows inside the allowance: exit $code: $(cat inside.err)"
"$dv" judge "$sc" "${short[@]}" outside.csv --out out_outside --quiet >outside.out 2>outside.err
code=$?
check '[ $code -eq 2 ] && grep -q "disagrees with the rows at them" outside.err' \
  "rows outside the allowance: exit $code: $(cat outside.err)"
# the state form with every third row left out (not the last): the samples between rows
# are interpolated, every rate too, and it agrees (measured: invariant_drift 1.4e-4 against
# its limit 0.01; the heading rate held from the row before made it 0.34)
"$dv" simulate "$sc" --set scenario.duration=2 --engine reduced --out every.csv --quiet 2>/dev/null
awk -v n="$(wc -l <every.csv)" 'NR == 1 || NR == n || NR % 3' every.csv >irregular.csv
"$dv" judge "$sc" --set scenario.duration=2 irregular.csv --out out_irregular --quiet >irregular.out 2>&1
code=$?
check '[ $code -eq 0 ] && [ "$(jq -r .engines.irregular.outcome out_irregular/$name/report.json)" = agrees ]' \
  "every third row left out: exit $code: $(cat irregular.out)"
cut -d, -f1-6 dense.csv | awk 'NR == 1 || (NR - 2) % 50 == 0' >sparse.csv
sparse=(--set scenario.duration=2 --set scenario.output_dt=0.01 --set tolerance.energy_drift=100
  --set tolerance.invariant_drift=100)
for case in "0.05 2 rad in theta" "2 0.05 m in the contact point"; do
  read -r th path what <<<"$case"
  "$dv" judge "$sc" "${sparse[@]}" --set tolerance.theta_max_err=$th \
    --set tolerance.path_max_err=$path sparse.csv --out out_sparse --quiet >sparse.out 2>sparse.err
  code=$?
  check '[ $code -eq 2 ] && grep -q "samples too sparse to judge: .* uncertain by [0-9.e-]* $what" sparse.err' \
    "rows every 0.05 s, limits $th rad and $path m: exit $code, not too sparse $what: $(cat sparse.err)"
done
[ $fail -eq 0 ] && echo "rows between samples: inside the allowance not refused, outside refused (T $T rad)"
exit $fail
