#!/usr/bin/env bash
# check_long_run.sh DISKVAL: an hour of simulated time in the reference and in
# MuJoCo keeps memory bounded: simulate streams its samples, so the peak RSS of
# a 1-hour run is within 20% of a 6-minute run's (and under 64 MiB).
# Measured: reference 8.6 MiB for both; MuJoCo 13 MiB for both.
set -u
command -v /usr/bin/time >/dev/null || { echo "SKIP: GNU time not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
peak() { # scenario duration engine [--set ...]: peak RSS in kB
  local d=$1 e=$2
  shift 2
  sed "s/^duration = .*/duration = $d/" "$work/long.ini" >"$work/run.ini"
  /usr/bin/time -f "%M" -o "$work/rss" "$diskval" simulate "$work/run.ini" --engine "$e" "$@" \
    --out /dev/null 2>/dev/null
  cat "$work/rss"
}
diskval=$1
cat >"$work/long.ini" <<'INI'
[scenario]
name = long_upright
duration = 3600
output_dt = 0.01
[disk]
radius = 0.1
mass = 1
[initial]
theta = 1.5707963267948966
theta_dot = 0.01
psi_dot = 8.577587
INI
fail=0
for e in reduced mujoco; do
  set=()
  [ "$e" = mujoco ] && set=(--set engines.mujoco.timestep=2e-3 --set engines.mujoco.solref_timeconst=4e-3)
  short=$(peak 360 "$e" "${set[@]}")
  long=$(peak 3600 "$e" "${set[@]}")
  echo "$e: peak RSS 6 min $short kB, 1 h $long kB"
  if [ "$long" -gt 65536 ] || [ "$long" -gt $((short * 12 / 10)) ]; then
    echo "FAIL: $e memory grows with the simulated time"
    fail=1
  fi
done
exit $fail
