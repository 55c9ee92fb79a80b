#!/usr/bin/env bash
# check_suite_faults.sh DISKVAL SCENARIO_DIR: a suite's faults and its output directory.
#   - a scenario over --timeout is ended and reported as an error, "timed out
#     after N s", on stdout, in summary.json, junit.xml and index.html; the
#     other scenario is still reported, and nothing temporary is left;
#   - so is a case of --verify (scenario and engine) over --timeout;
#   - a scenario that errors replaces its earlier (passing) report by its
#     failure with the real cause, in every output;
#   - a second run into a directory another run holds (.diskval.lock) is
#     refused in one line, exit 2, and touches nothing there;
#   - temporaries of a dead run (.diskval-tmp.PID.XXXXXX) are removed by the
#     next suite or compare, those of a live process kept, and a directory of
#     that name is removed only when diskval marked it (or it is empty);
#   - a suite stopped by SIGTERM while its scenarios choose their settings
#     (the probes, their first work: an adapter answering each row after 1 s,
#     tests/adapters/slow) exits 130 and still writes summary.json, the JUnit
#     XML and index.html, each scenario an error "did not end", and leaves no
#     adapter running.
# Timings (diskval suite ... --jobs 2 on 2 busy cores): fast.ini and slow.ini
# at 1 s take 0.7 s together; slow.ini at 60 s takes over 20 s (MuJoCo alone:
# 20 s), so at 300 s over 100 s. A 20 s limit is 20x the fast case's verify
# (1.0 s of CPU; it took 13 s of wall time with the machine at load 13 on 2
# cores) and a fifth of the slow run. No wall time is asserted: the "timed out"
# messages prove the limit fired, tests/exec/test_exec.c that it ends a child
# (one that sleeps), and bench/bench_time_limits.sh how soon. The
# suites run MuJoCo alone: the faults are the suite's, not an engine's (with five
# engines, fast took over the 5 s under the sanitizers on busy cores).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_suite_faults.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_suite_faults.sh DISKVAL SCENARIO_DIR}
slow_adapter=$(cd "$(dirname "$0")" && pwd)/adapters/slow
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
# scenario NAME DURATION: a copy of the 60 s long_horizon scene as NAME.ini
scenario() {
  sed -e "s/^name = .*/name = $1/" -e "s/^duration = .*/duration = $2/" \
    "$sc/hard/long_horizon.ini" >"$1.ini"
}
# summary FIELD NAME: the scenario's pass or error in summary.json
summary() {
  jq -r --arg f "$1" --arg n "$2" '.scenarios[] | select(.scenario == $n) | .[$f]' out/summary.json
}

# a passing run, then slow.ini made 300 s long under a 20 s limit
scenario fast 1
scenario slow 1
"$dv" suite fast.ini slow.ini --engines mujoco --out out --jobs 2 >stdout 2>stderr; code=$?
check '[ $code -eq 0 ] && [ "$(summary pass slow)" = true ]' "first run: exit $code, $(cat stderr)"
scenario slow 300
start=$(date +%s)
"$dv" suite fast.ini slow.ini --engines mujoco --out out --jobs 2 --timeout 20 >stdout 2>stderr; code=$?
took=$(($(date +%s) - start))
why="timed out after 20 s"
check '[ $code -eq 2 ]' "timeout: exit $code, want 2"
check 'grep -q "^slow: error: $why$" stdout' "timeout: stdout does not say so: $(cat stdout)"
check 'grep -q "slow: $why" stderr' "timeout: stderr does not say so: $(cat stderr)"
check '[ "$(summary pass slow)" = false ] && [ "$(summary error slow)" = "$why" ]' \
  "timeout: summary.json says pass $(summary pass slow), error $(summary error slow)"
check '[ "$(summary pass fast)" = true ]' "timeout: the other scenario is not reported as passing"
check 'grep -q "<error message=\"$why\"" out/junit.xml' "timeout: junit.xml has no error '$why'"
check 'grep -q "$why" out/index.html' "timeout: index.html does not say '$why'"
check '[ ! -e out/slow/reduced.csv ] && grep -q "$why" out/slow/report.json' \
  "timeout: the earlier report of slow is still there"
check '[ -z "$(find out -name ".diskval-tmp.*")" ]' "timeout: temporaries remain"

# --verify under the same limit: the slow case is an error, the fast one converges
start=$(date +%s)
# (MuJoCo's settings given: the ones chosen for fast.ini, euler at 1.24e-5 s, take
# its verify to 1.6e-6 s steps, 2.2 s alone; rk4 at 1.89e-4 s, 0.3 s)
"$dv" suite fast.ini slow.ini --verify --engines mujoco --out vout --timeout 20 \
  --set engines.mujoco.integrator=rk4 --set engines.mujoco.timestep=1.89e-4 >stdout 2>stderr
code=$?
took=$(($(date +%s) - start))
check '[ $code -eq 2 ]' "verify timeout: exit $code after $took s, want 2"
check 'grep -q "| slow | mujoco | nan, nan, nan, nan | error: $why" vout/verify.md' \
  "verify timeout: verify.md does not say so (or shows errors it never measured): $(cat vout/verify.md)"
check 'grep -q "^slow: mujoco: error: $why$" stdout' "verify timeout: stdout does not say so: $(cat stdout)"
check 'grep -q "failure message=\"error: $why\"" vout/junit.xml' "verify timeout: junit.xml lacks '$why'"
check 'grep -q "| fast | mujoco |.*converges" vout/verify.md' "verify timeout: the fast case did not converge"

# an error inside the run (the reference's step budget) replaces the report
scenario slow 1
"$dv" suite fast.ini slow.ini --engines mujoco --out out --jobs 2 >/dev/null 2>&1
"$dv" suite fast.ini slow.ini --engines mujoco --out out --set engines.reduced.max_steps=5 >stdout 2>stderr
code=$?
why="step budget spent"
check '[ $code -eq 2 ]' "error: exit $code, want 2"
check 'grep -q "^slow: error: .*$why" stdout' "error: stdout does not say so: $(cat stdout)"
check '[ "$(summary pass slow)" = false ] && [[ "$(summary error slow)" == *"$why"* ]]' \
  "error: summary.json says pass $(summary pass slow), error $(summary error slow)"
check 'grep -q "<error message=\"the reduced reference: gsl-rk8pd $why" out/junit.xml && ! grep -q "cannot open" out/junit.xml' \
  "error: junit.xml lacks the real cause: $(grep "<error" out/junit.xml)"
check 'grep -q "$why" out/index.html' "error: index.html lacks the cause"
check '[ ! -e out/slow/theta.svg ]' "error: the earlier report's plots remain"

# a pid that no process has: that of a process that has ended
sleep 0 &
dead=$!
wait "$dead"

# a second run while another holds the directory: refused, nothing touched
# (not even a dead run's temporary, which a run that went on would remove);
# the holder is a compare of the 60 s scene, ended once the check is done
mkdir -p held
"$dv" suite fast.ini --out held >/dev/null 2>&1 # a directory diskval made
touch "held/.diskval-tmp.$dead.abcdef"
scenario slow 300
"$dv" compare slow.ini --out held --engines mujoco >/dev/null 2>&1 &
holder=$!
for _ in $(seq 200); do [ -e held/.diskval.lock ] && break; sleep 0.05; done
snapshot() { (cd held && find . ! -name ".diskval-tmp.$holder.*" ! -path "./.diskval-tmp.$holder.*/*" \
  ! -name .diskval.lock -exec stat -c '%n %s %Y' {} + | sort); }
snapshot >before
"$dv" suite fast.ini --out held >stdout 2>stderr; code=$?
snapshot >after
kill -TERM "$holder"
wait "$holder"
check '[ $code -eq 2 ]' "lock: exit $code, want 2"
check '[ "$(wc -l <stderr)" -eq 1 ] && grep -q "another diskval run is writing into this directory" stderr' \
  "lock: want one line saying why, got: $(cat stderr)"
check '[ ! -s stdout ]' "lock: stdout: $(cat stdout)"
check 'diff before after >/dev/null' "lock: the held directory changed: $(diff before after)"

# temporaries of a dead run go (a report directory diskval marked, an empty
# one, a file), those of a live process stay, and nothing else of that shape
scenario slow 1
mkdir -p out/.diskval-tmp.$dead.abcdef out/.diskval-tmp.$dead.ghijkl out/.diskval-tmp.$$.abcdef
echo "diskval output directory, format 1" >out/.diskval-tmp.$dead.abcdef/.diskval-report
touch out/.diskval-tmp.$dead.mnopqr
"$dv" suite fast.ini --out out >/dev/null 2>&1
check '[ -z "$(compgen -G "out/.diskval-tmp.$dead.*")" ]' \
  "stale: a dead run's temporaries remain: $(compgen -G "out/.diskval-tmp.$dead.*")"
check '[ -d out/.diskval-tmp.$$.abcdef ]' "stale: a live process's temporary was removed"
mkdir -p out/.diskval-tmp.$dead.stuvwx out/.diskval-tmp.$dead.abcdef/keep
touch out/.diskval-tmp.$dead.abcdef/keep/mine
"$dv" compare fast.ini --out out >/dev/null 2>&1
check '[ ! -e out/.diskval-tmp.$dead.stuvwx ]' "stale: compare left a dead run's temporary"
check '[ -e out/.diskval-tmp.$dead.abcdef/keep/mine ]' \
  "stale: a directory diskval did not mark was removed for its name"
check '[ -d out/.diskval-tmp.$$.abcdef ]' "stale: compare removed a live process's temporary"

# SIGTERM while the scenarios probe their settings (the slow adapter: 1 s a
# row, over 10 s of probes each): their work had begun, so the suite's
# files say they did not end (it once said "nothing written")
mkdir probing && sed 's/^name = .*/name = fall_a/' "$sc/falling.ini" >probing/fall_a.ini &&
  sed 's/^name = .*/name = fall_b/' "$sc/falling.ini" >probing/fall_b.ini
DISKVAL_ADAPTERS=$slow_adapter DV_SLOW_SLEEP=1.$$ "$dv" suite probing --engines slow --out sig \
  --jobs 2 >sig.out 2>&1 &
pid=$!
sleep 2
kill -TERM $pid
wait $pid
code=$?
check '[ $code -eq 130 ] && [ -f sig/summary.json ] && [ -f sig/junit.xml ] && [ -f sig/index.html ]' \
  "SIGTERM in the probes: exit $code, files $(ls sig 2>&1): $(cat sig.out)"
check '[ "$(jq -r "[.scenarios[] | .error] | map(test(\"did not end\")) | all" sig/summary.json)" = true ] &&
  [ "$(jq ".scenarios | length" sig/summary.json)" -eq 2 ] && grep -q "did not end" sig/junit.xml sig/fall_a/report.json' \
  "SIGTERM in the probes: the scenarios are not errors that did not end: $(cat sig/summary.json)"
sleep 1.5 # a row's sleep: the adapters' guard ends them (SIGTERM) as their run ends
check '! pgrep -f "sleep 1.$$" >/dev/null' "SIGTERM in the probes: an adapter still runs: $(pgrep -af "sleep 1.$$")"

[ $fail -eq 0 ] && echo "suite faults: contained, with their causes"
exit $fail
