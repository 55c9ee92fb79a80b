#!/usr/bin/env bash
# check_read_once.sh DISKVAL DATA_DIR: the scenario is read once, before
# anything runs, by every command that runs it many times (issue 23, items 8
# and 12):
#   - a sweep whose file is edited while its first point runs gives the
#     points of the file as it was (the same metrics as an unedited sweep);
#   - a FIFO as the scenario works for sweep, best, attribute, verify and
#     suite --verify/--stability (a second read would block or see nothing).
# Markers, not sleeps: the sweep runs its points in child processes, which
# start once the command has read its file.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_read_once.sh DISKVAL DATA_DIR}
data=${2:?usage: check_read_once.sh DISKVAL DATA_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2

# children PID: the pids of PID's child processes, one a line
children() { pgrep -P "$1" | sort; }
# the points without their timing (wall_per_sim_s, pareto)
points() { jq -c '.points[] | del(.wall_per_sim_s, .pareto)' "$1/sweep.json"; }

# three points, one at a time: 5e-6 (about 1.4 s: the edit, 0.1 s after its process
# exists, lands while it runs; 1e-6 took 7 s for the same), 2e-3, 1e-3; the file is
# edited once the first runs (its process exists: diskval has loaded it)
vary=(--engine mujoco --vary timestep=5e-6,2e-3,1e-3 --jobs 1 --quiet)
cp "$data/short_circle.ini" same.ini
"$dv" sweep same.ini "${vary[@]}" --out unedited >/dev/null 2>&1
cp "$data/short_circle.ini" edited.ini
"$dv" sweep edited.ini "${vary[@]}" --out edited >/dev/null 2>err &
pid=$!
for _ in $(seq 600); do # 60 s at most
  [ -n "$(children $pid)" ] && break
  sleep 0.1
done
sed -i 's/^theta = 1.0$/theta = 1.2/' edited.ini
grep -q '^theta = 1.2$' edited.ini || echo "FAIL: the edit did not take"
wait $pid
code=$?
check '[ $code -eq 0 ]' "edited: exit $code: $(cat err)"
check '[ "$(points unedited)" = "$(points edited)" ]' \
  "edited: points after the edit came from the edited file: $(diff <(points unedited) <(points edited))"

# a FIFO written once (TIMEOUT s at most: a command that opens it again blocks)
fifo() {
  rm -f pipe.ini
  mkfifo pipe.ini
  (cat "$data/short_circle.ini" >pipe.ini &)
}
run() { # run WHAT ARGS...: diskval ARGS on the FIFO over 0.3 s of the scene, 120 s at most
  local what=$1
  shift
  fifo
  timeout 120 "$dv" "$@" --set scenario.duration=0.3 >out 2>err
  local code=$?
  check '[ $code -eq 0 ] || [ $code -eq 1 ]' "FIFO, $what: exit $code: $(head -3 err)"
  check '! grep -q "missing section" err' "FIFO, $what: read twice: $(head -3 err)"
  rm -f pipe.ini # no writer left behind
}
run sweep sweep pipe.ini --engine mujoco --vary timestep=2e-3,1e-3 --out fifo_sweep --quiet
check '[ "$(jq ".points | length" fifo_sweep/sweep.json 2>/dev/null)" = 2 ]' "FIFO, sweep: no sweep.json"
run best best pipe.ini --engine reduced --theta-tol 1e-6 --quiet
run attribute attribute pipe.ini --engine mujoco --quiet
run verify verify pipe.ini --engines mujoco --quiet
run "suite --verify" suite pipe.ini --verify --engines mujoco --out fifo_verify --quiet
run "suite --stability" suite pipe.ini --stability --engines mujoco --out fifo_stab --quiet
check '[ -s fifo_stab/stability.json ]' "FIFO, suite --stability: no stability.json"

[ $fail -eq 0 ] && echo "read once: an edited file and a FIFO give the scenario as first read"
exit $fail
