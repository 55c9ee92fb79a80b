#!/usr/bin/env bash
# bench_forecast.sh DISKVAL ROOT: how near the announced forecasts come to the
# time taken, as ratios (forecast / taken) measured in this one run: best's
# rest of the search on three scenes, and compare's attribution on the hoop
# (a failure made by a turning limit of 1e-4 rad). Target: every forecast
# within 2x of the time taken (0.5 to 2), each line PASS or FAIL; a busy
# machine moves them (the probes timed under a load that then went), which is
# why this is a benchmark and not a CTest test (it was best_forecast's and
# cli/hoop's check until issue 40).
set -u
diskval=$1 root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for case in "$root/tests/data/two_euro.ini ode" "$root/tests/data/saucer.ini mujoco" \
  "$root/scenarios/falling.ini ode"; do
  set -- $case
  "$diskval" best "$1" --engine "$2" --theta-tol 1e-3 >/dev/null 2>"$work/err"
  sed -n 's/.*took \([0-9.e+-]*\) s (forecast \([0-9.e+-]*\) s).*/\1 \2/p' "$work/err" |
    awk -v s="$(basename "$1") $2" '{ r = $2 / $1; printf "best %-22s forecast / taken %.2f (%s s / %s s), target 0.5-2: %s\n", s, r, $2, $1, (r >= 0.5 && r <= 2) ? "PASS" : "FAIL" }'
done
began=$(date +%s.%N)
"$diskval" compare "$root/tests/data/wheel_wobble.ini" --engines mujoco --out "$work/hoop" \
  --set tolerance.mujoco.theta_turning_err=1e-4 >/dev/null 2>"$work/err"
took=$(awk -v a="$began" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
said=$(sed -n 's/.*will take about \([0-9hms]*\) .*/\1/p' "$work/err" |
  awk '{ s = 0; n = ""; for (i = 1; i <= length($0); i++) { c = substr($0, i, 1);
         if (c ~ /[0-9]/) n = n c; else { s += n * (c == "h" ? 3600 : c == "m" ? 60 : 1); n = "" } }
         print s }')
awk -v f="${said:-nan}" -v t="$took" \
  'BEGIN { r = f / t; printf "compare hoop attribution  forecast / whole command %.2f (%s s / %.1f s), target 0.5-2: %s\n", r, f, t, (r >= 0.5 && r <= 2) ? "PASS" : "FAIL" }'
