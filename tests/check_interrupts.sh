#!/usr/bin/env bash
# check_interrupts.sh DISKVAL SCENARIO_DIR DATA_DIR: what an interrupted run
# leaves (issue 23, items 7 and 9):
#   - a suite interrupted after one scenario ended (and failed) exits 130 and
#     its summary.json, junit.xml and index.html describe this run: the
#     failure, and the scenario that did not end as an error saying so, never
#     the previous run's pass;
#     slow's own report (OUT/slow/report.json) says so too, never the
#     previous run's pass;
#   - SIGHUP stops a suite as SIGINT does (exit 130, no worker's temporary,
#     summary.json of this run); it killed the suite (129), its workers'
#     .diskval-tmp.* and the previous summary.json staying;
#   - SIGTERM before any scenario ran (the suite still reading its scenario,
#     a FIFO) exits 130 with a line, as later, and writes nothing: it died of
#     the signal (143) without a word;
#   - a sweep interrupted after its first point exits 130 and writes every
#     point: the one that ran with its metrics, the others with their
#     settings, NaN (null) metrics and steps, "missing".
# Markers, not sleeps: a scenario or point runs in a child process of
# diskval; one ended when its child is gone (pgrep -P), and a report says so.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_interrupts.sh DISKVAL SCENARIO_DIR DATA_DIR}
sc=${2:?usage: check_interrupts.sh DISKVAL SCENARIO_DIR DATA_DIR}
data=${3:?usage: check_interrupts.sh DISKVAL SCENARIO_DIR DATA_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2

# wait_for COND: until COND holds, 60 s at most
wait_for() {
  for _ in $(seq 600); do
    eval "$1" && return 0
    sleep 0.1
  done
  echo "FAIL: waited 60 s for: $1"
  fail=1
  return 1
}
nchildren() { pgrep -P "$1" | wc -l; }
# summary FIELD NAME: the scenario's FIELD in summary.json
summary() {
  jq -r --arg f "$1" --arg n "$2" '.scenarios[] | select(.scenario == $n) | .[$f]' out/summary.json
}

# a passing run of fast and slow (1 s each)
cp "$data/short_circle.ini" fast.ini
sed -e "s/^name = .*/name = slow/" -e "s/^duration = .*/duration = 1/" \
  "$sc/hard/long_horizon.ini" >slow.ini
# MuJoCo alone: the interruption is the suite's, not an engine's (fast's failure is
# attributed per engine: five engines under the sanitizers took over the 60 s wait)
"$dv" suite fast.ini slow.ini --engines mujoco --out out --jobs 2 --quiet >/dev/null 2>&1
check '[ "$(jq -r .pass out/summary.json)" = true ]' "first run: not a pass: $(cat out/summary.json)"
# then fast fails a limit at once and slow takes 60 s (over 20 s of MuJoCo)
printf '\n[tolerance]\ntheta_max_err = 1e-15\n' >>fast.ini
sed -i "s/^duration = .*/duration = 60/" slow.ini
"$dv" suite fast.ini slow.ini --engines mujoco --out out --jobs 2 --quiet >stdout 2>stderr &
pid=$!
# fast has ended: its report says fail and diskval has only slow's process left
wait_for '[ "$(jq -r .pass out/short_circle/report.json 2>/dev/null)" = false ] &&
  [ "$(nchildren $pid)" -eq 1 ]'
kill -INT $pid
wait $pid
code=$?
why="did not end: the suite was interrupted"
check '[ $code -eq 130 ]' "suite: exit $code, want 130: $(cat stderr)"
check '[ "$(jq -r .pass out/summary.json)" = false ]' "suite: summary.json still says pass"
check '[ "$(summary pass short_circle)" = false ] && [ "$(summary error short_circle)" = null ]' \
  "suite: summary.json: the failure of the scenario that ended is not there"
check '[ "$(summary pass slow)" = false ] && [ "$(summary error slow)" = "$why" ]' \
  "suite: summary.json: slow: pass $(summary pass slow), error $(summary error slow)"
check 'grep -q "<failure" out/junit.xml && grep -q "<error message=\"$why\"" out/junit.xml' \
  "suite: junit.xml does not say which failed and which did not end"
check 'grep -q "$why" out/index.html && grep -q "diskval suite: <span class=\"fail\">FAIL" out/index.html' \
  "suite: index.html does not describe this run"
check '[ -z "$(find out -name ".diskval-tmp*" -o -name "*.tmp.*")" ]' "suite: temporaries remain"
check '[ "$(jq -r .pass out/slow/report.json)" = false ] &&
  [ "$(jq -r .error out/slow/report.json)" = "$why" ]' \
  "suite: out/slow/report.json is not this run's: $(jq -c '{pass, error}' out/slow/report.json)"

# SIGHUP while slow runs (its worker's temporary directory is there)
"$dv" suite slow.ini --engines mujoco --out out --jobs 1 --quiet >stdout 2>stderr &
pid=$!
wait_for 'compgen -G "out/.diskval-tmp.*" >/dev/null'
kill -HUP $pid
wait $pid
code=$?
check '[ $code -eq 130 ]' "suite SIGHUP: exit $code, want 130: $(cat stderr)"
check 'grep -q "interrupted" stderr' "suite SIGHUP: stderr does not say so: $(cat stderr)"
check '[ -z "$(find out -name ".diskval-tmp*")" ]' "suite SIGHUP: temporaries remain: $(ls -A out)"
check '[ "$(jq -c "[.scenarios[].scenario]" out/summary.json)" = "[\"slow\"]" ] &&
  [ "$(summary error slow)" = "$why" ]' "suite SIGHUP: summary.json is not this run's: $(cat out/summary.json)"

# SIGTERM while the suite still reads its scenario: a FIFO that this shell
# holds open as a writer, fed once the signal is sent
mkfifo early.ini
exec 3<>early.ini
"$dv" suite early.ini --engines mujoco --out early --quiet >stdout 2>stderr 3<&- &
pid=$!
wait_for 'readlink /proc/$pid/fd/* 2>/dev/null | grep -q "/early.ini$"'
kill -TERM $pid
cat fast.ini >&3
exec 3>&-
wait $pid
code=$?
check '[ $code -eq 130 ]' "suite SIGTERM early: exit $code, want 130: $(cat stderr)"
check '[ "$(cat stderr)" = "diskval suite: interrupted before any scenario ran: nothing written" ]' \
  "suite SIGTERM early: stderr: $(cat stderr)"
check '[ ! -e early ]' "suite SIGTERM early: wrote $(ls -A early 2>/dev/null)"

# a sweep: 2e-3 (0.01 s), then 1e-6 (about 7 s) and 5e-7 (14 s), one at a time
"$dv" sweep "$data/short_circle.ini" --engine mujoco --vary timestep=2e-3,1e-6,5e-7 --jobs 1 \
  --out sweep --quiet >stdout 2>stderr &
pid=$!
first=
wait_for 'now=$(pgrep -P $pid | head -1); [ -z "$first" ] && first=$now;
  [ -n "$now" ] && [ "$now" != "$first" ]' # a point's process is gone: one ended
kill -INT $pid
wait $pid
code=$?
check '[ $code -eq 130 ]' "sweep: exit $code, want 130: $(cat stderr)"
check 'grep -q "interrupted" stderr' "sweep: stderr does not say so: $(cat stderr)"
# every point keeps its settings; one that ran has its metrics, one that did
# not (at least the last: it takes 14 s) has none: null in sweep.json, nan in
# sweep.csv, "missing"
ran='select(.outcome != "missing") | (.theta_max_err > 0) and (.steps > 0)'
unrun='select(.outcome == "missing") | [.theta_max_err, .path_max_err, .steps] == [null, null, null]'
check '[ "$(jq -c "[.points[].settings[]]" sweep/sweep.json)" = "[\"2e-3\",\"1e-6\",\"5e-7\"]" ]' \
  "sweep: the settings are not kept: $(jq -c "[.points[].settings]" sweep/sweep.json)"
check '[ "$(jq "[.points[] | $ran] | length, all" sweep/sweep.json | tr "\n" " ")" != "0 true " ] &&
  [ "$(jq "[.points[] | $ran] | all" sweep/sweep.json)" = true ]' \
  "sweep: no point that ran, or one without its metrics: $(jq -c .points sweep/sweep.json)"
check '[ "$(jq "[.points[] | $unrun] | length" sweep/sweep.json)" -ge 1 ] &&
  [ "$(jq "[.points[] | $unrun] | all" sweep/sweep.json)" = true ]' \
  "sweep: a point not run has metrics: $(jq -c .points sweep/sweep.json)"
check 'grep -q "^mujoco,5e-7,nan,nan,.*,nan,missing,0$" sweep/sweep.csv' \
  "sweep: sweep.csv: $(tail -1 sweep/sweep.csv)"

[ $fail -eq 0 ] && echo "interrupts: suite and sweep files describe the run that was stopped"
exit $fail
