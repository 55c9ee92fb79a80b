#!/usr/bin/env bash
# check_league.sh DISKVAL SOURCE_DIR: diskval league's cells hold their claims.
#   - a league of a thin circle and a thick coin, ODE and MuJoCo, targets
#     1e-2 and 1e-3: every cell ran; a reached cell's errors are within its
#     targets; three cells picked at random (the seed is printed) re-run by
#     compare at their settings give the same errors, within the targets;
#     league.json validates against its schema (where python3 has jsonschema)
#   - the cache: the same league again runs nothing; an edited object's cells
#     run again, the other's are kept; a league stopped by SIGTERM exits 130,
#     and the next run finishes only what was left
#   - an engine with no shape for the object's body is "cannot model", run on nothing
#   - bad input refused in one line, and a --out holding a user's file
#     refused with the file untouched
# Exit status: 0 as expected, 1 a difference, 77 skipped (no jq).
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1 src=$2
command -v jq >/dev/null || { echo "jq is not installed: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src/tests/data/short_circle.ini" "$src/tests/data/euro_coin.ini" "$work/"
objects=("$work/short_circle.ini" "$work/euro_coin.ini")
league() { "$diskval" league "${objects[@]}" --engines ode,mujoco --targets 1e-2,1e-3 --cause none "$@"; }

league --out "$work/L" --quiet >"$work/out" 2>"$work/err"
code=$?
json=$work/L/league.json
check '[ $code -eq 0 ]' "league exit $code: $(cat "$work/err")"
check '[ "$(jq ".cells | length" "$json")" -eq 8 ]' "not 8 cells: $(jq ".cells | length" "$json")"
check '[ "$(jq "[.cells[] | select(.outcome == \"not run\" or (.why | startswith(\"error\")))] | length" "$json")" -eq 0 ]' \
  "a cell did not run: $(jq -c "[.cells[] | select(.outcome == \"not run\") | .why]" "$json")"
# both engines reach both targets on both objects (measured: every cell reached, the
# nearest to its limit MuJoCo's coin at 1e-3, path 4.9e-5 of 1.1e-4 m)
check '[ "$(jq "[.cells[] | select(.reached)] | length" "$json")" -eq 8 ]' \
  "cells not reached: $(jq -c "[.cells[] | select(.reached | not) | [.object, .engine, .target, .why]]" "$json")"
# a reached cell's own numbers are within its targets, and its report is there
bad=$(jq -r '.cells[] | select(.reached) | select(.theta_max_err > .target or
  .path_max_err > .path_target) | "\(.object) \(.engine) \(.target)"' "$json")
check '[ -z "$bad" ]' "reached cells beyond their targets: $bad"
# the settings of a reached cell are one of its search's points (its star on the figure)
unmatched=$(jq -r '.cells[] | select(.reached) | . as $c | select([.points[] |
  select(.choice == $c.choice and .step == $c.step)] | length == 0) | "\(.object) \(.engine) \(.target)"' "$json")
check '[ -z "$unmatched" ]' "reached cells whose settings are none of their points: $unmatched"
for r in $(jq -r '.cells[] | select(.reached) | .report' "$json"); do
  check '[ -f "$work/L/$r/report.json" ]' "no backing report $r"
done
for f in league.csv league.md league.html overview.svg work_precision_euro_coin.svg; do
  check '[ -s "$work/L/$f" ]' "no $f"
done

# claims: cells picked at random, re-run by compare at their settings
seed=${LEAGUE_SEED:-$RANDOM}
echo "cells picked with seed $seed (LEAGUE_SEED=$seed to pick them again)"
reached=$(jq '[.cells[] | select(.reached)] | length' "$json")
check '[ "$reached" -ge 3 ]' "only $reached cells reached"
RANDOM=$seed
for i in 1 2 3; do
  cell=$(jq -c "[.cells[] | select(.reached)][$((RANDOM % reached))]" "$json")
  engine=$(jq -r .engine <<<"$cell")
  sets=$(jq -r '.settings | to_entries[] | "--set\n\(.key)=\(.value)"' <<<"$cell")
  mapfile -t set_args <<<"$sets"
  "$diskval" compare "$(jq -r .scenario_file <<<"$cell")" --engines "$engine" "${set_args[@]}" \
    --cause none --quiet --out "$work/claim$i" >/dev/null 2>&1
  report=$(ls "$work/claim$i"/*/report.json)
  theta=$(jq ".engines.$engine.theta_max_err" "$report")
  path=$(jq ".engines.$engine.path_max_err" "$report")
  # the engines are deterministic: the same run gives the same errors (to the digits printed)
  check "jq -e --argjson t $theta --argjson p $path \
    '(\$t - .theta_max_err | fabs) <= 1e-12 * .target and (\$p - .path_max_err | fabs) <= 1e-12 * .path_target
     and \$t <= .target and \$p <= .path_target' <<<'$cell' >/dev/null" \
    "cell $(jq -c '[.object, .engine, .target, .settings]' <<<"$cell"): compare gives theta $theta, path $path"
done
if python3 -c 'import jsonschema' 2>/dev/null; then
  check 'python3 "$src/tests/json_validate.py" "$src/tests/fixtures/schemas" league.schema.json valid "$json"' \
    "league.json does not match league.schema.json"
  jq '.cells[0].reached = "yes"' "$json" >"$work/broken.json"
  check 'python3 "$src/tests/json_validate.py" "$src/tests/fixtures/schemas" league.schema.json invalid "$work/broken.json"' \
    "a cell with reached as a string was accepted"
else
  echo "python3 jsonschema is not installed: the schema is not checked"
fi

# the cache: nothing runs again; an edited object's cells do
keys() { jq -r '.cells[] | "\(.object) \(.engine) \(.target) \(.key) \(.wall_s)"' "$1"; }
keys "$json" >"$work/keys1"
jq -S .cells "$json" >"$work/cells1"
league --out "$work/L" >/dev/null 2>"$work/err2"
check 'grep -q "8 of 8 cells from the cache" "$work/err2"' "the second league ran again: $(cat "$work/err2")"
check 'jq -S .cells "$json" | cmp -s - "$work/cells1"' "the cells read back from the cache differ"
# an edited object runs again, the other is kept; stopped by a signal (TERM: a
# background job ignores INT) after its first new cell, the league exits 130, and the
# next run finishes only the rest
echo "; edited" >>"$work/euro_coin.ini"
touch "$work/mark"
"$diskval" league "${objects[@]}" --engines ode,mujoco --targets 1e-2,1e-3 --cause none \
  --out "$work/L" --jobs 1 >/dev/null 2>&1 &
pid=$! # diskval's own: a function's subshell would take the signal instead
for _ in $(seq 600); do [ -n "$(find "$work/L/cells" -newer "$work/mark" -name 'euro_coin*')" ] && break; sleep 0.1; done
kill -TERM $pid
wait $pid
code=$?
check '[ $code -eq 130 ]' "a stopped league exited $code, not 130"
kept=$(find "$work/L/cells" -newer "$work/mark" -name 'euro_coin*' | wc -l)
check '[ "$kept" -ge 1 ] && [ "$kept" -lt 4 ]' "a stopped league kept $kept new cells"
league --out "$work/L" >/dev/null 2>"$work/err3"
check 'grep -q "$((4 + kept)) of 8 cells from the cache" "$work/err3"' "the resumed league: $(head -2 "$work/err3")"
check '[ "$(jq "[.cells[] | select(.outcome == \"not run\")] | length" "$json")" -eq 0 ]' \
  "the resumed league left cells not run"
check '[ "$(keys "$json" | grep short_circle)" = "$(grep short_circle "$work/keys1")" ]' \
  "the unedited object's cells changed"
check '[ "$(keys "$json" | grep euro_coin | cut -d" " -f4)" != "$(grep euro_coin "$work/keys1" | cut -d" " -f4)" ]' \
  "the edited object's keys did not change"

# the cost cap: no run over it; a cell it stops says so
# (measured: ODE's first run on the circle, at 4.4e-6 s, costs 0.2 s a simulated s
# for 2e-4 rad; 1e-5 rad needs finer steps)
"$diskval" league "$work/short_circle.ini" --engines ode --targets 1e-5 --cost-cap 0.02 --cause none \
  --quiet --out "$work/C" >/dev/null 2>&1
check 'jq -e ".cells[0] | (.reached | not) and (.why | startswith(\"cost cap\"))
  and ([.points[] | select(.step < 4.4e-6)] | length == 0)" "$work/C/league.json" >/dev/null' \
  "a cap of 0.02 s a simulated s: $(jq -c ".cells[0] | [.outcome, .why, [.points[].step]]" "$work/C/league.json")"

# an engine with no shape for the object's body: said, nothing run (the test adapter
# simulates a cylinder, never the thin disk)
DISKVAL_ADAPTERS=$src/tests/adapters "$diskval" league "$work/short_circle.ini" --engines replay \
  --cause none --quiet --out "$work/T" >/dev/null 2>&1
check 'jq -e ".cells[0] | .outcome == \"cannot model\" and (.why | startswith(\"cannot model: no thin disk\"))
  and .report == \"\" and (.points | length) == 0" "$work/T/league.json" >/dev/null' \
  "a thin object in an engine with no thin disk: $(jq -c ".cells[0] | [.outcome, .why]" "$work/T/league.json")"

# bad input, and a --out that holds a user's file
refused "targets not numbers" "targets" "$diskval" league "${objects[@]}" --targets 1e-3,abc --out "$work/B"
refused "a target of 0" "targets" "$diskval" league "${objects[@]}" --targets 0 --out "$work/B"
refused "an unknown engine" "nosuch" "$diskval" league "${objects[@]}" --engines nosuch --out "$work/B"
refused "a missing object" "nothere" "$diskval" league "$work/nothere.ini" --out "$work/B"
mkdir "$work/U" && echo mine >"$work/U/notes.txt"
refused "a --out diskval did not make" "U" "$diskval" league "${objects[@]}" --out "$work/U"
check '[ "$(cat "$work/U/notes.txt")" = mine ] && [ "$(ls "$work/U")" = notes.txt ]' \
  "the user's --out was touched"
exit $fail
