#!/bin/sh
# A test adapter (docs/adapters.md) in POSIX sh: it answers every "advance T"
# after sleeping $DV_SLOW_SLEEP s (1 unless set) with the start's pose at
# time T, at rest (every velocity 0: a still disk, its rows consistent).
# Slow, not faulty: each row takes the sleep, as a heavy engine's would.
# $DV_SLOW_SILENT set: it never answers (reads and sleeps), as a hung engine.
if [ "$1" = --version ]; then echo "slow 1 (a test adapter)"; exit 0; fi
dt=0.001
pos="0 0 0"
quat="1 0 0 0"
while read -r key a b c d; do
  case $key in
    set) [ "$a" = timestep ] && dt=$b ;;
    position) pos="$a $b $c" ;;
    quaternion) quat="$a $b $c $d" ;;
    start) break ;;
  esac
done
echo ready
nap=${DV_SLOW_SLEEP:-1}
while read -r key t rest; do
  [ "$key" = advance ] || continue
  sleep "$nap"
  [ -n "${DV_SLOW_SILENT:-}" ] && continue
  steps=$(awk -v t="$t" -v dt="$dt" 'BEGIN { printf "%d", t / dt + 0.5 }')
  echo "$t $pos $quat 0 0 0 0 0 0 1 $steps"
done
