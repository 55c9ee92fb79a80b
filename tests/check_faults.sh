#!/usr/bin/env bash
# check_faults.sh DISKVAL SCENARIO_DIR: faults outside the numerics.
#   - a read-only output directory: a clear error, exit 2, nothing written;
#   - a full disk (a 64 KiB tmpfs): exit 2, no half-written report (at most
#     the scenario's error report), no temporary files left;
#   - SIGINT during a suite: exit 130, finished reports intact, no temporary
#     directories of its own left, another live process's kept.
# The file systems are tmpfs mounts: skipped (77) where mounting is not allowed.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
scenarios=$2
work=$(mktemp -d)
ro="$work/ro" full="$work/full"
mkdir -p "$ro" "$full"
cleanup() { umount "$ro" 2>/dev/null; umount "$full" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
if ! mount -t tmpfs -o ro,size=64k tmpfs "$ro" 2>/dev/null ||
   ! mount -t tmpfs -o size=64k tmpfs "$full" 2>/dev/null; then
  echo "SKIP: cannot mount a tmpfs here"
  exit 77
fi

# read-only
"$diskval" suite "$scenarios/falling.ini" --out "$ro/report" 2>"$work/err"; code=$?
check '[ $code -eq 2 ]' "read-only: exit $code, want 2"
check '[ "$(wc -l <"$work/err")" -eq 1 ] && grep -q "Read-only" "$work/err"' \
  "read-only: want one line naming the cause, got: $(cat "$work/err")"
"$diskval" simulate "$scenarios/falling.ini" --engine reduced --out "$ro/x.csv" 2>/dev/null; code=$?
check '[ $code -eq 2 ]' "read-only simulate: exit $code, want 2"
check '[ -z "$(ls -A "$ro")" ]' "read-only: files appeared"

# full disk: upright_stable's reference CSV alone is larger than 64 KiB (110 KiB); one engine
# at a given step, so that no settings are probed (all engines: 30 s, 0.06 s so)
pinned=(--engines ode --set engines.ode.timestep=1e-3)
"$diskval" suite "$scenarios/upright_stable.ini" "${pinned[@]}" --out "$full/report" 2>"$work/err"
code=$?
check '[ $code -eq 2 ]' "full disk: exit $code, want 2"
check 'grep -q "No space" "$work/err"' "full disk: no clear message: $(cat "$work/err")"
# the scenario's directory, if any, is its error report (report_suite_dir.h), not a part of a report:
# report.json, report.md and its page whole, if the page fitted
check '[ ! -e "$full/report/upright_stable" ] ||
  { grep -q "No space" "$full/report/upright_stable/report.json" &&
    [ "$(ls "$full/report/upright_stable" | grep -vx index.html)" = "$(printf "report.json\nreport.md")" ] &&
    { [ ! -e "$full/report/upright_stable/index.html" ] ||
      tail -n 1 "$full/report/upright_stable/index.html" | grep -qx "</html>"; }; }' \
  "full disk: a half-written report remains: $(ls "$full/report/upright_stable" 2>&1)"
check '[ -z "$(find "$full" -name ".diskval-tmp.*")" ]' "full disk: temporary files remain"
"$diskval" simulate "$scenarios/upright_stable.ini" --engine reduced --out "$full/x.csv" 2>/dev/null
code=$?
check '[ $code -eq 2 ] && [ ! -e "$full/x.csv" ]' "full disk simulate: exit $code or a file left"
# a file small enough to sit in the stdio buffer fails only when flushed or closed
# on a disk already full: still no file, whole or half
cat /dev/zero >"$full/fill" 2>/dev/null
"$diskval" simulate "$scenarios/falling.ini" --engine reduced --set scenario.duration=0.01 \
  --out "$full/small.csv" 2>"$work/err"
code=$?
check '[ $code -eq 2 ] && [ ! -e "$full/small.csv" ] && [ ! -e "$full/small.csv.json" ] &&
  grep -q "No space" "$work/err"' \
  "full disk, a small file: exit $code, $(ls "$full" | tr '\n' ' '), $(cat "$work/err")"
rm -f "$full/fill"

# SIGINT in the middle of the default suite; a live process's temporary
# there (this shell's pid) is not the suite's to remove
mkdir -p "$work/int/.diskval-tmp.$$.abcdef"
# ODE at 2e-6 s: the suite takes 6.5 s on two cores (at 1e-3 s it ends in 0.7 s, before the signal)
"$diskval" suite "$scenarios" --engines ode --set engines.ode.timestep=2e-6 --out "$work/int" \
  --jobs 2 >/dev/null 2>"$work/err" &
pid=$!
# the suite takes --out's lock once every scenario is loaded, then runs
for _ in $(seq 600); do [ -e "$work/int/.diskval.lock" ] && break; sleep 0.1; done
sleep 1
kill -INT "$pid"
wait "$pid"; code=$?
check '[ $code -eq 130 ]' "SIGINT: exit $code, want 130"
check 'grep -q interrupted "$work/err"' "SIGINT: no message"
check '[ -z "$(find "$work/int" -name ".diskval-tmp.*" ! -name ".diskval-tmp.$$.abcdef")" ]' \
  "SIGINT: temporary directories remain"
check '[ -d "$work/int/.diskval-tmp.$$.abcdef" ]' "SIGINT: another process's temporary was removed"
for d in "$work"/int/*/; do
  [ -d "$d" ] || continue
  check '[ -s "$d/report.json" ] && [ -s "$d/report.md" ]' "SIGINT: $d is incomplete"
done
[ $fail -eq 0 ] && echo "faults: all contained"
exit $fail
