#!/usr/bin/env bash
# check_input_limits.sh DISKVAL SCENARIO_DIR: a scenario file is read with bounded
# memory and time (docs/scenarios.md):
#   - /dev/zero (never ends, no newline) and a 3 MiB file are refused at once
#     as larger than 1 MiB, with one line naming the file;
#   - a 1 MiB line is refused as too long, at its line;
#   - all of it under `ulimit -v` (1 GiB) and `timeout` (60 s: a hang, not a busy
#     machine; analyze of steady_circle.ini passed 10 s at load 12 on 2 cores),
#     peak RSS below 64 MiB:
#     a reader that grows a buffer to the line's length fails here;
#   - a FIFO with no writer (a scenario of analyze, simulate or a suite's
#     directory, a trajectory of judge) is one line and exit 2 at once, never
#     a wait for ever; a pipe with a writer (<(...)) is read as a file.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
scenarios=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -x /usr/bin/time ] || { echo "SKIP: no /usr/bin/time"; exit 77; }

# run diskval analyze FILE bounded; sets code, err (stderr) and rss (KiB)
bounded() {
  (ulimit -v 1048576; exec timeout -k 2 60 /usr/bin/time -f '%M' -o "$work/rss" \
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

# FIFOs with no writer: refused at once (timeout's 124: it waited)
mkdir "$work/fifos" && mkfifo "$work/fifos/a.ini" "$work/t.csv"
cp "$scenarios/steady_circle.ini" "$work/fifos/b.ini"
nowriter="$work/fifos/a.ini: a pipe with nothing to read (no writer has it open)"
# fifo WHAT WANT_ERR COMMAND...: exit 2, stderr WANT_ERR (a line), nothing under out/
fifo() {
  local what=$1 want=$2
  shift 2
  (cd "$work" && exec timeout -k 2 60 "$diskval" "$@") >/dev/null 2>"$work/err"
  code=$?
  err=$(cat "$work/err")
  check '[ $code -eq 2 ]' "$what: exit $code, want 2: $err"
  check '[ "$err" = "$want" ]' "$what: got: $err"
  check '[ ! -e "$work/out" ]' "$what: wrote $(ls "$work/out" 2>/dev/null)"
}
fifo "analyze of a FIFO" "$nowriter" analyze "$work/fifos/a.ini"
fifo "simulate of a FIFO" "$nowriter" simulate "$work/fifos/a.ini" --engine reduced --out out/x.csv
fifo "suite of a directory holding a FIFO" "$nowriter" suite "$work/fifos" --engines mujoco \
  --out out --quiet
fifo "judge of a FIFO" "diskval judge: $work/t.csv:1: an empty file: no header" \
  judge "$scenarios/steady_circle.ini" "$work/t.csv" --out out
# a pipe with a writer is read
(exec timeout -k 2 60 "$diskval" analyze <(sleep 0.5; cat "$scenarios/steady_circle.ini")) \
  >/dev/null 2>"$work/err"
code=$?
check '[ $code -eq 0 ]' "analyze <(cat steady_circle.ini): exit $code, want 0: $(cat "$work/err")"
exit $fail
