#!/usr/bin/env bash
# check_valgrind.sh DISKVAL SCENARIO_DIR JUDGE_TO_POSE SHORT_CIRCLE ADAPTERS: memcheck
# (every diskval process, forked or not) over short runs that take every code path
# a whole scene takes: no errors, no leaks definitely lost. Skipped (77) where
# valgrind is not installed.
#  - a suite of falling.ini cut to 0.2 s: the settings probes, every contact
#    engine (ODE, MuJoCo, Bullet, DART, Simbody), the references and the nudged
#    ones, judging, the report and the suite's pages, in the pool's processes;
#  - judge of a pose-form trajectory file (trajectory files, pose conversion);
#  - compare with the test adapter (tests/adapters/replay) passing, then
#    sending garbage (the adapter protocol and its fault path).
# The whole falling.ini suite took 387 s under valgrind in the suite's run; these
# take 63 s in `ctest -R valgrind` on busy cores. A leak planted in judge's replay
# (run/file/run_replay.c, r->t not freed) fails it at the judge step.
set -u
command -v valgrind >/dev/null || { echo "SKIP: valgrind not installed"; exit 77; }
dv=$1 scenarios=$2 to_pose=$3 short=$4 adapters=$5
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail=0
# the shell and tools an adapter runs are not ours: only diskval is traced
vg() {
  valgrind --tool=memcheck --trace-children=yes --trace-children-skip='/bin/*,/usr/bin/*' \
    --leak-check=full --errors-for-leak-kinds=definite --error-exitcode=99 \
    --log-file="$out/vg.%p" "$@"
}
# ran WHAT CODE WANT: the exit status of WHAT is one of WANT (99: valgrind found errors)
ran() {
  case " $3 " in *" $2 "*) echo "$1: exit $2" ;; *) echo "FAIL: $1: exit $2, want $3"; fail=1 ;; esac
}

vg "$dv" suite "$scenarios/falling.ini" --set scenario.duration=0.2 --out "$out/suite" \
  --jobs 1 >/dev/null
ran "suite of falling.ini over 0.2 s" $? "0 1"

awk '/^\[disk\]/{print; print "thickness = 0.002"; next} {print}' "$short" >"$out/thick.ini"
"$dv" simulate "$out/thick.ini" --engine matched --out "$out/ref.csv" --quiet --set scenario.duration=0.2
"$to_pose" 0.1 0.001 <"$out/ref.csv" >"$out/pose.csv"
vg "$dv" judge "$out/thick.ini" "$out/pose.csv" --out "$out/judge" --quiet --set scenario.duration=0.2 \
  >/dev/null
ran "judge of a pose file" $? "0 1"

export DISKVAL_ADAPTERS=$adapters DV_REPLAY_POSE=$out/pose.csv
vg "$dv" compare "$out/thick.ini" --engines replay --out "$out/adapter" --quiet \
  --set scenario.duration=0.2 >/dev/null
ran "compare of the replay adapter" $? "0 1"
DV_REPLAY_FAULT=garbage vg "$dv" compare "$out/thick.ini" --engines replay --cause none \
  --out "$out/fault" --quiet --set scenario.duration=0.2 >"$out/fault.out"
code=$?
ran "compare of the replay adapter sending garbage" $code "1"
grep -q "replay .*FAIL" "$out/fault.out" || { echo "FAIL: the adapter's garbage did not fail its run"; fail=1; }

grep -h "ERROR SUMMARY\|definitely lost" "$out"/vg.* | sort | uniq -c
if [ $fail -ne 0 ]; then
  grep -h -B2 -A12 "Invalid\|uninitialised\|definitely lost in" "$out"/vg.* | head -80
  exit 1
fi
echo "valgrind: clean"
