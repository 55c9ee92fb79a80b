#!/usr/bin/env bash
# check_bad_scenario.sh: proves that diskval rejects a bad scenario cleanly.
#
#   check_bad_scenario.sh DISKVAL FILE               FILE's first line is "; expect: REGEX"
#   check_bad_scenario.sh DISKVAL FILE --empty       FILE is empty: expect ":1: " and "scenario"
#   check_bad_scenario.sh DISKVAL FILE --binary      FILE is binary garbage: expect ":1: "
#   check_bad_scenario.sh DISKVAL DIR                a directory instead of a file
#   check_bad_scenario.sh DISKVAL FILE --unreadable  a chmod 000 copy of FILE (exit 77 = skip
#                                                    when the copy stays readable, e.g. as root)
#   check_bad_scenario.sh DISKVAL FILE --missing     FILE does not exist
#   check_bad_scenario.sh DISKVAL FILE --valid       FILE is good: the control case
#
# Each run is `DISKVAL simulate FILE --engine reduced --out $tmp/out.csv`, in a
# fresh temporary directory, under `timeout 20`. A bad scenario passes only if
#   - the exit status is exactly 2,
#   - stderr is exactly one newline-terminated line,
#   - that line is "FILE:LINE: ..." (FILE made absolute, as diskval gets it),
#     or, for a file that cannot be read (directory, unreadable, missing),
#     "FILE: what" with no line number,
#   - the rest of the line, from the ':' after FILE on, matches the extended
#     regex REGEX (grep -E, case-sensitive),
#   - $tmp/out.csv was not created.
# A valid scenario passes only if the exit status is 0 and $tmp/out.csv exists,
# starts with the header line below, and holds at least one data row.
# Exit status: 0 pass, 1 fail (with a message), 77 skipped, 2 usage error.
set -u
export LC_ALL=C

HEADER='t,theta,phi,psi,x,y,contact_x,contact_y,theta_dot,phi_dot,psi_dot,energy'

usage() {
  echo "usage: $0 DISKVAL FILE|DIR [--valid|--empty|--binary|--unreadable|--missing]" >&2
  exit 2
}
[ $# -eq 2 ] || [ $# -eq 3 ] || usage
diskval=$1 file=$2 mode=${3:-}
[ -d "$file" ] && [ -z "$mode" ] && mode=--directory
case $mode in '' | --valid | --empty | --binary | --unreadable | --directory | --missing) ;; *) usage ;; esac

absolute() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
diskval=$(absolute "$diskval")
file=$(absolute "$file")

tmp=$(mktemp -d "${TMPDIR:-/tmp}/check_bad_scenario.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
name=${file##*/}

fail() {
  echo "FAIL: $name: $*"
  if [ -s "$tmp/stderr" ]; then
    echo "--- stderr:"
    cat -v "$tmp/stderr"
  fi
  if [ -s "$tmp/stdout" ]; then
    echo "--- stdout (first lines):"
    head -n 5 "$tmp/stdout" | cat -v
  fi
  exit 1
}

[ -x "$diskval" ] || fail "diskval is not an executable: $diskval"

# what the error line must match, and the file diskval is given
case $mode in
  --valid) [ -f "$file" ] || fail "no such file: $file" ;;
  --directory)
    [ -d "$file" ] || fail "not a directory: $file"
    regex='^: is a directory, not a scenario file$' ;;
  --missing)
    [ -e "$file" ] && fail "exists: $file"
    regex='^: cannot open: No such file or directory$' ;;
  --empty)
    { [ -f "$file" ] && [ ! -s "$file" ]; } || fail "not an empty file: $file"
    regex=':1: .*scenario' ;;
  --binary)
    [ -s "$file" ] || fail "not a non-empty file: $file"
    regex=':1: ' ;;
  --unreadable)
    [ -f "$file" ] || fail "no such file: $file"
    cp "$file" "$tmp/unreadable.ini" || fail "cannot copy $file"
    chmod 000 "$tmp/unreadable.ini" || fail "cannot chmod 000 the copy"
    if [ -r "$tmp/unreadable.ini" ]; then
      echo "SKIP: $name: a chmod 000 file stays readable (running as root?)"
      exit 77
    fi
    file=$tmp/unreadable.ini
    regex='^: cannot open: Permission denied$' ;;
  '')
    [ -f "$file" ] || fail "no such file: $file"
    IFS= read -r first <"$file" || true
    first=${first%$'\r'}
    case $first in
      '; expect: '?*) regex=${first#'; expect: '} ;;
      *) fail "first line is not '; expect: REGEX'" ;;
    esac ;;
esac

(cd "$tmp" && exec timeout -k 5 20 "$diskval" simulate "$file" --engine reduced --out "$tmp/out.csv" \
  >"$tmp/stdout" 2>"$tmp/stderr" </dev/null)
status=$?
[ "$status" -eq 124 ] && fail "timed out after 20 s"
[ "$status" -gt 128 ] && fail "killed by signal $((status - 128))"

if [ "$mode" = --valid ]; then
  [ "$status" -eq 0 ] || fail "exit status $status, want 0"
  [ -f "$tmp/out.csv" ] || fail "no CSV written"
  IFS= read -r first <"$tmp/out.csv" || true
  [ "$first" = "$HEADER" ] || fail "CSV header is '$first', want '$HEADER'"
  [ "$(wc -l <"$tmp/out.csv")" -ge 2 ] || fail "CSV has no data rows"
  echo "PASS: $name: accepted, CSV written"
  exit 0
fi

[ "$status" -eq 2 ] || fail "exit status $status, want 2"
[ -e "$tmp/out.csv" ] && fail "out.csv was created for a bad scenario"
# one line: exactly one newline, and it is the last byte
{ [ "$(wc -l <"$tmp/stderr")" -eq 1 ] && [ -z "$(tail -c 1 "$tmp/stderr")" ]; } ||
  fail "stderr is not exactly one line"
IFS= read -r line <"$tmp/stderr"
case $line in
  "$file":*) ;;
  *) fail "error line does not start with '$file:'" ;;
esac
rest=${line#"$file"}
case $mode in
  --directory | --unreadable | --missing) ;; # no line to point at
  *) grep -aEq '^:[0-9]+: .' <<<"$rest" || fail "error line is not 'FILE:LINE: key: what'" ;;
esac
grep -aEq -- "$regex" <<<"$rest" || fail "error line does not match /$regex/"
echo "PASS: $name: $line"
exit 0
