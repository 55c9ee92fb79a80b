#!/usr/bin/env bash
# check_adapters_node.sh DISKVAL CIRCLE FALL: the shipped adapters (adapters/,
# on Node; skipped where Node or their packages are not installed) are judged
# like linked engines, on the thin steady circle CIRCLE and the fall FALL, both
# made 2 mm thick (the body every adapter models exactly or by its stand-in):
#   - each of mujoco3, jolt, havok, rapier, cannon runs and gets a verdict
#     (pass or FAIL on a metric, never "error" nor a hang), its version from
#     the module itself in `diskval engines`;
#   - MuJoCo 3 (mujoco-js) on the model and settings of the linked MuJoCo 2.2.2
#     gives the same theta, row by row, to 1e-8 relative (measured: see
#     docs/adapters.md);
#   - MuJoCo 3 passes the steady circle at the settings diskval chooses, and
#     `verify` finds it converging to the reference (order 1.00, 1.8e-8 rad
#     extrapolated on short_circle);
#   - attribution of cannon-es (2 mm circle) names its missing gyroscopic
#     term as the cause of its theta error (0.077 -> 0.0015 rad with the
#     adapter's term on), not of its energy loss (the prism's corners).
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
circle=$2
fall=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$diskval" engines >"$work/engines"
# skipped where Node or the adapters' packages are missing (a checkout without npm ci)
if ! grep -q "^mujoco3 .*MuJoCo 3\." "$work/engines" ||
  grep -q "^mujoco3 .*\[not available" "$work/engines"; then
  echo "SKIP: no Node or adapters' packages: $(grep "^mujoco3" "$work/engines")"
  exit 77
fi
for e in mujoco3 jolt havok rapier cannon; do
  check 'grep -q "^$e " "$work/engines" && ! grep -q "^$e .*not available" "$work/engines"' \
    "$e is listed and available: $(grep "^$e " "$work/engines")"
done
for s in "$circle" "$fall"; do
  awk '/^\[disk\]/{print; print "thickness = 0.002"; next} {print}' "$s" >"$work/$(basename "$s")"
done
thick_circle=$work/$(basename "$circle")
thick_fall=$work/$(basename "$fall")

# every adapter judged on both scenes: a verdict, not an error
for s in "$thick_circle" "$thick_fall"; do
  timeout -k 5 600 "$diskval" compare "$s" --engines mujoco3,jolt,havok,rapier,cannon \
    --set scenario.duration=0.5 --out "$work/all" --quiet >"$work/out" 2>&1
  code=$?
  check '[ $code -le 1 ]' "$(basename "$s"): exit $code: $(tail -5 "$work/out")"
  for e in mujoco3 jolt havok rapier cannon; do
    check 'grep -Eq "^[^ ]+ +$e +.*(pass|FAIL)$" "$work/out" && ! grep -Eq "^[^ ]+ +$e +error" "$work/out"' \
      "$(basename "$s") $e: a verdict, not an error: $(grep -E "^[^ ]+ +$e " "$work/out")"
  done
done

# MuJoCo 3 against MuJoCo 2.2.2: one model, one set of settings
set_both=()
for k in integrator=rk4 timestep=5e-05 solref_timeconst=0.0001; do
  set_both+=(--set "engines.mujoco.$k" --set "engines.mujoco3.$k")
done
"$diskval" compare "$thick_circle" --engines mujoco,mujoco3 "${set_both[@]}" \
  --out "$work/pair" --quiet >"$work/out" 2>&1
d=$work/pair/$(awk -F' *= *' '$1 == "name" {print $2; exit}' "$thick_circle")
rel=$(paste -d, "$d/mujoco.csv" "$d/mujoco3.csv" | awk -F, 'NR > 1 {
  d = $2 - $14; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3g", m }')
check 'awk -v r="$rel" "BEGIN { exit !(r != \"\" && r <= 1e-8) }"' \
  "MuJoCo 3 and 2.2.2 differ in theta by $rel rad (want <= 1e-8 of theta ~ 1)"
check 'grep -Eq "^[^ ]+ +mujoco3 +.*pass$" "$work/out"' "mujoco3 passes at 2.2.2's settings: $(cat "$work/out")"
"$diskval" verify "$circle" --engines mujoco3 >"$work/verify" 2>&1
check 'grep -q "converges to the reference" "$work/verify"' "verify mujoco3: $(tail -2 "$work/verify")"
# on the 2 mm circle: on the thin one its prism is a stand-in, not judged (cannot model)
"$diskval" attribute "$thick_circle" --engine cannon >"$work/attr" 2>&1
check 'grep -q "^cause: .*gyroscopic (off -> on) removes theta" "$work/attr"' \
  "cannon's cause: $(grep cause: "$work/attr")"
exit $fail
