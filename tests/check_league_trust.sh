#!/usr/bin/env bash
# check_league_trust.sh DISKVAL SOURCE_DIR: a league claims only what its
# backing compares say, overwrites none of its inputs, and ends when told
# (issue 49, items 2, 3, 5, 8, 10, 11).
#   - a cell is reached only when its backing compare passes, judged: a window
#     too short to judge, or an energy drift over its limit, backs no reached
#     cell (an energy limit above the drift still does)
#   - a cached cell is reused only when its claims are its report's and its
#     report lies in --out: an edited cell, one whose report is elsewhere (or
#     linked out of --out or its compare/), or one whose limit is not its target,
#     runs again
#   - an input in --out's cells/ or compare/ is refused, nothing written
#   - --timeout ends a pair of object and engine that takes longer: its cells
#     are errors that say so (exit 1)
#   - a --set of a key the league gives each cell (a step or choice the search
#     varies, the theta limit) is refused in one line; another --set is applied
#     and listed in league.md
#   - a league stopped by SIGTERM lists the cells it finished as what they
#     were, not "not run"
# The objects are the quick set's quarter fall (1.5 s a league of MuJoCo and
# ODE) and the tests' thick coin. Exit status: 0 as expected, 1 a difference,
# 77 skipped (no jq).
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1 src=$2
command -v jq >/dev/null || { echo "jq is not installed: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
quarter=$work/quarter_fall.ini coin=$work/euro_coin.ini
cp "$src/league/quarter_fall.ini" "$quarter"
cp "$src/tests/data/euro_coin.ini" "$coin"
league() { "$diskval" league "$quarter" --engines mujoco,ode --cause none --quiet "$@"; }
cells() { jq -c '[.cells[] | [.engine, .outcome, .verdict, .why]]' "$1/league.json"; }

# item 2: reached only when the backing compare passes, judged
league --out "$work/L" >/dev/null 2>"$work/err"
code=$?
check '[ $code -eq 0 ]' "the quarter's league: exit $code: $(cat "$work/err")"
# measured: both cells reached, their compares pass (theta 5.0e-4 and 3.8e-4 rad of 1e-3)
check 'jq -e "[.cells[] | select(.reached and .verdict == \"pass\")] | length == 2" "$work/L/league.json" >/dev/null' \
  "the quarter's league: $(cells "$work/L")"
# a window of 0.02 s is too short to judge (5 samples, 10 needed): nothing is reached
league --out "$work/S" --set scenario.duration=0.02 >/dev/null 2>&1
check 'jq -e "([.cells[] | select(.reached or .verdict != \"not judged\" or (.why | startswith(\"not judged\") | not))]
  | length == 0) and (.cells | length == 2)" "$work/S/league.json" >/dev/null' \
  "a window of 0.02 s: $(cells "$work/S")"
check '[ "$(awk -F, "NR > 1 && \$8 == \"true\"" "$work/S/league.csv" | wc -l)" -eq 0 ]' \
  "a window of 0.02 s: league.csv says reached"
# the energy drift at the cells' settings, measured: 4.9e-4 (MuJoCo), 2.8e-4 (ODE) of
# E(0); a limit of 1e-4 fails both compares, one of 1e-3 passes both (the search's
# settings do not depend on it: theta and path alone steer it)
league --out "$work/E" --set tolerance.energy_drift=1e-4 >/dev/null 2>&1
check 'jq -e "([.cells[] | select(.reached or .verdict != \"fail\" or (.why | startswith(\"fails: energy_drift\") | not))]
  | length == 0) and (.cells | length == 2)" "$work/E/league.json" >/dev/null' \
  "an energy limit below the drift: $(cells "$work/E")"
league --out "$work/F" --set tolerance.energy_drift=1e-3 >/dev/null 2>&1
check 'jq -e "[.cells[] | select(.reached and .verdict == \"pass\")] | length == 2" "$work/F/league.json" >/dev/null' \
  "an energy limit above the drift: $(cells "$work/F")"
# item 10: that --set is applied, and league.md says so
check 'grep -qF "Every cell ran with --set tolerance.energy\_drift=1e-3." "$work/F/league.md"' \
  "league.md does not list the --set applied"

# item 3: a cached cell is reused only when its claims are its report's
cell=cells/quarter_fall--mujoco--0.001.json
theta=$(jq .theta_max_err "$work/L/$cell")
cp -r "$work/L" "$work/C1"
jq '.theta_max_err = 1e-7' "$work/L/$cell" >"$work/C1/$cell"
league --out "$work/C1" >/dev/null 2>&1
check '[ "$(jq ".cells[0].theta_max_err" "$work/C1/league.json")" = "$theta" ]' \
  "an edited cell's theta 1e-7 was reused: $(jq -c ".cells[0] | [.theta_max_err, .report]" "$work/C1/league.json")"
# a not-reached cell said reached (the energy league's) runs again, and is not reached
cp -r "$work/E" "$work/C2"
jq '.outcome = "reached" | .reached = true | .why = ""' "$work/E/$cell" >"$work/C2/$cell"
"$diskval" league "$quarter" --engines mujoco,ode --cause none --out "$work/C2" \
  --set tolerance.energy_drift=1e-4 >/dev/null 2>"$work/err"
check 'jq -e ".cells[0].reached | not" "$work/C2/league.json" >/dev/null && grep -q "run again" "$work/err"' \
  "a cell edited to reached: $(jq -c ".cells[0] | [.outcome, .why]" "$work/C2/league.json"): $(cat "$work/err")"
# a cell whose report lies outside --out (a copy there that says theta 1e-7) runs again
mkdir -p "$work/elsewhere"
cp -r "$work/L/compare" "$work/elsewhere/"
report=compare/quarter_fall/mujoco-0.001/quarter_fall
jq '.engines.mujoco.theta_max_err = 1e-7' "$work/L/$report/report.json" >"$work/elsewhere/$report/report.json"
cp -r "$work/L" "$work/C3"
jq --arg r "../elsewhere/$report" '.theta_max_err = 1e-7 | .report = $r' "$work/L/$cell" >"$work/C3/$cell"
league --out "$work/C3" >/dev/null 2>&1
check 'jq -e --arg r "$report" ".cells[0] | .report == \$r and .theta_max_err == $theta" "$work/C3/league.json" >/dev/null' \
  "a cell whose report is outside --out was reused: $(jq -c ".cells[0] | [.theta_max_err, .report]" "$work/C3/league.json")"
# rerun DIR WHY WHAT: the league over --out DIR runs its doctored cell again (theta the
# run's own, not 1e-7) and says why on stderr (not --quiet: a progress line)
rerun() {
  local d=$work/$1 why=$2
  "$diskval" league "$quarter" --engines mujoco,ode --cause none --out "$d" >/dev/null 2>"$work/err"
  check 'jq -e ".cells[0].theta_max_err == $theta" "$d/league.json" >/dev/null && grep -q "run again: $why" "$work/err"' \
    "$3: $(jq -c ".cells[0] | [.theta_max_err, .report]" "$d/league.json"): $(cat "$work/err")"
}
# its report's path as the cell says, through a link: compare/ itself a link out of --out
# (to a copy whose report says theta 1e-7, as the cell does) runs again
cp -r "$work/L" "$work/C4"
mkdir -p "$work/away"
mv "$work/C4/compare" "$work/away/compare"
ln -s ../away/compare "$work/C4/compare"
jq '.engines.mujoco.theta_max_err = 1e-7' "$work/L/$report/report.json" >"$work/away/$report/report.json"
jq '.theta_max_err = 1e-7' "$work/L/$cell" >"$work/C4/$cell"
rerun C4 "its report lies outside" "a cell whose compare/ links out of --out"
# a folder in compare/ a link to one in --out but not in its compare/ (its report says
# theta 1e-7, as the cell does) runs again
cp -r "$work/L" "$work/C5"
mv "$work/C5/compare/quarter_fall" "$work/C5/decoy"
ln -s ../decoy "$work/C5/compare/quarter_fall"
jq '.engines.mujoco.theta_max_err = 1e-7' "$work/L/$report/report.json" \
  >"$work/C5/decoy/${report#compare/quarter_fall/}/report.json"
jq '.theta_max_err = 1e-7' "$work/L/$cell" >"$work/C5/$cell"
rerun C5 "its report lies outside" "a cell whose compare/ folder links out of compare/"
# a report whose theta limit is not the cell's target (0.5 rad) runs again
cp -r "$work/L" "$work/C6"
jq '.engines.mujoco.limits.theta_max_err.limit = 0.5' "$work/L/$report/report.json" >"$work/C6/$report/report.json"
rerun C6 "it says other than its report" "a report whose theta limit is 0.5 rad backed its cell of target 1e-3"

# item 5: an input in cells/ or compare/ is refused, the file and --out untouched
cp "$quarter" "$work/L/$cell"
cp -r "$work/L" "$work/L.before"
refused "an object at a cached cell's file" "$cell.*inside" \
  "$diskval" league "$work/L/$cell" --engines mujoco --cause none --out "$work/L"
cp "$quarter" "$work/L/$report/reduced.csv"
cp "$quarter" "$work/L.before/$report/reduced.csv"
refused "an object at a backing report's file" "$report/reduced.csv.*inside" \
  "$diskval" league "$work/L/$report/reduced.csv" --engines mujoco --cause none --out "$work/L"
check 'diff -r "$work/L" "$work/L.before" >/dev/null' "a refused league changed its --out"

# item 10: a --set of a key the league gives each cell: one line naming the key, nothing written
for set in engines.mujoco.integrator=rk4 engines.mujoco.timestep=1e-3 engines.ode.timestep=1e-4 \
  tolerance.theta_max_err=0.1 tolerance.ode.theta_max_err=0.1; do
  refused "--set $set" "--set ${set%%=*}: the league's (search varies|targets set) it" \
    "$diskval" league "$quarter" --engines mujoco,ode --set "$set" --out "$work/V"
done
check '[ ! -e "$work/V" ]' "a refused --set wrote $work/V"

# item 8: --timeout, documented; a pair over it ends as an error that says so (measured:
# the coin's ODE cell at 1e-5 takes 6 s, its search 6 probes; the limit 0.5 s)
check '"$diskval" league --help | grep -q -- "--timeout S"' "league --help says nothing of --timeout"
refused "a negative --timeout" "timeout" "$diskval" league "$coin" --timeout -1 --out "$work/B"
"$diskval" league "$coin" --engines ode --targets 1e-5 --cause none --quiet --timeout 0.5 \
  --out "$work/T" >/dev/null 2>&1
code=$?
check '[ $code -eq 1 ] && jq -e ".cells[0] | (.reached | not) and (.why | startswith(\"error: timed out after 0.5 s\"))" "$work/T/league.json" >/dev/null' \
  "--timeout 0.5: exit $code, $(jq -c ".cells" "$work/T/league.json" 2>&1 | head -c 300)"

# item 11: stopped after its first cell (1e-2, about 1 s), while the second (1e-5, 6 s)
# runs: the first is listed as it ended, the second as not run
"$diskval" league "$coin" --engines ode --targets 1e-2,1e-5 --cause none --jobs 1 \
  --out "$work/I" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 600); do [ -e "$work/I/cells/euro_coin--ode--0.01.json" ] && break; sleep 0.1; done
kill -TERM $pid
wait $pid
code=$?
check '[ $code -eq 130 ]' "a stopped league exited $code, not 130"
first=$(jq -r .outcome "$work/I/cells/euro_coin--ode--0.01.json")
check '[ "$(awk -F, "NR == 2 { print \$7 }" "$work/I/league.csv")" = "$first" ] &&
  [ "$(awk -F, "NR == 3 { print \$7 }" "$work/I/league.csv")" = "not run" ]' \
  "a stopped league's league.csv (its cell kept says $first): $(cut -d, -f5,7 "$work/I/league.csv" | tr '\n' ' ')"
# league.md: one matrix row per target, the 1e-5 one alone not run
check '[ "$(grep -c "^| euro\\\\_coin |.*not run" "$work/I/league.md")" -eq 1 ] &&
  jq -e ".cells[0].outcome == \"$first\"" "$work/I/league.json" >/dev/null' \
  "a stopped league's league.md or league.json lists its finished cell otherwise: $(grep "^| euro" "$work/I/league.md")"
exit $fail
