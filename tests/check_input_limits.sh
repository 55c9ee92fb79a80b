#!/usr/bin/env bash
# check_input_limits.sh DISKVAL SCENARIO_DIR: a scenario file is read with bounded
# memory and time (README "Scenario files"):
#   - /dev/zero (never ends, no newline) and a 3 MiB file are refused at once
#     as larger than 1 MiB, with one line naming the file;
#   - a 1 MiB line is refused as too long, at its line;
#   - all of it under `ulimit -v` (1 GiB) and `timeout`, peak RSS below 64 MiB:
#     a reader that grows a buffer to the line's length fails here.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
scenarios=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -x /usr/bin/time ] || { echo "SKIP: no /usr/bin/time"; exit 77; }

# run diskval analyze FILE bounded; sets code, err (stderr) and rss (KiB)
bounded() {
  (ulimit -v 1048576; exec timeout -k 2 10 /usr/bin/time -f '%M' -o "$work/rss" \
    "$diskval" analyze "$1") >/dev/null 2>"$work/err"
  code=$?
  err=$(cat "$work/err")
  rss=$(tail -n 1 "$work/rss" 2>/dev/null || echo 0)
}

bounded /dev/zero
check '[ $code -eq 2 ]' "/dev/zero: exit $code, want 2"
check '[ "$err" = "/dev/zero: more than the 1 MiB a scenario file may have" ]' "/dev/zero: got: $err"
check '[ "$rss" -lt 65536 ]' "/dev/zero: peak RSS $rss KiB"

head -c 3145728 /dev/zero | tr '\0' a >"$work/big.ini"
bounded "$work/big.ini"
check '[ $code -eq 2 ]' "3 MiB file: exit $code, want 2"
check '[ "$err" = "$work/big.ini: 3.0 MiB, more than the 1 MiB a scenario file may have" ]' \
  "3 MiB file: got: $err"
check '[ "$rss" -lt 65536 ]' "3 MiB file: peak RSS $rss KiB"

{ cat "$scenarios/steady_circle.ini"; head -c 1000000 /dev/zero | tr '\0' ';'; echo; } >"$work/long.ini"
line=$(($(wc -l <"$scenarios/steady_circle.ini") + 1))
bounded "$work/long.ini"
check '[ $code -eq 2 ]' "a 1 MB line: exit $code, want 2"
check '[ "$err" = "$work/long.ini:$line: syntax: line longer than 198 characters" ]' \
  "a 1 MB line: got: $err"
check '[ "$rss" -lt 65536 ]' "a 1 MB line: peak RSS $rss KiB"

# the same file within the limits still loads
bounded "$scenarios/steady_circle.ini"
check '[ $code -eq 0 ]' "steady_circle.ini: exit $code, want 0: $err"
exit $fail
