#!/usr/bin/env bash
# check_best_failed.sh DISKVAL SCENARIO_DIR: best where no probe can run
# (MuJoCo refuses C = 0) says why on every probe, shows no error for a run
# that measured nothing, and exits 2 (issue 23, item 14).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_best_failed.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_best_failed.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$dv" best "$sc/c_zero.ini" --engine mujoco --theta-tol 1e-3 >"$work/out" 2>"$work/err"; code=$?
check '[ $code -eq 2 ]' "exit $code, want 2: $(cat "$work/err")"
probes=$(grep -c " failed " "$work/out")
check '[ "$probes" -gt 0 ] && [ "$(grep -c " n/a .* failed (error: MuJoCo cannot load the disk model: .*mass and inertia" "$work/out")" -eq "$probes" ]' \
  "a failed probe does not say why: $(head -3 "$work/out")"
check '! grep -q "0\.000e+00" "$work/out"' "a failed probe shows an error of 0: $(head -3 "$work/out")"
check 'grep -q "^diskval best: no probe could run: MuJoCo cannot load the disk model" "$work/err"' \
  "stderr does not say why: $(cat "$work/err")"
exit $fail
