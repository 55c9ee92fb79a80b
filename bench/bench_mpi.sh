#!/usr/bin/env bash
# bench_mpi.sh DISKVAL SOURCE_DIR: parallel efficiency of an MPI sweep at 1, 2,
# 3 and 4 ranks on this machine, against the serial sweep (--jobs 1). Rank 0
# hands out the points and computes none, so N ranks give N - 1 workers; on 2
# cores the curve flattens past 3 ranks. Prints wall times and ratios.
set -u
command -v mpirun >/dev/null || { echo "mpirun not installed: skipped"; exit 0; }
diskval=$1 src=$2
. "$src/tests/mpi_run.sh"
mpi_scratch
sweep=(sweep "$src/tests/data/short_circle.ini" --engine mujoco --vary timestep=1e-3..1e-4:16)
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk "BEGIN{print $t1 - $t0}"; }
serial=$(seconds "$diskval" "${sweep[@]}" --out "$work/s" --jobs 1)
printf "serial sweep (16 points, 1 process): %.2f s\n" "$serial"
for np in 1 2 3 4; do
  t=$(seconds mpi_run "$np" "$diskval" "${sweep[@]}" --out "$work/m$np")
  workers=$((np > 1 ? np - 1 : 1))
  printf "mpirun -np %d: %.2f s, %.2fx the serial time, efficiency %.0f%% per worker\n" "$np" "$t" \
    "$(awk "BEGIN{print $t / $serial}")" "$(awk "BEGIN{print 100 * $serial / $t / $workers}")"
done
