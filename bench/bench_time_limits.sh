#!/usr/bin/env bash
# bench_time_limits.sh DISKVAL ROOT: how soon --timeout ends work, as the wall
# time past the limit, measured in this run: a suite whose second scenario
# (the 60 s long_horizon scene in MuJoCo, 20 s alone) runs under --timeout 5,
# and compare and simulate of that scene under a limit of 0.6x their own
# estimate (so they start and are cut; a refusal is printed as such). Target:
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
    return
  fi
  awk -v l="$label" -v t="$took" -v s="$limit" -v ok="$(grep -c "timed out after $limit s" "$work/err")" \
    'BEGIN { printf "%-28s %.1f s under --timeout %g: %.1f s past it, target 3 s: %s\n", l, t, s, t - s,
             (ok > 0 && t - s <= 3) ? "PASS" : "FAIL" }'
}
over "suite, one scenario slow" "$diskval" suite "$work/fast.ini" "$long" --engines mujoco --jobs 2 \
  --out "$work/s" --timeout "$limit"
# a limit of 0.6x the command's own estimate (refused over 2x: it starts, and is cut)
for cmd in "compare --engines" "simulate --engine"; do
  set -- $cmd
  est=$("$diskval" "$1" "$long" "$2" mujoco --out "$work/e" --timeout 1e-3 2>&1 |
    sed -n 's/.*would take about \([0-9.e+]*\) s.*/\1/p')
  limit=$(awk -v e="${est:-10}" 'BEGIN { printf "%.2f", e * 0.6 }' | sed 's/0*$//; s/\.$//')
  over "$1 mujoco" "$diskval" "$1" "$long" "$2" mujoco --out "$work/$1.out" --timeout "$limit"
done
