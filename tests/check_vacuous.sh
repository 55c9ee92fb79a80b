#!/usr/bin/env bash
# check_vacuous.sh DISKVAL SCENARIO_DIR: a comparison that measures nothing is
# "not judged", exit 1, never a pass (issue 23, item 6).
#   - the reference as an engine (--engines reduced, or a scenario's engines =
#     reduced, matched): compared with itself, errors exactly 0;
#   - duration = output_dt = 1e-300 (2 samples), and 0.05 s of a scene whose
#     fall time is 0.1 s (51 samples): windows too short to judge;
#   - a fall cut before it lies down is too short; the whole fall, shorter
#     than the scene's time scale, is judged (the reference showed all of it);
#   - suite --engines reduced: JUnit <failure>, summary.json fails;
#   - suite --verify where every case is skipped;
#   - the control: c_zero compares matched (Newton-Euler) with reduced, two
#     formulations, and passes.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_vacuous.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_vacuous.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
circle=$sc/steady_circle.ini

# compare ARGS...: exit status into code
compare() { "$dv" compare "$@" --out out >stdout 2>stderr; code=$?; }
# every SCENE result row of stdout (one for each engine, two at least) matches PATTERN
every() {
  local rows ok
  rows=$(grep -c "^$1 " stdout) ok=$(grep -c "^$1 .*$2" stdout)
  [ "$rows" -ge 2 ] && [ "$rows" -eq "$ok" ]
}

compare "$circle" --engines reduced
check '[ $code -eq 1 ]' "--engines reduced: exit $code, want 1: $(cat stdout stderr)"
check 'grep -q "^steady_circle *reduced *not judged .* FAIL$" stdout' "--engines reduced: $(cat stdout)"
check 'grep -q "reduced is the reference it would be compared with" stdout' "--engines reduced: no reason"
check '[ "$(jq -r .pass out/steady_circle/report.json)" = false ]' "--engines reduced: report.json passes"

sed 's/^name = .*/name = own\nengines = reduced, matched/' "$circle" >own.ini
compare own.ini
check '[ $code -eq 1 ]' "engines = reduced, matched: exit $code, want 1: $(cat stdout stderr)"
check 'grep -q "^own *reduced *not judged" stdout' "engines = reduced, matched: $(cat stdout)"

compare "$circle" --set scenario.duration=1e-300 --set scenario.output_dt=1e-300
check '[ $code -eq 1 ]' "duration 1e-300: exit $code, want 1: $(cat stdout stderr)"
check 'every steady_circle "not judged .* FAIL$"' "duration 1e-300: $(cat stdout)"
check 'grep -q "too short: 2 samples, at least" stdout' "duration 1e-300: no reason: $(cat stdout)"

compare "$circle" --set scenario.duration=0.05 --set scenario.output_dt=0.001
check '[ $code -eq 1 ]' "duration 0.05 s: exit $code, want 1: $(cat stdout stderr)"
check 'grep -q "too short: 0.05 s, shorter than the scene.s shortest time scale" stdout' \
  "duration 0.05 s: $(cat stdout)"

# a coin that falls flat in 0.031 s, under the scene's shortest scale (0.035 s):
# the reference lying down has shown the whole motion, which is judged (both
# engines lie down within 3e-5 s of it); cut at 0.02 s, before it lies down, not
coin=$(dirname "$0")/data/coin_falls_flat.ini
compare "$coin"
check '[ $code -eq 0 ] && every coin_falls_flat " agrees .* pass$"' \
  "a fall shorter than the scale, whole: exit $code, want 0: $(cat stdout)"
compare "$coin" --set scenario.duration=0.02 --set scenario.output_dt=0.0005
check '[ $code -eq 1 ] && grep -q "too short: 0.02 s, shorter than the scene.s shortest time scale" stdout' \
  "the fall cut before it lies down: exit $code: $(cat stdout)"

"$dv" suite "$circle" --engines reduced --out sout --jobs 1 >stdout 2>stderr; code=$?
check '[ $code -eq 1 ]' "suite --engines reduced: exit $code, want 1: $(cat stdout stderr)"
check 'grep -q "<failure message=\"steady_circle: reduced: not judged" sout/junit.xml' \
  "suite --engines reduced: no JUnit <failure>"
check '[ "$(jq -r .pass sout/summary.json)" = false ]' "suite --engines reduced: summary.json passes"

"$dv" suite --verify "$sc/c_zero.ini" --engines mujoco --out vout >stdout 2>stderr; code=$?
check '[ $code -eq 1 ]' "suite --verify, every case skipped: exit $code, want 1: $(cat stdout stderr)"
check 'grep -q "not judged" stdout' "suite --verify, every case skipped: $(cat stdout)"
check 'grep -q "<skipped" vout/junit.xml' "suite --verify: the skipped case is no <skipped>"

compare "$sc/c_zero.ini"
check '[ $code -eq 0 ]' "c_zero (matched against reduced): exit $code, want 0: $(cat stdout stderr)"
exit $fail
