#!/usr/bin/env bash
# run_mutants.sh [SOURCE_DIR] [--only ID,...] [--jobs N] [--tests REGEX]
#                [--list FILE] [--out FILE] [--keep] [--check] [--quick-only]
#
# A mutation run of the test suite; not part of CTest (it takes over an hour).
# SOURCE_DIR's HEAD (default: the checkout this script is in) is copied with
# git archive into a temporary directory, so no working tree is touched, and
# built there once (Release); the suite must pass on it unmutated. Then each
# mutant of the list (default SOURCE_DIR/tests/mutants.txt, format there) is
# planted alone, rebuilt, and tested with ctest --stop-on-failure, the quick
# tier first (ctest -L quick; in it first the tests that killed earlier mutants)
# and, only when it survives there, the slow tier
# (-L slow): "killed" (with the first test that failed and its tier) or
# "survived"; the slow tier's unmutated run waits for the first mutant that
# needs it. One that does not build
# "did not compile", one whose ORIGINAL is not in its file exactly once "bad
# mutant" (both skipped, not counted). The file is restored before the next.
#
#   --only ID,...  run these mutants only
#   --jobs N       build and test jobs (default: the number of CPUs)
#   --tests REGEX  run only the tests matching REGEX (ctest -R), on top of the
#                  exclusions below: for a quick look, not for the kill rate
#   --list FILE    the mutants (default: SOURCE_DIR/tests/mutants.txt, as the working
#                  tree has it)
#   --out FILE     the markdown result, also printed (default: ./mutants-result.md)
#   --keep         keep the temporary directory (sources, build, logs)
#   --check        only check that every mutant's ORIGINAL occurs once; no build
#   --quick-only   no slow tier: a mutant the quick tier misses is counted survived (the
#                  kill rate a lower bound), in minutes where the slow tier takes a quarter
#                  of an hour
#
# Exit status: 0 when killed / (killed + survived) >= 90 % and the quick tier
# alone killed >= 90 % too, 1 below (or when nothing was measured), 2 on a
# usage or set-up error (the unmutated build or suite failing among them).
set -u

# Left out of every run, being slow or dependent on what the machine has; what
# they alone guard is not counted here:
#   scenario_with  (100 s) a scenario varied in memory is the file loaded with those overrides
#   cli/hoop       (90 s of MuJoCo) issue 24's hoop fails pointwise and on its period, and
#                  attribute's forecast for it holds within 2x
#   package        (an install, dpkg) the installed package: find_package, pkg-config,
#                  only diskval_* exported, the .deb
#   valgrind       (valgrind, minutes) no memory error or leak in a suite run
#   suite_render   (Chromium) the suite's index.html renders in a browser
#   mpi            (mpirun, run alone) sweeps and suites under MPI write what serial runs write
EXCLUDE='scenario_with|cli/hoop$|package|valgrind|suite_render|mpi'
TEST_TIMEOUT=600 # s, for a test without a TIMEOUT of its own: a mutant may make one hang
MIN_RATE=90      # %

usage() {
  echo "usage: run_mutants.sh [SOURCE_DIR] [--only ID,...] [--jobs N] [--tests REGEX]" \
    "[--list FILE] [--out FILE] [--keep] [--check] [--quick-only]" >&2
  exit 2
}
die() {
  echo "run_mutants.sh: $*" >&2
  exit 2
}
say() { echo "$*" >&2; }

src="" only="" jobs="" tests="" list="" out="mutants-result.md" keep=0 check=0 quick_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --only | --jobs | --tests | --list | --out)
      [ $# -ge 2 ] || usage
      case $1 in
        --only) only=$2 ;;
        --jobs) jobs=$2 ;;
        --tests) tests=$2 ;;
        --list) list=$2 ;;
        --out) out=$2 ;;
      esac
      shift 2
      ;;
    --keep) keep=1 && shift ;;
    --check) check=1 && shift ;;
    --quick-only) quick_only=1 && shift ;;
    -h | --help) usage ;;
    -*) usage ;;
    *)
      [ -z "$src" ] || usage
      src=$1 && shift
      ;;
  esac
done
[ -n "$src" ] || src="$(dirname "$0")/.."
dir=$(cd "$src" 2>/dev/null && pwd) || die "no such directory: $src"
src=$dir
git -C "$src" rev-parse --verify -q HEAD >/dev/null 2>&1 || die "$src: not a git checkout with a HEAD"
[ -n "$jobs" ] || jobs=$(nproc 2>/dev/null || echo 1)
case $jobs in '' | *[!0-9]* | 0) die "--jobs wants a whole number > 0, not '$jobs'" ;; esac
[ -n "$list" ] || list="$src/tests/mutants.txt"
[ -r "$list" ] || die "cannot read the mutant list $list"
case $out in /*) ;; *) out="$PWD/$out" ;; esac

# the list as ID, FILE, ORIGINAL, REPLACEMENT, WHAT separated by \037 (\| unescaped)
ids=() files=() origs=() repls=() whats=()
while IFS=$'\037' read -r id file orig repl what; do
  ids+=("$id") files+=("$file") origs+=("$orig") repls+=("$repl") whats+=("$what")
done < <(perl -ne 'next if /^\s*(#|$)/; chomp;
  my @f = map { s/\\\|/|/gr } split /(?<!\\)\|/, $_, 5;
  @f = ("line$.", "", "", "", "malformed line $.: $_") unless @f == 5 && length $f[0];
  print join("\037", @f), "\n";' "$list")
[ ${#ids[@]} -gt 0 ] || die "$list holds no mutants"

# --only: the positions of the IDs asked for, in the list's order
picked=()
if [ -n "$only" ]; then
  IFS=, read -r -a wanted <<<"$only"
  for want in "${wanted[@]}"; do
    found=0
    for i in "${!ids[@]}"; do [ "${ids[$i]}" = "$want" ] && found=1; done
    [ $found -eq 1 ] || die "--only: no mutant $want in $list"
  done
  for i in "${!ids[@]}"; do
    case ",$only," in *",${ids[$i]},"*) picked+=("$i") ;; esac
  done
else
  picked=("${!ids[@]}")
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/diskval-mutants.XXXXXX") || die "cannot make a temporary directory"
cleanup() {
  if [ $keep -eq 1 ]; then say "kept: $tmp"; else rm -rf "$tmp"; fi
}
trap cleanup EXIT
# each build or test step runs in a process group of its own (set -m), which INT or
# TERM stops as a whole (make, compilers, tests) before the directory goes
set -m
step_pid=""
step() {
  "$@" </dev/null &
  step_pid=$!
  wait "$step_pid"
  local rc=$?
  step_pid=""
  return $rc
}
stop() {
  [ -z "$step_pid" ] || kill -TERM -- "-$step_pid" 2>/dev/null
  wait
  exit "$1"
}
trap 'stop 130' INT
trap 'stop 143' TERM
mkdir "$tmp/src"
git -C "$src" archive HEAD | tar -x -C "$tmp/src"
[ "${PIPESTATUS[*]}" = "0 0" ] || die "cannot copy $src's HEAD"
commit=$(git -C "$src" rev-parse --short HEAD)
cd "$tmp/src" || die "cannot enter $tmp/src"

# plant ORIGINAL -> REPLACEMENT in FILE, or with DRY=1 only look; print the
# line, or the number of occurrences and exit 3 when it is not exactly one
plant() {
  ORIG=$2 REPL=$3 perl -e 'my $path = shift; local $/;
    open my $fh, "<", $path or exit 4; my $s = <$fh>; close $fh;
    my ($o, $r) = @ENV{qw(ORIG REPL)};
    my ($n, $p) = (0, -1);
    $n++ while length $o && ($p = index($s, $o, $p + 1)) >= 0;
    if ($n != 1) { print $n; exit 3 }
    my $at = index $s, $o;
    my $line = 1 + (() = substr($s, 0, $at) =~ /\n/g);
    substr($s, $at, length $o) = $r;
    unless ($ENV{DRY}) { open $fh, ">", $path or exit 4; print $fh $s; close $fh or exit 4 }
    print $line;' "$1"
}

# a mutant's FILE inside the copy, or "" when it names none
target() {
  case $1 in '' | /* | *..*) return ;; esac
  [ -f "$1" ] && echo "$1"
}

if [ $check -eq 1 ]; then
  bad=0
  for i in "${picked[@]}"; do
    f=$(target "${files[$i]}")
    if [ -z "$f" ]; then
      echo "${ids[$i]}: bad mutant: no file '${files[$i]}' (${whats[$i]})" && bad=1
    elif ! where=$(DRY=1 plant "$f" "${origs[$i]}" "${repls[$i]}"); then
      echo "${ids[$i]}: bad mutant: ORIGINAL found ${where:-?} times in $f" && bad=1
    else
      echo "${ids[$i]}: $f:$where"
    fi
  done
  exit $bad
fi

# ctest starts the costliest tests first; a mutant is mostly killed by a quick
# test, so every run is given the baseline's costs reversed (quick ones first)
fast_first() {
  local costs=build/Testing/Temporary/CTestCostData.txt
  [ -f "$tmp/fast-first.txt" ] ||
    perl -ane 'last if /^---/; push @r, [@F]; END { my $max = 0;
      $_->[2] > $max and $max = $_->[2] for @r;
      printf "%s %d %.6f\n", $_->[0], $_->[1], $max - $_->[2] + 1e-3 for @r; print "---\n" }' \
      "$costs" >"$tmp/fast-first.txt" 2>/dev/null || return 0
  cp "$tmp/fast-first.txt" "$costs"
}

ctest_run() { # TIER LOG [ONLY]: one tier of the suite as every run takes it, or of it the
  # tests matching the regex ONLY, or (ONLY "!REGEX") the others
  [ ! -f "$tmp/baseline-quick.log" ] || fast_first
  local only=() exclude=$EXCLUDE
  case ${3:-} in
    '') ;;
    '!'*) exclude="$EXCLUDE|${3#!}" ;;
    *) only=(-R "$3") ;;
  esac
  # a tier with no test left (--tests, EXCLUDE) passes: nothing there can kill
  step ctest --test-dir build --stop-on-failure -j "$jobs" --timeout "$TEST_TIMEOUT" \
    --no-tests=ignore --output-on-failure -L "^$1\$" -E "$exclude" ${tests:+-R "$tests"} \
    "${only[@]}" >"$2" 2>&1
}

# the quick tier, the tests that killed earlier mutants first: most mutants of a file
# fall to the test that killed its neighbour, and so need not wait for the rest
killers=""
quick_killed() { # LOG: 0 when the quick tier kills the planted mutant
  local first="^(${killers#|})\$"
  if [ -n "$killers" ]; then
    ctest_run quick "$1" "$first" || return 0
    mv "$1" "$1.first"
    ! ctest_run quick "$1" "!$first"
  else
    ! ctest_run quick "$1"
  fi
}

# the slow tier unmutated, once, when a mutant first survives the quick one
slow_baseline() {
  [ ! -f "$tmp/baseline-slow.ok" ] || return 0
  say "running the slow tier unmutated (a mutant survived the quick one)"
  cp "$tmp/pristine" "$f" && step cmake --build build -j "$jobs" >"$tmp/build-pristine.log" 2>&1 ||
    die "cannot rebuild unmutated for the slow tier's baseline"
  if ! ctest_run slow "$tmp/baseline-slow.log"; then
    tail -n 30 "$tmp/baseline-slow.log" >&2
    die "the unmutated slow tier fails ($(first_failure "$tmp/baseline-slow.log")): no mutant can be judged there"
  fi
  touch "$tmp/baseline-slow.ok"
  plant "$f" "${origs[$i]}" "${repls[$i]}" >/dev/null && step cmake --build build -j "$jobs" >>"$tmp/build-$log.log" 2>&1 ||
    die "cannot plant ${ids[$i]} again after the slow tier's baseline"
}

# the first test that failed in a ctest log (in the order they ended)
first_failure() {
  local name
  # a skipped test (***Skipped) is not a failure
  name=$(sed -n -E 's/^ *[0-9]+\/[0-9]+ +Test +#[0-9]+: ([^ ]+) .*\*\*\*(Failed|Timeout|Exception|Not Run).*/\1/p' "$1" |
    head -n 1)
  [ -n "$name" ] ||
    name=$(sed -n '/The following tests FAILED/,$p' "$1" |
      sed -n -E 's/^[[:space:]]+[0-9]+ - (.+) \([^)]*\)$/\1/p' | head -n 1)
  echo "$name"
}

started=$(date +%s)
say "copied $src at $commit into $tmp; configuring"
step cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >"$tmp/configure.log" 2>&1 ||
  { tail -n 20 "$tmp/configure.log" >&2; die "cmake configure failed (log above)"; }
say "building with -j $jobs"
step cmake --build build -j "$jobs" >"$tmp/build.log" 2>&1 ||
  { tail -n 20 "$tmp/build.log" >&2; die "the unmutated build failed (log above)"; }
say "running the quick tier unmutated${tests:+ (tests matching $tests)}"
if ! ctest_run quick "$tmp/baseline-quick.log"; then
  tail -n 30 "$tmp/baseline-quick.log" >&2
  die "the unmutated quick tier fails ($(first_failure "$tmp/baseline-quick.log")): no mutant can be judged"
fi
say "the unmutated quick tier passes ($(($(date +%s) - started)) s so far)"

rows=() killed=0 by_quick=0 survived=0 broken=0 bad=0 n=0
for i in "${picked[@]}"; do
  n=$((n + 1))
  id=${ids[$i]} file=${files[$i]} what=${whats[$i]} by="" tier="" where="?"
  log=${id//[^A-Za-z0-9_.-]/_}
  t0=$(date +%s)
  f=$(target "$file")
  if [ -z "$f" ]; then
    result="bad mutant (no such file)" && bad=$((bad + 1))
  else
    cp "$f" "$tmp/pristine"
    if ! where=$(plant "$f" "${origs[$i]}" "${repls[$i]}"); then
      result="bad mutant (ORIGINAL found ${where:-?} times)" && bad=$((bad + 1)) && where="?"
    elif ! step cmake --build build -j "$jobs" >"$tmp/build-$log.log" 2>&1; then
      result="did not compile" && broken=$((broken + 1))
    elif quick_killed "$tmp/ctest-$log.log"; then
      result="killed" && killed=$((killed + 1)) && by_quick=$((by_quick + 1)) && tier=quick
    elif [ $quick_only -eq 1 ] || { slow_baseline && ctest_run slow "$tmp/ctest-$log.log"; }; then
      result="survived" && survived=$((survived + 1))
    else
      result="killed" && killed=$((killed + 1)) && tier=slow
    fi
    if [ -n "$tier" ]; then
      by=$(first_failure "$tmp/ctest-$log.log")
      [ -n "$by" ] || by="(ctest failed, no test named)"
      case "|$killers|" in *"|$by|"*) ;; *) [ "${by:0:1}" = "(" ] || killers="$killers|$by" ;; esac
    fi
    cp "$tmp/pristine" "$f" # a fresh mtime: the next build recompiles it
  fi
  say "[$n/${#picked[@]}] $id $file:$where: $result${by:+ by $by ($tier tier)} ($(($(date +%s) - t0)) s)"
  rows+=("| $id | $file:$where | ${what//|/\\|} | $result | ${by:--} | ${tier:--} |")
done

measured=$((killed + survived))
percent() { # PART: PART / measured as a percentage, one decimal
  if [ $measured -gt 0 ]; then
    echo "$(($1 * 100 / measured)).$(($1 * 1000 / measured % 10)) %"
  else
    echo "n/a (nothing killed or survived)"
  fi
}
rate=$(percent $killed) quick_rate=$(percent $by_quick)
how="ctest --stop-on-failure -L quick, then -L slow for a survivor; -E '$EXCLUDE'"
[ $quick_only -eq 0 ] || how="ctest --stop-on-failure -L quick only (no slow tier); -E '$EXCLUDE'"
[ -z "$tests" ] || how="$how -R '$tests'"
{
  echo "# Mutation run"
  echo
  echo "Source $commit; ${#picked[@]} mutants from ${list#"$src"/}; tests: $how;" \
    "$(($(date +%s) - started)) s."
  echo
  echo "| id | file:line | what | result | killed by | tier |"
  echo "|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Killed $killed ($by_quick by the quick tier), survived $survived, did not compile" \
    "$broken, bad mutants $bad; kill rate (killed / (killed + survived)) $rate, by the" \
    "quick tier alone $quick_rate."
} >"$tmp/result.md"
cp "$tmp/result.md" "$out" || die "cannot write $out"
cat "$tmp/result.md"
[ $measured -gt 0 ] && [ $((killed * 100)) -ge $((MIN_RATE * measured)) ] &&
  [ $((by_quick * 100)) -ge $((MIN_RATE * measured)) ]
