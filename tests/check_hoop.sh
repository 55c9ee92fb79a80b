#!/usr/bin/env bash
# check_hoop.sh DISKVAL HOOP OUT: the hoop of tests/data/wheel_wobble.ini fails
# MuJoCo pointwise under the dynamics' horizon and on its period, and the
# attribution that follows is announced with a forecast within 2x of what the
# whole command took. The horizon (issue 24, item 1): the reference amplifies a
# 1e-6 rad nudge linearly (x99 in 8 s) and MuJoCo's early error (1.1e-6 rad)
# never grows to the limit, so its pointwise error is judged over the whole
# window; the period (item 2) is limited to 0.01 rad over the reference's
# fastest theta rate, 3.27 rad/s: 3.06e-3 s. MuJoCo at the settings the scene
# chooses (implicit, 8e-6 s) errs 0.043 rad and its period 5.2e-3 s a cycle
# (with rk4, the old default, 0.337 rad and 0.042 s): exit 1, where a 1e-3 rad
# nudge ended pointwise judging at 0.7 s and it passed. Measured: the cause's
# forecast 1m18s (28 runs of the 2.8 s run), the whole command 85 s.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1 hoop=$2 out=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rm -rf "$out"
began=$(date +%s.%N)
"$diskval" compare "$hoop" --engines mujoco --out "$out" >"$work/out" 2>"$work/err"
code=$?
took=$(awk -v a="$began" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
check '[ $code -eq 1 ]' "exit $code, want 1: $(cat "$work/out" "$work/err")"
check 'grep -Eq "wheel_wobble: mujoco: theta_max_err = 0\.0[1-9][0-9]* > 0\.01 \(default: 0\.01 rad\)" "$work/out"' \
  "no pointwise failure: $(cat "$work/out")"
check "grep -Eq \"wheel_wobble: mujoco: nutation_period_err = 0\\.00[3-9][0-9]* > 0\\.0030[0-9]+ \\(default: 0\\.01 rad over the reference's fastest theta rate, 3\\.27 rad/s\\)\" \"\$work/out\"" \
  "no period failure: $(cat "$work/out")"
line=$(grep "mujoco: its cause (.* runs' worth) will take about" "$work/err")
check '[ -n "$line" ]' "the attribution was not announced: $(cat "$work/err")"
said=$(sed -n 's/.*will take about \([0-9hms]*\) .*/\1/p' <<<"$line" |
  awk '{ s = 0; n = ""; for (i = 1; i <= length($0); i++) { c = substr($0, i, 1);
         if (c ~ /[0-9]/) n = n c; else { s += n * (c == "h" ? 3600 : c == "m" ? 60 : 1); n = "" } }
         print s }')
check 'awk -v f="$said" -v t="$took" "BEGIN { exit !(f >= t / 2 && f <= 2 * t) }"' \
  "forecast ${said:-?} s, the command took $took s: $line"
echo "forecast $said s, took $took s"
exit $fail
