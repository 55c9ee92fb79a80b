#!/usr/bin/env bash
# check_map.sh DISKVAL: a small stability map of upright rolling in the
# reference agrees with the linear theory away from the boundary: every cell
# spinning at 1.5x the critical spin or more stays up, every cell at 0.5x or
# less does not; under mpirun (3 ranks, where installed) the map is the same.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(map --engines reduced --c 0.1..0.5:3 --spin 2..40:6 --duration 3)
"$1" "${args[@]}" --out "$work/serial" >/dev/null || { echo "FAIL: map"; exit 1; }
bad=$(awk -F, 'NR > 1 && (($4 >= 1.5 && $5 != "stays up") || ($4 <= 0.5 && $5 == "stays up"))' \
  "$work/serial/map.csv")
[ -z "$bad" ] || { echo "FAIL: cells against the theory:"; echo "$bad"; exit 1; }
[ -s "$work/serial/map_reduced.svg" ] || { echo "FAIL: no map_reduced.svg"; exit 1; }
if command -v mpirun >/dev/null && [ -z "${DV_TEST_NO_MPI:-}" ]; then
  . "$(dirname "$0")/mpi_run.sh"
  mpi_run 3 "$1" "${args[@]}" --out "$work/mpi" >/dev/null
  cmp -s "$work/serial/map.csv" "$work/mpi/map.csv" || { echo "FAIL: mpirun map differs"; exit 1; }
fi
echo "map: agrees with the linear theory"
