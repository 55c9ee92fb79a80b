#!/usr/bin/env bash
# check_valgrind.sh DISKVAL SCENARIO_DIR: memcheck over one suite run (every
# contact engine and the references, every child process): no errors, no
# leaks definitely lost. Skipped (77) where valgrind is not installed.
set -u
command -v valgrind >/dev/null || { echo "SKIP: valgrind not installed"; exit 77; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
valgrind --tool=memcheck --trace-children=yes --leak-check=full --errors-for-leak-kinds=definite \
  --error-exitcode=99 --log-file="$out/vg.%p" \
  "$1" suite "$2/falling.ini" --out "$out/report" --jobs 1 >/dev/null
code=$?
grep -h "ERROR SUMMARY\|definitely lost" "$out"/vg.* | sort | uniq -c
if [ $code -ne 0 ]; then
  echo "FAIL: exit $code"
  grep -h -B2 -A12 "Invalid\|uninitialised\|definitely lost in" "$out"/vg.* | head -80
  exit 1
fi
echo "valgrind: clean"
