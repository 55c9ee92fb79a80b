#!/usr/bin/env bash
# bench_harness.sh DISKVAL BARE_MUJOCO BARE_ODE SOURCE_DIR [PAIRS]: what the
# harness adds to a contact engine's run. `diskval simulate --engine E` against
# a bare loop of the same library (bench/bare_mujoco.c, bench/bare_ode.c: the
# model the engine builds, the same steps, the same CSV, checked byte for
# byte) on the steady circle at its own settings (5 s); PAIRS (default 7) pairs of runs in this process
# tree, alternating which goes first. Prints the median of the pairs' ratios
# (diskval / bare) per engine; the goal is <= 1.03.
set -u
diskval=$1 bare_mujoco=$2 bare_ode=$3 src=$4 pairs=${5:-7}
scene="$src/scenarios/steady_circle.ini"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk "BEGIN{print $t1 - $t0}"; }
median() { sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# bench_engine ENGINE BARE
bench_engine() {
  local engine=$1 bare=$2
  run_diskval() { "$diskval" simulate "$scene" --engine "$engine" --out "$work/diskval.csv"; }
  run_bare() { "$bare" "$scene" "$work/bare.csv"; }
  run_diskval && run_bare || { echo "$engine: a run failed"; return 1; }
  local same=no
  cmp -s "$work/diskval.csv" "$work/bare.csv" && same=yes
  : >"$work/ratios" && : >"$work/td" && : >"$work/tb"
  for ((i = 0; i < pairs; i++)); do
    local td tb
    if ((i % 2)); then
      tb=$(seconds run_bare) td=$(seconds run_diskval)
    else
      td=$(seconds run_diskval) tb=$(seconds run_bare)
    fi
    echo "$td" >>"$work/td" && echo "$tb" >>"$work/tb"
    awk "BEGIN{print $td / $tb}" >>"$work/ratios"
  done
  printf "%-6s steady circle (same CSV: %s): median diskval %.3f s, bare %.3f s; median ratio of %d pairs %.3f (goal <= 1.03)\n" \
    "$engine" "$same" "$(median <"$work/td")" "$(median <"$work/tb")" "$pairs" \
    "$(median <"$work/ratios")"
}

bench_engine mujoco "$bare_mujoco"
bench_engine ode "$bare_ode"
