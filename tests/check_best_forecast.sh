#!/usr/bin/env bash
# check_best_forecast.sh DISKVAL DATA SCENARIOS: best tells each probe on
# stderr as it ends, and forecasts the rest of its search once every choice has
# had its first probe, saying how long the rest took, on three scenes of
# different engines and costs. How near the forecast comes is a benchmark
# (bench/bench_forecast.sh: a busy machine moves it), not a test. Measured (this
# machine, one at a time): 2-euro coin ODE 5.55 s forecast, 5.54 s taken;
# saucer MuJoCo 13.1 s, 9.5 s; falling ODE 0.60 s, 0.51 s. On the coin,
# QuickStep's error at the first step ties dWorldStep's (8.871e-04 rad both)
# at 2.5x the cost a step: it is not searched further.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1 data=$2 scenarios=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0
for case in "$data/two_euro.ini ode" "$data/saucer.ini mujoco" "$scenarios/falling.ini ode"; do
  set -- $case
  n=$((n + 1))
  "$diskval" best "$1" --engine "$2" --theta-tol 1e-3 >"$work/out$n" 2>"$work/err$n"
  code=$?
  check '[ $code -eq 0 ]' "$1 $2: exit $code: $(tail -3 "$work/err$n")"
  rows=$(grep -cE ' (meets|marginal|exceeds|failed)( |$)' "$work/out$n")
  told=$(grep -c "^diskval best: $2 " "$work/err$n")
  check '[ "$rows" -gt 0 ] && [ "$rows" -eq "$told" ]' "$1: $rows probes, $told told on stderr"
  line=$(grep 'the rest of the search took' "$work/err$n")
  took=$(sed -n 's/.*took \([0-9.e+-]*\) s (forecast \([0-9.e+-]*\) s).*/\1 \2/p' <<<"$line")
  check '[ -n "$took" ]' "$1 $2: no forecast and time taken: $(tail -3 "$work/err$n")"
  echo "$1 $2: $line"
done
check 'grep -q "^quickstep not searched: its error at .* ties step" "$work/out1"' \
  "the coin: QuickStep searched though it ties dWorldStep: $(grep -c quickstep "$work/out1") rows"
check '! grep -q "^quickstep not searched" "$work/out2"' "mujoco has no quickstep"
"$diskval" best "$scenarios/falling.ini" --engine ode --theta-tol 1e-3 --quiet >/dev/null 2>"$work/quiet"
check '[ ! -s "$work/quiet" ]' "--quiet still told: $(head -3 "$work/quiet")"
exit $fail
