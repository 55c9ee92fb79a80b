#!/usr/bin/env bash
# check_output_faults.sh DISKVAL SCENARIO_DIR: outputs that cannot be written,
# and runs that die while writing.
#   - simulate ended by SIGINT or SIGTERM dies of that signal and leaves no
#     temporary file; one killed by SIGKILL leaves its temporary, which the
#     next run writing the same file removes, while a temporary whose owner
#     lives is kept;
#   - an --out that is a regular file or /dev/full is refused before any run,
#     in one line, exit 2; output on stdout that cannot be written (/dev/full)
#     is exit 2 with one line saying so.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_output_faults.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_output_faults.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
set -m # background runs get SIGINT like a foreground one (no job control: ignored)

# the 60 s scene in MuJoCo takes 20 s: still running when the signal comes
long=$sc/hard/long_horizon.ini
# start_long OUT: simulate in the background, once its temporary exists
start_long() {
  "$dv" simulate "$long" --engine mujoco --out "$1" --forces "$1.forces" 2>/dev/null &
  pid=$!
  for _ in $(seq 1200); do # up to 60 s: a sanitizer build on a busy machine starts slowly
    compgen -G ".diskval-tmp.$pid.*" >/dev/null && return
    sleep 0.05
  done
}
for sig in INT TERM; do
  start_long "$sig.csv"
  kill -"$sig" "$pid"
  wait "$pid"
  code=$?
  want=$((128 + $(kill -l "$sig")))
  check '[ $code -eq $want ]' "SIG$sig: exit $code, want $want (died of the signal)"
  check '[ -z "$(ls -A | grep diskval-tmp)" ]' "SIG$sig: temporaries remain: $(ls -A | grep diskval-tmp)"
done

start_long kill.csv
kill -KILL "$pid"
wait "$pid"
check '[ -n "$(compgen -G ".diskval-tmp.$pid.*")" ]' "SIGKILL: no temporary to clean (the test proves nothing)"
touch ".diskval-tmp.$$.abcdef" # this shell's: alive
"$dv" simulate "$sc/falling.ini" --engine reduced --out kill.csv 2>/dev/null
code=$?
check '[ $code -eq 0 ] && [ -s kill.csv ]' "after SIGKILL: exit $code"
check '[ -z "$(compgen -G ".diskval-tmp.$pid.*")" ]' "the dead run's temporary was not removed"
check '[ -e ".diskval-tmp.$$.abcdef" ]' "a live process's temporary was removed"

# expect_refusal REGEX ARGS...: exit 2, one stderr line matching REGEX, no stdout
expect_refusal() {
  local regex=$1
  shift
  "$dv" "$@" >out.txt 2>err.txt
  local code=$?
  if [ $code -ne 2 ] || [ "$(wc -l <err.txt)" -ne 1 ] || ! grep -Eq -e "$regex" err.txt ||
    [ -s out.txt ]; then
    echo "FAIL: diskval $*: exit $code, stderr: $(cat err.txt), stdout: $(head -c 200 out.txt)"
    fail=1
  fi
}
touch plain
expect_refusal "plain: not a directory" compare "$sc/falling.ini" --out plain
expect_refusal "plain: not a directory" suite "$sc/falling.ini" --out plain
expect_refusal "/dev/full: not a directory" suite "$sc/falling.ini" --out /dev/full
expect_refusal "plain: not a directory" sweep "$sc/falling.ini" --engine mujoco \
  --vary timestep=1e-3 --out plain
expect_refusal "plain: not a directory" map --c 0.2..0.4:2 --spin 5..6:2 --out plain
check '[ ! -s plain ]' "a refused --out was written"

# expect_lost_stdout ARGS...: stdout is /dev/full: exit 2, one line saying so
# (besides the long-run warning, which a busy machine's probe brings: compare of
# falling.ini said "will take about 1m55s" at load 13 on 2 cores)
expect_lost_stdout() {
  "$dv" "$@" >/dev/full 2>err.txt
  local code=$?
  if [ $code -ne 2 ] || [ "$(grep -vc 'will take about' err.txt)" -ne 1 ] ||
    ! grep -q "No space left" err.txt; then
    echo "FAIL: diskval $* >/dev/full: exit $code, stderr: $(cat err.txt)"
    fail=1
  fi
}
expect_lost_stdout analyze "$sc/falling.ini"
expect_lost_stdout analyze "$sc/falling.ini" --json
expect_lost_stdout engines
expect_lost_stdout --help
expect_lost_stdout compare --help
expect_lost_stdout compare "$sc/falling.ini" --out cmp
expect_lost_stdout simulate "$sc/falling.ini" --engine reduced
expect_lost_stdout simulate "$sc/falling.ini" --engine reduced --out /dev/full

[ $fail -eq 0 ] && echo "output faults: refused or cleaned up"
exit $fail
