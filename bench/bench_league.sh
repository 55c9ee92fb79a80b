#!/usr/bin/env bash
# bench_league.sh DISKVAL SOURCE_DIR [OUT]: the league, timed.
#   - the quick default (league/, every engine diskval engines lists, 1e-3 rad):
#     its wall time against the goal of 15 minutes on 2 cores;
#   - the full set (league/ and league/more/, targets 1e-2, 1e-3, 1e-4) into OUT
#     (default: a temporary folder; give one to keep the table, and to resume an
#     interrupted run there).
# Prints each league's summary lines, its wall time, and PASS/FAIL for the goal.
set -u
diskval=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=${3:-$work/full}
t0=$(date +%s)
(cd "$src" && "$diskval" league --quiet --out "$work/quick") || echo "the quick league exited $?"
t1=$(date +%s)
quick=$((t1 - t0))
[ "$quick" -le 900 ] && verdict=PASS || verdict=FAIL
echo "league, quick default: ${quick} s on $(nproc) cores (goal 900 s on 2): $verdict"
"$diskval" league "$src/league" "$src/league/more" --targets 1e-2,1e-3,1e-4 --quiet --out "$out" ||
  echo "the full league exited $?"
echo "league, full set: $(($(date +%s) - t1)) s; the table: $out/league.md"
