#!/usr/bin/env bash
# check_event_verdicts.sh DISKVAL SCENARIO_DIR: an engine that lies down where
# the reference does not has failed (issue 23, item 5).
#   - steady_steep with theta_limit 0.3999 rad (0.1 mrad under its steady
#     tilt): ODE lies down at t = 0.81 s, the reference and its nudged run
#     roll on to 5 s. compare exits 1, the line says FAIL, the failure and
#     report.md/report.json say which event and when, for both; suite's
#     JUnit has a <failure> for it;
#   - best on that scene (1 s) counts a probe that lies down as failed
#     ("falls", with the event), never as meeting the tolerance: it once chose
#     a 6.6 ms step whose run lay down at once, "theta error 5.551e-17 rad";
#   - falling.ini, where every run lies down past the validity limit: still
#     a pass (nothing is judged there).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_event_verdicts.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_event_verdicts.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
low="--set engines.reduced.theta_limit=0.3999"

"$dv" compare "$sc/steady_steep.ini" --engines ode $low --out out >stdout 2>stderr; code=$?
check '[ $code -eq 1 ]' "steady_steep: exit $code, want 1: $(cat stdout stderr)"
check 'grep -q "^steady_steep *ode *ended by event .* FAIL$" stdout' "the line does not fail: $(cat stdout)"
want="lies down where the reference does not"
check 'grep -q "$want.*ode: theta reached the lower limit 0.3999 rad at t = 0\.8[0-9]* s; the reference: did not lie down (ran to t = 5 s)" stdout' \
  "the failure does not say which event and when, for both: $(cat stdout)"
rj=out/steady_steep/report.json
check '[ "$(jq -r .engines.ode.pass $rj)" = false ] && [ "$(jq -r .pass $rj)" = false ]' "report.json passes"
check '[ "$(jq -r .engines.ode.event.agrees $rj)" = false ]' "report.json: event.agrees is not false"
check 'jq -r .engines.ode.event.runs $rj | grep -q "ode: theta reached the lower limit 0.3999 rad at t = 0.8"' \
  "report.json: event.runs does not name the engine's event: $(jq -c .engines.ode.event $rj)"
check 'grep -q "^Lying down: $want, nudged or not: ode: theta reached" out/steady_steep/report.md' \
  "report.md does not say it"

"$dv" suite "$sc/steady_steep.ini" --engines ode $low --out sout --jobs 1 >stdout 2>stderr; code=$?
check '[ $code -eq 1 ]' "suite: exit $code, want 1: $(cat stdout stderr)"
check 'grep -q "<failure message=\"steady_steep: ode: $want" sout/junit.xml' "suite: no JUnit <failure>"

"$dv" best "$sc/steady_steep.ini" --engine ode --theta-tol 1e-3 $low --set scenario.duration=1 \
  >stdout 2>stderr; code=$?
check '[ $code -eq 0 ] && grep -q "^best: " stdout' "best: exit $code: $(tail -3 stdout) $(cat stderr)"
check '[ "$(grep -c " meets$" stdout)" -gt 0 ]' "best: no probe meets"
check '! grep " meets$\| marginal$\| exceeds$" stdout | grep -q " n/a "' "best: a probe without an error is judged"
check '[ "$(grep -c "failed (falls: theta reached the lower limit 0.3999 rad at t = " stdout)" -gt 0 ]' \
  "best: no probe lies down, or it is not said: $(head -5 stdout)"
check '! grep "^best: " stdout | grep -q "e-1[0-9] rad"' "best: chose a run that lay down: $(grep "^best: " stdout)"

"$dv" compare "$sc/falling.ini" --out fout >stdout 2>stderr; code=$?
check '[ $code -eq 0 ]' "falling: exit $code, want 0: $(cat stdout stderr)"
exit $fail
