#!/usr/bin/env bash
# check_mpi.sh DISKVAL SOURCE_DIR: under mpirun with 3 ranks, a sweep and a
# suite write the same files as serial runs, apart from timing (wall_per_sim_s
# and the Pareto flag that depends on it). Skipped (77) without mpirun.
set -u
command -v mpirun >/dev/null || { echo "SKIP: mpirun not installed"; exit 77; }
diskval=$1 src=$2
. "$src/tests/mpi_run.sh"
mpi_scratch
mpi() { mpi_run 3 "$diskval" "$@"; }
fail=0
# the scenes cut to 0.3 s: 5 points and 3 scenes over 3 ranks are what the split shows
short=(--set scenario.duration=0.3)
sweep=(sweep "$src/tests/data/short_circle.ini" --engine ode --vary timestep=8e-5..1e-5:5 "${short[@]}")
mpi "${sweep[@]}" --out "$work/mpi" >/dev/null || { echo "FAIL: mpirun sweep"; fail=1; }
"$diskval" "${sweep[@]}" --out "$work/serial" --jobs 1 >/dev/null
# drop the columns wall_per_sim_s and pareto, found by name
untimed() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) drop[i] = $i == "wall_per_sim_s" || $i == "pareto" }
           { line = ""; for (i = 1; i <= NF; i++) if (!drop[i]) line = line "," $i; print line }' "$1"
}
if ! cmp -s <(untimed "$work/mpi/sweep.csv") <(untimed "$work/serial/sweep.csv"); then
  echo "FAIL: sweep.csv differs between mpirun and serial"
  diff <(untimed "$work/mpi/sweep.csv") <(untimed "$work/serial/sweep.csv") | head
  fail=1
fi
suite=(suite "$src/scenarios/falling.ini" "$src/scenarios/upright_stable.ini" "$src/scenarios/small_c.ini"
  "${short[@]}")
# exit 1 is a tolerance failed (ODE over falling's first 0.3 s): the reports still compare
mpi "${suite[@]}" --out "$work/mpi_suite" >/dev/null
code=$?
[ $code -le 1 ] || { echo "FAIL: mpirun suite: exit $code"; fail=1; }
"$diskval" "${suite[@]}" --out "$work/serial_suite" --jobs 1 >/dev/null
for f in "$work"/serial_suite/*/report.json; do
  rel=${f#"$work/serial_suite/"}
  cmp -s <(grep -vE '"(horizon_)?wall_(s|per_sim_s)"' "$f") \
    <(grep -vE '"(horizon_)?wall_(s|per_sim_s)"' "$work/mpi_suite/$rel") ||
    { echo "FAIL: $rel differs"; fail=1; }
done
[ $fail -eq 0 ] && echo "mpi: identical to serial apart from timing"
exit $fail
