#!/usr/bin/env bash
# check_signals_lock.sh DISKVAL SCENARIO_DIR: what a run leaves when it is stopped.
#   - compare ended by SIGINT, SIGTERM or SIGHUP, and by SIGINT under --timeout
#     (its run in a process of its own), dies of that signal and leaves
#     neither its temporary report directory nor the directory's lock file;
#   - a suite killed with SIGKILL leaves no worker behind and no lock: the
#     next run into the same --out goes ahead;
#   - simulate puts its CSV and its metadata into place while holding the
#     output's directory (flock), so two runs writing the same names never
#     leave one run's CSV beside the other's metadata: while another holder
#     has the directory, simulate has written neither file.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_signals_lock.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_signals_lock.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap '[ "$(ps -o comm= -p "${worker:-0}" 2>/dev/null)" = diskval ] && kill -KILL "$worker"; rm -rf "$work"' EXIT
cd "$work" || exit 2
set -m # background runs get SIGINT like a foreground one (no job control: ignored)

# the 60 s scene in MuJoCo takes 20 s: still running when the signal comes
long=$sc/hard/long_horizon.ini
# wait_for GLOB: until a path matches (at most 60 s: a busy machine)
wait_for() {
  for _ in $(seq 1200); do
    compgen -G "$1" >/dev/null && return 0
    sleep 0.05
  done
  return 1
}

for sig in INT TERM HUP INT/600; do
  limit=${sig#*/} sig=${sig%/*}
  [ "$limit" = "$sig" ] && limit=0
  "$dv" compare "$long" --engines mujoco --out "c$sig" --timeout "$limit" >/dev/null 2>&1 &
  pid=$!
  wait_for "c$sig/.*tmp.*" || echo "FAIL: compare made no temporary report directory"
  kill -"$sig" "$pid"
  wait "$pid"
  code=$?
  want=$((128 + $(kill -l "$sig")))
  check '[ $code -eq $want ]' "compare SIG$sig --timeout $limit: exit $code, want $want (died of the signal)"
  check '[ -z "$(ls -A "c$sig" | grep -v "^\.diskval-report$")" ]' \
    "compare SIG$sig --timeout $limit: left behind: $(ls -A "c$sig")"
  rm -rf "c$sig"
done

# a suite killed outright: its worker goes with it, and so does the lock
sed -e "s/^name = .*/name = fast/" -e "s/^duration = .*/duration = 0.5/" "$long" >fast.ini
# 600 s long (200 s of MuJoCo): a worker the kill missed would outlast the 60 s
# wait below (at 60 s, one did end by itself within it on a busy machine)
sed -e "s/^duration = .*/duration = 600/" "$long" >longer.ini
"$dv" suite longer.ini --engines mujoco --out s --jobs 1 >/dev/null 2>&1 &
pid=$!
# the worker's temporary, not the suite's own (made first: the glob "s/.*tmp.*"
# used before matched it, so the test waited on the dead suite, not the
# worker, and on a busy machine the next suite ran while the killed worker was
# not yet reaped: its temporary, rightly, not yet stale)
worker=
for _ in $(seq 1200); do # 60 s at most
  worker=$(compgen -G "s/.diskval-tmp.*" | sed -n 's/.*tmp\.\([0-9]*\)\..*/\1/p' | grep -vx "$pid" | head -1)
  [ -n "$worker" ] && break
  sleep 0.05
done
check '[ -n "$worker" ]' "the suite's worker made no temporary report directory: $(ls -A s)"
kill -KILL "$pid"
wait "$pid" 2>/dev/null
# gone and reaped, 60 s at most (its parent's death sends it SIGKILL at once;
# a busy machine delays only its end)
for _ in $(seq 1200); do kill -0 "${worker:-$pid}" 2>/dev/null || break; sleep 0.05; done
check '! kill -0 "${worker:-$pid}" 2>/dev/null' "SIGKILL: the suite's worker $worker outlived it by 60 s"
"$dv" suite fast.ini --engines mujoco --out s >stdout 2>stderr
code=$?
check '[ $code -eq 0 ]' "after SIGKILL: the next suite exits $code: $(cat stderr)"
check '[ -z "$(compgen -G "s/.diskval-tmp.*")" ]' "after SIGKILL: the dead run's temporaries remain"

# simulate's pair is committed under the directory's flock
mkdir -p pair
exec 9<pair
flock -x 9
"$dv" simulate "$sc/falling.ini" --engine reduced --out pair/a.csv 2>/dev/null 9<&- &
pid=$!
for _ in $(seq 40); do kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
check '[ ! -e pair/a.csv ] && [ ! -e pair/a.csv.json ] && kill -0 "$pid" 2>/dev/null' \
  "simulate committed while another held the directory"
exec 9<&-
wait "$pid"
code=$?
check '[ $code -eq 0 ] && [ -s pair/a.csv ] && [ -s pair/a.csv.json ]' \
  "simulate after the directory was released: exit $code"

[ $fail -eq 0 ] && echo "signals and locks: nothing left behind"
exit $fail
