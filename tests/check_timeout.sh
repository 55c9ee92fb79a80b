#!/usr/bin/env bash
# check_timeout.sh DISKVAL SCENARIO_DIR: long work is known before it starts.
#   - compare and simulate of a scene whose one output interval lasts the
#     whole run (steady_circle to t = 20000 s, output_dt 20000 s: minutes)
#     say how long they will take before the run's end (the probe once waited
#     for a first sample that came at the end): within 60 s, 0.2 s measured;
#   - with --timeout 1 that scene is refused at once: one line, exit 2,
#     nothing written;
#   - a run let start (its estimate under twice the limit) is killed at the
#     limit: exit 2, "timed out after S s", no CSV, no temporaries, compare's
#     error report saying so;
#   - the limit bounds the whole run, the settings probes of the load and
#     the up-front forecast too: with an adapter answering each row after
#     1 s (tests/adapters/slow), simulate and compare --timeout 3 and suite
#     --timeout 3 end "timed out after 3 s", nothing of
#     simulate's left, compare's and suite's error reports written; so does
#     compare with an adapter that never answers (its manifest waits 30 s).
# No wall time is asserted (3.0-3.1 s measured, idle; 38-125 s before the
# probes were under the limit): the message "timed out after 3 s" says the
# limit ended them, and a run that outlives 60 s (the silent adapter's
# manifest waits 30 s a row) is killed and fails. How soon a limit ends a child is tests/exec/test_exec.c's
# check (a child that sleeps 10 s under a 0.5 s limit); here the messages prove it.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
scenarios=$2
sc=$scenarios/steady_circle.ini
work=$(mktemp -d)
pids=()
cleanup() { for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done; rm -rf "$work"; }
trap cleanup EXIT
long=(--set scenario.duration=20000 --set scenario.output_dt=20000)
: >"$work/announce"
: >"$work/err"

# announced CMD...: CMD's stderr has "will take about" within 60 s (then it is killed)
announced() {
  "$diskval" "$@" >/dev/null 2>"$work/announce" &
  local pid=$! i
  pids+=("$pid")
  for i in $(seq 600); do
    grep -q "will take about" "$work/announce" && break
    sleep 0.1
  done
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  grep -q "will take about" "$work/announce"
}
check 'announced compare "$sc" "${long[@]}" --out "$work/a"' "compare: no estimate within 60 s: $(cat "$work/announce")"
check 'announced simulate "$sc" --engine mujoco "${long[@]}" --out "$work/a.csv"' \
  "simulate: no estimate within 60 s: $(cat "$work/announce")"

# refused up front
# (the message proves it was not run: the run itself takes minutes)
"$diskval" compare "$sc" "${long[@]}" --out "$work/r" --timeout 1 >/dev/null 2>"$work/err"
code=$?
check '[ $code -eq 2 ]' "compare --timeout 1: exit $code"
check '[ "$(wc -l <"$work/err")" -eq 1 ] && grep -Eq "^diskval compare: [^ ]*steady_circle[^ ]*: would take about [0-9.e+]+ s .*more than 2 times the time limit of 1 s: not started$" "$work/err"' \
  "compare --timeout 1: $(cat "$work/err")"
check '[ ! -e "$work/r/steady_circle" ]' "compare --timeout 1 wrote a report"
"$diskval" simulate "$sc" --engine mujoco "${long[@]}" --out "$work/r.csv" --timeout 1 2>"$work/err"
code=$?
check '[ $code -eq 2 ] && grep -q "more than 2 times the time limit of 1 s: not started" "$work/err"' \
  "simulate --timeout 1: exit $code: $(cat "$work/err")"
check '[ -z "$(ls -A "$work" | grep r.csv)" ]' "simulate --timeout 1 wrote $(ls "$work" | grep r.csv)"

# killed at the limit: a limit between half the probe's estimate (under it
# the run is refused) and the estimate, so that the run starts and is cut.
# The estimate and the run both vary with the machine's load (8-37 s measured
# for the same run at t = 200 s, so 50 s here, one estimate to the next up to 1.4x): a run that ended
# inside its limit after all, or one refused, is tried again, six times at
# most; every attempt is logged for the failure message.
mid=(--set scenario.duration=50 --set scenario.output_dt=50)
# killed OUT CMD...: 0 when CMD (writing OUT) was killed at its limit once, with nothing of it left
killed() {
  local out=$1 est limit i start code
  shift
  : >"$work/attempts"
  for i in 1 2 3 4 5 6; do
    # the estimate, from a limit under half of it (refused): 2 s, which the
    # settings probes and the forecast fit in (0.2 s measured; the limit
    # bounds them too: a limit of 1e-3 ends them, "timed out")
    est=$("$diskval" "$@" --timeout 2 2>&1 | sed -n 's/.*would take about \([0-9.e+]*\) s.*/\1/p')
    [ -n "$est" ] || { echo "no estimate" >>"$work/attempts"; return 1; }
    # two decimals, written as diskval writes them back (%g: 10.6, not 10.60)
    limit=$(awk -v e="$est" 'BEGIN { printf "%.2f", e / 1.5 }' | sed 's/0*$//; s/\.$//')
    start=$SECONDS
    "$diskval" "$@" --timeout "$limit" >/dev/null 2>"$work/err"
    code=$?
    echo "estimate $est s, limit $limit s: exit $code after $((SECONDS - start)) s: $(head -c 300 "$work/err")" >>"$work/attempts"
    if [ $code -le 1 ] || grep -q "not started" "$work/err"; then
      rm -rf "$out" "$out.json"
      continue
    fi
    [ $code -eq 2 ] && grep -q "timed out after $limit s" "$work/err"
    return
  done
  return 1
}
check 'killed "$work/k.csv" simulate "$sc" --engine mujoco "${mid[@]}" --out "$work/k.csv" || { cat "$work/attempts"; false; }' \
  "simulate: not killed at its limit (attempts above)"
check '[ -z "$(ls -A "$work" | grep k.csv)" ]' "simulate killed: left $(ls -A "$work" | grep k.csv)"
check 'killed "$work/k" compare "$sc" --engines mujoco "${mid[@]}" --out "$work/k" || { cat "$work/attempts"; false; }' \
  "compare: not killed at its limit (attempts above)"
check 'grep -q "timed out after" "$work/k/steady_circle/report.json"' "compare killed: no error report"
check '[ -z "$(ls -A "$work/k" | grep -v "^steady_circle$\|^.diskval.lock$")" ]' "compare killed: left $(ls -A "$work/k")"

# the limit bounds the settings probes and the forecast too (the slow adapter)
export DISKVAL_ADAPTERS=$(cd "$(dirname "$0")" && pwd)/adapters/slow
slow_sc=$scenarios/falling.ini # at rest at its start: the adapter's still rows are consistent
limit=3
# within CMD...: runs CMD (killed at 60 s), sets code and took (s of wall time)
within() {
  local t0 t1
  t0=$(date +%s.%N)
  timeout -k 2 60 "$@" >"$work/stdout" 2>"$work/err"
  code=$?
  t1=$(date +%s.%N)
  took=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
}
within "$diskval" simulate "$slow_sc" --engine slow --out "$work/p.csv" --timeout $limit
check '[ $code -eq 2 ] && grep -q "timed out after $limit s" "$work/err"' \
  "simulate --engine slow --timeout $limit: exit $code after $took s: $(cat "$work/err")"
check '[ -z "$(ls -A "$work" | grep p.csv)" ]' "simulate timed out in its probes: left $(ls -A "$work" | grep p.csv)"
within "$diskval" compare "$slow_sc" --engines slow --out "$work/p" --timeout $limit
check '[ $code -eq 2 ] && grep -q "timed out after $limit s" "$work/err"' \
  "compare --engines slow --timeout $limit: exit $code after $took s: $(cat "$work/err")"
check 'grep -q "timed out after $limit s" "$work/p/falling/report.json"' "compare timed out in its probes: no error report"
check '[ -z "$(ls -A "$work/p" | grep -v "^falling$\|^.diskval.lock$")" ]' "compare timed out: left $(ls -A "$work/p")"
DV_SLOW_SILENT=1 within "$diskval" compare "$slow_sc" --engines slow --out "$work/q" --timeout $limit
check '[ $code -eq 2 ] && grep -q "timed out after $limit s" "$work/err"' \
  "compare, an adapter that never answers, --timeout $limit: exit $code after $took s: $(cat "$work/err")"
mkdir "$work/sd" && cp "$slow_sc" "$work/sd/" &&
  sed 's/^name = .*/name = falling2/' "$slow_sc" >"$work/sd/falling2.ini"
within "$diskval" suite "$work/sd" --engines slow --out "$work/so" --timeout $limit --jobs 2
check '[ $code -eq 2 ] && [ "$(grep -c "error: timed out after $limit s" "$work/stdout")" -eq 2 ]' \
  "suite --engines slow --timeout $limit: exit $code after $took s: $(cat "$work/stdout" "$work/err")"
check '[ "$(grep -c "timed out after $limit s" "$work/so/summary.json")" -eq 2 ] && grep -q "timed out after $limit s" "$work/so/junit.xml" "$work/so/index.html"' \
  "suite timed out in its probes: not in summary.json, junit.xml, index.html"
# under a limit the probes choose what they choose without one (a fast adapter)
export DV_SLOW_SLEEP=0
"$diskval" simulate "$slow_sc" --engine slow --set scenario.duration=0.3 --out "$work/u.csv" 2>/dev/null
"$diskval" simulate "$slow_sc" --engine slow --set scenario.duration=0.3 --out "$work/l.csv" --timeout 60 2>/dev/null
check 'cmp -s "$work/u.csv" "$work/l.csv" && [ "$(jq -c .derived "$work/u.csv.json")" = "$(jq -c .derived "$work/l.csv.json")" ] && jq -e ".derived.reason | test(\"from a probe\")" "$work/l.csv.json" >/dev/null' \
  "simulate --timeout 60 chose other settings than without a limit: $(jq -c .derived "$work/u.csv.json" "$work/l.csv.json")"
unset DV_SLOW_SLEEP
exit $fail
