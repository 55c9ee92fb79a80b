#!/usr/bin/env bash
# bench_time_limits.sh DISKVAL ROOT: how soon --timeout ends work, as the wall
# time past the limit, measured in this run: a suite whose second scenario
# (the 60 s long_horizon scene in MuJoCo, 20 s alone) runs under --timeout 5,
# and compare and simulate of that scene under a limit of 0.65x their own
# estimate, so they start and are cut: the estimate ran 1.3x over the run
# (17.3 s for 13.1 s), and one estimate to the next varied 1.2-1.4x, so a run
# refused (the next estimate over 2x the limit) or ended inside its limit is
# tried again, three times at most, and printed as such. Target:
# the command over within 3 s of its limit, each line PASS or FAIL. The wall times were asserted by
# suite_faults and timeout until issue 40; a busy machine moves them, so the
# tests now check the messages and tests/exec/test_exec.c checks the pool's kill
# with a child that sleeps.
set -u
diskval=$1 root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
long=$root/scenarios/hard/long_horizon.ini
sed -e 's/^name = .*/name = fast/' -e 's/^duration = .*/duration = 1/' "$long" >"$work/fast.ini"
limit=5
# over LABEL CMD...: CMD's wall time past $limit s, target 3 s
over() {
  local label=$1 began took
  shift
  began=$(date +%s.%N)
  "$@" >/dev/null 2>"$work/err"
  took=$(awk -v a="$began" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  if grep -q "not started" "$work/err"; then
    printf "%-28s refused up front (%s)\n" "$label" "$(head -c 160 "$work/err")"
    return 1
  fi
  if ! grep -q "timed out after" "$work/err"; then
    printf "%-28s ended inside its limit of %g s, in %.1f s: no cut measured\n" "$label" "$limit" "$took"
    return 1
  fi
  awk -v l="$label" -v t="$took" -v s="$limit" -v ok="$(grep -c "timed out after $limit s" "$work/err")" \
    'BEGIN { printf "%-28s %.1f s under --timeout %g: %.1f s past it, target 3 s: %s\n", l, t, s, t - s,
             (ok > 0 && t - s <= 3) ? "PASS" : "FAIL" }'
}
over "suite, one scenario slow" "$diskval" suite "$work/fast.ini" "$long" --engines mujoco --jobs 2 \
  --out "$work/s" --timeout "$limit"
# a limit of 0.65x the command's own estimate (refused over 2x: it starts, and is cut);
# each estimate written to its own --out (simulate's, given compare's directory, failed)
for cmd in "compare --engines" "simulate --engine"; do
  set -- $cmd
  for try in 1 2 3; do
    est=$("$diskval" "$1" "$long" "$2" mujoco --out "$work/e.$1" --timeout 1e-3 2>&1 |
      sed -n 's/.*would take about \([0-9.e+]*\) s.*/\1/p')
    limit=$(awk -v e="${est:-10}" 'BEGIN { printf "%.2f", e * 0.65 }' | sed 's/0*$//; s/\.$//')
    over "$1 mujoco" "$diskval" "$1" "$long" "$2" mujoco --out "$work/$1.out" --timeout "$limit" && break
    rm -rf "$work/$1.out"
  done
done
