#!/usr/bin/env bash
# bench_output.sh BEFORE AFTER SOURCE_DIR [PAIRS]: the cost of writing a
# fine-output trajectory CSV, two diskval builds compared. Both simulate the
# steady circle with the reduced engine for 20 s at output_dt 1e-4 (200001
# rows) into files; PAIRS runs of each (default 9), alternating which goes
# first. Prints the median wall times, their ratio (AFTER / BEFORE) and the
# ratio of the file sizes.
#
# bench_output.sh baseline DISKVAL PLAIN_GSL_DISK [PAIRS]: the reference at
# its defaults against a plain GSL rk8pd driver stepping onto every output
# (bench/plain_gsl_disk.c), at equal theta accuracy: 2000 s with output every
# 1 s, and 20 s every 1 ms (a uniform disk, theta 1, spin -12 rad/s).
set -u
if [ "${1:-}" = baseline ]; then
  exec bash "$(dirname "$0")/bench_output_baseline.sh" "${@:2}"
fi
before=$1 after=$2 src=$3 pairs=${4:-9}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run=(simulate "$src/scenarios/steady_circle.ini" --engine reduced --set scenario.output_dt=1e-4
     --set scenario.duration=20 --set engines.ode.timestep=1e-4 --set engines.mujoco.timestep=1e-4)
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk "BEGIN{print $t1 - $t0}"; }
median() { sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
: >"$work/b" && : >"$work/a"
for ((i = 0; i < pairs; i++)); do
  if ((i % 2)); then
    seconds "$after" "${run[@]}" --out "$work/after.csv" >>"$work/a"
    seconds "$before" "${run[@]}" --out "$work/before.csv" >>"$work/b"
  else
    seconds "$before" "${run[@]}" --out "$work/before.csv" >>"$work/b"
    seconds "$after" "${run[@]}" --out "$work/after.csv" >>"$work/a"
  fi
done
tb=$(median <"$work/b") ta=$(median <"$work/a")
sb=$(stat -c %s "$work/before.csv") sa=$(stat -c %s "$work/after.csv")
printf "median of %d runs: before %.3f s, after %.3f s, ratio %.3f\n" "$pairs" "$tb" "$ta" \
  "$(awk "BEGIN{print $ta / $tb}")"
printf "CSV: before %d bytes, after %d bytes, ratio %.4f (%d rows)\n" "$sb" "$sa" \
  "$(awk "BEGIN{print $sa / $sb}")" "$(($(wc -l <"$work/after.csv") - 1))"
