#!/usr/bin/env bash
# check_cause_quick.sh DISKVAL SAUCER: compare's --cause quick names the cause
# --cause full names, with fewer knob runs; --cause none runs none; a bad mode
# is refused with one line. Knob runs are counted on DV_CAUSE_TRACE's lines
# ("cause trace: ENGINE: KNOB (CHANGE): worst W, ..."). Two failing cases whose
# causes differ, made short (re-run: the commands below with DV_CAUSE_TRACE=1):
#   integrator  MuJoCo rk4 over 0.5 s, path limit 1e-5 m: path 9.18e-4 m, of
#               which the spread of its early error excuses 8.8e-4 m (issue 48);
#               full: euler 3.58e-4, implicit 1.01e-4 remove it, the step
#               /4 leaves worst 2.29; quick tries the integrator first (its
#               signature: nothing over but the path, and a time integrator
#               to choose): euler removes it, 1 run, full 5
#   timestep    Bullet at 1.6e-4 s over 1 s: theta 3.16e-3 > 1e-3 rad, energy
#               0.59 % of 1 %; full: only the step /4 removes it (worst 0.79,
#               body 6.37); quick tries it first: 1 run, full 4
#   window      the same Bullet over the scene's 3 s, limits 1e-4 rad and
#               1e-3 m: theta 9.38e-3 rad against 1.4e-3 (the spread of its
#               early error 1.3e-3 rad); full: no knob removes it (the step /4
#               leaves worst 1.67); quick over the first 0.6075 s: the step /4 removes that
#               window's error (worst 0.392) but not the whole run's, which it
#               then runs: no cause named, as full
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1 saucer=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mujoco=(--engines mujoco --set engines.mujoco.integrator=rk4 --set scenario.duration=0.5
  --set tolerance.mujoco.path_max_err=1e-5)
bullet=(--engines bullet --set engines.bullet.timestep=1.6e-4 --set scenario.duration=1)
# the knob named in stdout's cause, and the knob runs on stderr
run() { # NAME MODE ARGS...
  local name=$1 mode=$2
  shift 2
  DV_CAUSE_TRACE=1 "$diskval" compare "$saucer" "$@" --cause "$mode" --quiet \
    --out "$work/r" >"$work/$name.$mode.out" 2>"$work/$name.$mode.err"
}
cause() { grep -m1 -o "; cause: [a-z ]*" "$work/$1.out" | sed 's/; cause: //; s/ *$//'; }
runs() { grep -c "^cause trace: .*: worst " "$work/$1.err"; }
for name in mujoco bullet; do
  declare -n args=$name
  run "$name" full "${args[@]}"
  run "$name" quick "${args[@]}"
done
check '[ "$(cause mujoco.full)" = integrator ]' "full, mujoco: $(cat "$work/mujoco.full.out")"
check '[ "$(cause bullet.full)" = timestep ]' "full, bullet: $(cat "$work/bullet.full.out")"
for name in mujoco bullet; do
  check '[ "$(cause $name.quick)" = "$(cause $name.full)" ]' \
    "quick names another cause than full for $name: $(cat "$work/$name.quick.out")"
  check '[ "$(runs $name.quick)" -lt "$(runs $name.full)" ]' \
    "$name: quick ran $(runs $name.quick) knobs, full $(runs $name.full)"
  check 'grep -q "(quick; --cause full tries all)" "$work/$name.quick.out"' \
    "$name: quick does not say what it tried: $(cat "$work/$name.quick.out")"
done
check '[ "$(runs bullet.quick)" -eq 1 ]' "bullet: the step is not tried first: $(cat "$work/bullet.quick.err")"
# a knob that removes the error over the short window only is no cause
window=(--engines bullet --set engines.bullet.timestep=1.6e-4 --set tolerance.theta_max_err=1e-4
  --set tolerance.path_max_err=1e-3)
run window full "${window[@]}"
run window quick "${window[@]}"
check 'grep -q "; cause: none of the knobs removes it" "$work/window.full.out"' \
  "full, window: $(cat "$work/window.full.out")"
check 'grep -q "^cause trace: bullet: timestep .* with scenario.duration=0\.[5-9][0-9]*: .*removes it" "$work/window.quick.err"' \
  "quick did not try the step over the first second: $(cat "$work/window.quick.err")"
check 'grep -q "; cause: not found among .*(quick, each over the first 0\.[5-9][0-9]* s" "$work/window.quick.out"' \
  "quick names a cause full does not: $(cat "$work/window.quick.out")"
run bullet none "${bullet[@]}"
check '[ "$(runs bullet.none)" -eq 0 ] && grep -q "; cause: not searched (--cause none)" "$work/bullet.none.out"' \
  "--cause none: $(cat "$work/bullet.none.out" "$work/bullet.none.err")"
refused "--cause bogus" "^diskval compare: --cause bogus: quick, full or none" \
  "$diskval" compare "$saucer" --cause bogus
[ $fail -eq 0 ] && echo "cause: quick names full's cause with fewer runs; none runs none"
exit $fail
