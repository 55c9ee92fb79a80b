#!/usr/bin/env bash
# check_sweep_order.sh DISKVAL DATA_DIR: a sweep fits an order of convergence
# and an accuracy floor only over the step its engine declares (issue 23,
# item 18): over disk.radius it says there is none, on stdout and in
# sweep.json ("orders": []); over the timestep it fits one (the control), and
# its work-precision plot labels the reference's curves as against the
# reference's own tighter run (issue 25, item 4).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_sweep_order.sh DISKVAL DATA_DIR}
data=${2:?usage: check_sweep_order.sh DISKVAL DATA_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2

"$dv" sweep "$data/short_circle.ini" --engine mujoco --vary disk.radius=0.1,0.12,0.15 \
  --out radius --jobs 2 --quiet >stdout 2>stderr
code=$?
check '[ $code -eq 0 ]' "radius: exit $code: $(cat stderr)"
check '! grep -Eq "order [0-9.]+ over|accuracy floor" stdout' "radius: an order or floor: $(cat stdout)"
check 'grep -q "^no order of convergence: disk.radius is not mujoco.s step (engines.mujoco.timestep)$" stdout' \
  "radius: stdout does not say why there is no order: $(cat stdout)"
check '[ "$(jq -c .orders radius/sweep.json)" = "[]" ]' "radius: sweep.json: $(jq -c .orders radius/sweep.json)"

"$dv" sweep "$data/short_circle.ini" --engine mujoco --vary timestep=2e-3,1e-3,5e-4 \
  --out step --jobs 2 --quiet >stdout 2>stderr
code=$?
check '[ $code -eq 0 ] && grep -Eq "^mujoco: order [0-9.]+ over 3 points" stdout' \
  "timestep: exit $code, no order: $(cat stdout)"
check '[ "$(jq ".orders | length" step/sweep.json)" = 1 ]' "timestep: sweep.json has no order"
# the work-precision plot draws the reference's own curves beside the engine's:
# they are against a tighter run of the reference, and say so; none is "no data"
if command -v perl >/dev/null; then
  perl -pe 's/&#x([0-9a-f]+);/chr(hex($1))/ge' step/work_precision.svg 2>/dev/null >wp.txt
  check '[ "$(grep -c "reduced [a-z0-9-]* (vs its own tighter run)" wp.txt)" -ge 5 ]' \
    "the reference's curves do not say what they are against: $(grep -o "reduced [^<]*" wp.txt | head -3)"
  check '! grep -q "no data" wp.txt' "a curve called no data: $(grep -o "[^>]*no data[^<]*" wp.txt)"
fi

[ $fail -eq 0 ] && echo "sweep order: fitted over the engine's step only"
exit $fail
