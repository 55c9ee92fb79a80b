#!/usr/bin/env bash
# check_map.sh DISKVAL: a small stability map of upright rolling in the
# reference agrees with the linear theory away from the boundary: every cell
# spinning at 1.5x the critical spin or more stays up, every cell at 0.5x or
# less does not; the disk comes from a scenario file (a US quarter); a disk
# that comes within 0.2 rad of the floor falls; the maps draw filled cells and
# an engine's map counts the cells that differ from the reference's; errors
# name the option typed; under mpirun (3 ranks, where installed) the map is
# the same.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(map --engines reduced --c 0.1..0.5:3 --spin 2..40:6 --duration 3)
"$1" "${args[@]}" --out "$work/serial" >/dev/null || { echo "FAIL: map"; exit 1; }
bad=$(awk -F, 'NR > 1 && (($4 >= 1.5 && $5 != "stays up") || ($4 <= 0.5 && $5 == "stays up"))' \
  "$work/serial/map.csv")
[ -z "$bad" ] || { echo "FAIL: cells against the theory:"; echo "$bad"; exit 1; }
[ -s "$work/serial/map_reduced.svg" ] || { echo "FAIL: no map_reduced.svg"; exit 1; }
# the disk comes from a scenario file: the quarter's critical spin at C = m r^2 / 2
# is 16.4757556 rad/s (diskval analyze tests/data/quarter.ini), so psi_dot / spin_ratio
# gives it back in the C / (m r^2) = 0.5 column (to the 6 digits spin_ratio is written with)
quarter=$(dirname "$0")/data/quarter.ini
"$1" map "$quarter" --engines reduced --c 0.25,0.5 --spin 5..80:5 --out "$work/quarter" >/dev/null ||
  { echo "FAIL: map $quarter"; exit 1; }
bad=$(awk -F, 'NR > 1 && $2 == 0.5 { w = $3 / $4 / 16.4757556; if (w < 1 - 1e-5 || w > 1 + 1e-5) print }' \
  "$work/quarter/map.csv")
[ -z "$bad" ] || { echo "FAIL: not the quarter's critical spin:"; echo "$bad"; exit 1; }
# a disk that comes within 0.2 rad of the floor has fallen, never "wobbles"
bad=$(awk -F, 'FNR > 1 && $6 >= 3.14159265 / 2 - 0.2 - 1e-9 && $5 != "falls"' "$work"/*/map.csv)
[ -z "$bad" ] || { echo "FAIL: near the floor but not a fall:"; echo "$bad"; exit 1; }
grep -q ',falls,' "$work/quarter/map.csv" || { echo "FAIL: no quarter cell falls"; exit 1; }
# cells, not dots: a filled rectangle per cell (10 cells, and the legend's boxes)
fills=$(grep -c 'fill-rule="nonzero"' "$work/quarter/map_reduced.svg")
[ "$fills" -ge 10 ] || { echo "FAIL: $fills filled shapes for 10 cells"; exit 1; }
# an engine's map marks the cells whose outcome is not the reference's: the
# differs column says so, cell by cell, and the title counts them
"$1" map "$quarter" --engines reduced,ode --c 0.25,0.5 --spin 5..80:3 --duration 0.5 \
  --out "$work/ode" >/dev/null || { echo "FAIL: map with ode"; exit 1; }
bad=$(awk -F, 'NR > 1 && $1 == "reduced" { ref[$2 "," $3] = $5 }
  NR > 1 && $1 == "ode" && $7 != ($5 != ref[$2 "," $3]) { print }' "$work/ode/map.csv")
[ -z "$bad" ] || { echo "FAIL: differs is not outcome != reference:"; echo "$bad"; exit 1; }
n=$(awk -F, '$1 == "ode" && $7 == 1' "$work/ode/map.csv" | wc -l)
perl -CS -pe 's/&#x([0-9a-f]+);/chr(hex($1))/gie' "$work/ode/map_ode.svg" | grep -q "($n of 6 cells differ)" ||
  { echo "FAIL: map_ode.svg does not count the $n cells that differ"; exit 1; }
# errors name the option typed, exit 2
for opt in "--c 0.1..x" "--c 0.7" "--spin -1,2" "--spin ''"; do
  msg=$(eval "\"$1\" map $opt" 2>&1 >/dev/null)
  [ $? -eq 2 ] && [[ $msg == *"${opt%% *} "* ]] && [[ $msg != *--vary* ]] ||
    { echo "FAIL: map $opt: '$msg'"; exit 1; }
done
"$1" map "$work/none.ini" >/dev/null 2>&1; [ $? -eq 2 ] || { echo "FAIL: a missing file"; exit 1; }
if command -v mpirun >/dev/null && [ -z "${DV_TEST_NO_MPI:-}" ]; then
  . "$(dirname "$0")/mpi_run.sh"
  mpi_run 3 "$1" "${args[@]}" --out "$work/mpi" >/dev/null
  cmp -s "$work/serial/map.csv" "$work/mpi/map.csv" || { echo "FAIL: mpirun map differs"; exit 1; }
fi
echo "map: agrees with the linear theory; the quarter, the floor band, cells, differences, messages"
