#!/usr/bin/env bash
# check_adapter_children.sh DISKVAL JUDGE_TO_POSE SCENARIO ADAPTERS: every
# process an adapter starts ends with the run that started it (issue 49, item
# 7), and a manifest's timeout is bounded (item 8). The test adapter
# (tests/adapters/spawner: the replay adapter of check_adapter_faults.sh)
# starts `sleep 1001.TAG` in a session of its own (setsid: out of its process
# group) and `sleep 1000.TAG` in the background before it replays:
#   - after a passing compare (--jobs 1 and 2) or league neither is left;
#   - compare (--jobs 1 and 2) or league held at the adapter's start
#     (hangstart, which sleeps 1002.TAG) and ended by SIGINT, SIGTERM or
#     SIGKILL leaves none;
#   - the guard itself killed by the adapter (killguard: `kill -9 $PPID`),
#     stopped by it (stopguard: `kill -STOP $PPID`, the run replays on) or
#     killed from outside (SIGKILL, the adapter held at its start) leaves
#     none once the run has ended: its orphans land on the process that
#     started the guard (a subreaper), which kills them;
#   - a manifest's timeout of 600 s is taken, 600.5 s or 1e300 s refused with
#     the manifest's file, line and key.
# TAG is this script's pid: its sleeps are told from any other run's, and
# whatever is left is killed at the end (they are found by their argv).
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
to_pose=$2
scenario=$3
adapters=$4
work=$(mktemp -d)
tag=$$
leftovers() { pgrep -f "^sleep 100[012]\.$tag\$"; }
kill_leftovers() {
  local pids
  pids=$(leftovers)
  [ -z "$pids" ] || kill -9 $pids 2>/dev/null
}
trap 'kill_leftovers; rm -rf "$work"' EXIT

# alive PID: the process runs (a zombie, waiting for its parent, does not)
alive() { [ -e "/proc/$1" ] && ! grep -q ') Z ' "/proc/$1/stat" 2>/dev/null; }
# none_left WHAT: once every adapter's parent is gone (diskval's guard, which
# ends only when all its adapter started is gone; before, diskval or its job),
# no sleep of this run is left. Markers, not a time: 60 s is a hang's guard
# (measured: a SIGKILLed compare's guard ended 0.03 s after it)
none_left() {
  for p in $(sed -n 's/^parent //p' "$work/spawned" 2>/dev/null); do
    for _ in $(seq 600); do
      alive "$p" || break
      sleep 0.1
    done
  done
  check '[ -z "$(leftovers)" ]' \
    "$1: the adapter's children outlived its run: $(pgrep -af "^sleep 100[012]\.$tag\$" | tr '\n' ' ')"
  kill_leftovers
}

awk '/^\[disk\]/{print; print "thickness = 0.002"; next} {print}' "$scenario" >"$work/thick.ini"
"$diskval" simulate "$work/thick.ini" --engine matched --out "$work/ref.csv" --quiet ||
  { echo "FAIL: the matched reference did not run"; exit 1; }
"$to_pose" 0.1 0.001 <"$work/ref.csv" >"$work/pose.csv"
export DISKVAL_ADAPTERS=$adapters DV_REPLAY_POSE=$work/pose.csv DV_SPAWN_TAG=$tag \
  DV_SPAWN_LOG=$work/spawned DV_REPLAY_SLEEP=1002.$tag

# the runs: compare in one process and in two jobs, a league of the scene
runs=("compare --jobs 1" "compare --jobs 2" "league --jobs 2")
n=0 # each run its own --out: a league reuses the cells of its --out

# a passing run
for run in "${runs[@]}"; do
  rm -f "$work/spawned"
  n=$((n + 1))
  # 60 s: a hang's guard (measured: 0.2-0.6 s a run, 2 cores busy with a build)
  timeout -k 2 60 "$diskval" ${run%% *} "$work/thick.ini" --engines spawner ${run#* } \
    --out "$work/out$n" --quiet >"$work/stdout" 2>&1
  code=$?
  check '[ $code -eq 0 ] && grep -E -q "spawner .*(pass|reached 1 of 1)" "$work/stdout"' \
    "$run: the replay through the spawner passes: exit $code: $(cat "$work/stdout")"
  check '[ "$(grep -c "^child" "$work/spawned")" -ge 2 ]' "$run: the spawner started no child"
  none_left "a passing $run"
done

# a run ended by a signal while the adapter is held at its start
for sig in INT TERM KILL; do
  for run in "${runs[@]}"; do
    rm -f "$work/spawned"
    n=$((n + 1))
    # a background job ignores SIGINT unless told otherwise (bash without job control)
    DV_REPLAY_FAULT=hangstart env --default-signal=INT "$diskval" ${run%% *} "$work/thick.ini" \
      --engines spawner ${run#* } --out "$work/out$n" --quiet >/dev/null 2>&1 &
    pid=$!
    disown $pid # its death by a signal is this test's, not for bash to report
    # the three sleeps running (measured: 0.12 s after the start, 2 cores busy;
    # 30 s is the manifest's timeout, which would end the run)
    for _ in $(seq 300); do
      [ "$(leftovers | wc -l)" -ge 3 ] && break
      sleep 0.1
    done
    check '[ "$(leftovers | wc -l)" -ge 3 ]' "$run, SIG$sig: the spawner's children never ran"
    kill -s "$sig" $pid
    # diskval ends at once (measured: 0.02 s after SIGKILL); 20 s is a hang's guard
    for _ in $(seq 200); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
    check '! kill -0 $pid 2>/dev/null' "$run: SIG$sig did not end it (killed)"
    kill -9 $pid 2>/dev/null
    none_left "$run ended by SIG$sig"
  done
done

# the guard killed or stopped by its adapter
for mode in killguard stopguard; do
  for run in "${runs[@]}"; do
    rm -f "$work/spawned"
    n=$((n + 1))
    # 60 s: a hang's guard (measured: 0.2-0.6 s a run; before the fix a
    # stopped guard held each run 12 s, till its stop's SIGKILL)
    DV_SPAWN_MODE=$mode timeout -k 2 60 "$diskval" ${run%% *} "$work/thick.ini" \
      --engines spawner ${run#* } --out "$work/out$n" --quiet >"$work/stdout" 2>&1
    code=$?
    check '[ $code -ne 124 ] && [ $code -ne 137 ]' "$run, $mode: it hung (killed at 60 s)"
    check '[ "$(grep -c "^child" "$work/spawned")" -ge 2 ]' "$run, $mode: the spawner started no child"
    none_left "$run, $mode"
  done
done

# the guard killed from outside while the adapter is held at its start: the
# adapter dies with it (diskval may start it again: a new guard, new
# children), and what it started is gone while diskval still runs
for run in "${runs[@]}"; do
  rm -f "$work/spawned"
  n=$((n + 1))
  DV_REPLAY_FAULT=hangstart "$diskval" ${run%% *} "$work/thick.ini" --engines spawner ${run#* } \
    --out "$work/out$n" --quiet >/dev/null 2>&1 &
  pid=$!
  disown $pid # its death by SIGKILL is this test's
  for _ in $(seq 300); do # as above: the three sleeps running
    [ "$(leftovers | wc -l)" -ge 3 ] && break
    sleep 0.1
  done
  guard=$(sed -n 's/^parent //p' "$work/spawned" 2>/dev/null | head -n 1)
  kids=$(sed -n 's/^child //p' "$work/spawned" 2>/dev/null | head -n 2)
  check '[ -n "$guard" ] && [ "$(leftovers | wc -l)" -ge 3 ]' "$run, guard killed: the spawner's children never ran"
  [ -z "$guard" ] || kill -9 "$guard"
  # gone as diskval sees the guard's end (measured: 0.3 s); 20 s is a hang's guard
  for _ in $(seq 200); do
    left=
    for k in $kids; do alive "$k" && left="$left $k"; done
    [ -z "$left" ] && break
    sleep 0.1
  done
  check '[ -z "$left" ]' "$run, its guard killed from outside: its children outlived it:$left"
  kill -9 $pid 2>/dev/null # the rest: as for a SIGKILLed run, above
  none_left "$run, its guard killed from outside"
done

# a manifest's timeout: at most 600 s (the suite's default time limit)
for t in 600 600.5 1e300; do
  mkdir -p "$work/more/t$t"
  sed "s/^name = spawner/name = t${t//./_}/; s/^timeout = .*/timeout = $t/" \
    "$adapters/spawner/manifest.ini" >"$work/more/t$t/manifest.ini"
done
DISKVAL_ADAPTERS=$work/more "$diskval" engines >"$work/engines" 2>&1
line=$(grep -n '^timeout' "$adapters/spawner/manifest.ini" | cut -d: -f1)
check 'grep -q "^t600 " "$work/engines" && ! grep -q "t600/manifest.ini" "$work/engines"' \
  "a timeout of 600 s refused: $(grep t600 "$work/engines")"
for t in 600.5 1e300; do
  check 'grep -q "t$t/manifest.ini:$line: timeout: .*at most 600" "$work/engines"' \
    "a timeout of $t s taken, or refused without its file, line and key: $(grep "t$t" "$work/engines")"
done
exit $fail
