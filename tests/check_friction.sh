#!/usr/bin/env bash
# check_friction.sh DISKVAL SCENARIO: [disk] friction, the one coefficient of
# the scene (docs/scenarios.md):
#   - a NaN, a negative or a non-number is refused: exit 2, one line
#     FILE:LINE: friction: ...;
#   - by default every engine and the validity window ([engines.matched]
#     friction) take it: report.json's settings give each the same value, and
#     settings_why says "[disk] friction";
#   - an engine's own key wins, and its settings_why says so;
#   - the validity window follows it: the matched reference's run ends where
#     rolling needs more than [disk] friction, earlier at a smaller one.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_friction.sh DISKVAL SCENARIO}
sc=${2:?usage: check_friction.sh DISKVAL SCENARIO}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for bad in nan -0.5 -inf soap; do
  sed "s/^\[disk\]/[disk]\nfriction = $bad/" "$sc" >"$work/bad.ini"
  line=$(grep -n "^friction = " "$work/bad.ini" | cut -d: -f1)
  refused "friction = $bad" "^$work/bad.ini:$line: friction: " "$dv" analyze "$work/bad.ini"
  refused "--set disk.friction=$bad" "friction" "$dv" simulate "$sc" --engine matched \
    --set "disk.friction=$bad"
done

# every engine the same coefficient by default; ODE's own key wins
"$dv" compare "$sc" --set disk.friction=0.8 --set engines.ode.friction=5 \
  --set scenario.duration=0.1 --out "$work/out" --quiet >/dev/null 2>&1
json=$(compgen -G "$work/out/*/report.json" | head -1)
check '[ -f "$json" ]' "compare wrote no report.json"
for e in mujoco bullet dart simbody; do
  mu=$(jq -r ".engines.$e.settings.friction" "$json")
  why=$(jq -r ".engines.$e.settings_why" "$json")
  echo "$e: friction $mu ($why)"
  check '[ "$mu" = 0.8 ] && [[ $why == *"friction 0.8: [disk] friction"* ]]' \
    "$e: friction $mu, '$why', want 0.8 from [disk] friction"
done
mu=$(jq -r ".engines.ode.settings.friction" "$json")
why=$(jq -r ".engines.ode.settings_why" "$json")
echo "ode: friction $mu ($why)"
check '[ "$mu" = 5 ] && [[ $why == *"friction 5: [engines.ode] friction"* ]]' \
  "ode: friction $mu, '$why', want 5 from [engines.ode] friction"

# the validity window: where the matched reference ends for want of friction
ends() {
  "$dv" simulate "$sc" --engine matched "$@" --out "$work/m.csv" --quiet >/dev/null 2>&1
  jq -r '.run.detail' "$work/m.csv.json" | sed -n 's/.*friction needed.* at t = \([0-9.e-]*\) s.*/\1/p'
}
t_default=$(ends)
t_low=$(ends --set disk.friction=0.5)
t_own=$(ends --set disk.friction=0.5 --set engines.matched.friction=2)
echo "matched ends for friction at t = $t_default (default), $t_low ([disk] 0.5), $t_own ([engines.matched] 2 over it)"
check '[ -n "$t_default" ] && [ -n "$t_low" ] && awk -v a="$t_low" -v b="$t_default" "BEGIN { exit !(a < b) }"' \
  "the window does not follow [disk] friction: $t_low at 0.5, $t_default at the default"
check '[ "$t_own" = "$t_default" ]' "[engines.matched] friction 2 over [disk] 0.5: $t_own, want $t_default"
exit $fail
