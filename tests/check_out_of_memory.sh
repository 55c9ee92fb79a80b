#!/usr/bin/env bash
# check_out_of_memory.sh DISKVAL SCENARIO_DIR: a comparison that runs out of
# memory says so, and what it was allocating, on stderr and in report.json
# (it said "output failed"). 1e6 samples (144 bytes each) under a 300 MB
# address-space limit: a trajectory's growth fails about 1 s in; exit 2.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
scenarios=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(ulimit -v 300000; exec timeout -k 2 60 "$diskval" compare "$scenarios/steady_circle.ini" \
  --engines mujoco --set scenario.output_dt=5e-6 --set scenario.memory_budget=4 \
  --out "$work/out" --quiet) >/dev/null 2>"$work/err"
code=$?
want="out of memory: the [a-z]+ run's trajectory could not grow to keep sample [0-9]+ "
check '[ $code -eq 2 ]' "exit $code, want 2"
# the scenario (its file), then the run that failed (a reference's is named), then why
check 'grep -Eq "^diskval compare: [^ ]*steady_circle[^ ]*: (the [a-z]+ reference[^:]*: )?$want" "$work/err"' \
  "stderr: $(cat "$work/err")"
check 'grep -Eq "\"error\":.*$want" "$work/out/steady_circle/report.json"' \
  "report.json: $(grep '"error"' "$work/out/steady_circle/report.json" 2>/dev/null)"
exit $fail
