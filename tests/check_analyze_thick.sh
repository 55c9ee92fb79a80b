#!/usr/bin/env bash
# check_analyze_thick.sh DISKVAL THIN: analyze analyses the scene's body.
#   - a 2 mm disk on a steady circle (the matched reference holds theta to
#     1e-14) is steady, on the range [theta, theta], analysed as a cylinder;
#   - a euro coin (r 11.625 mm, 2.33 mm, 7.5 g) released at 1.4 rad with a
#     spin nutates: its range of theta and its period are those of the
#     matched reference's run (simulate --engine matched sampled every 1e-5
#     s: the sampling misses a turning point by theta'' dt^2 / 8, about 1e-9
#     rad, and a time by dt: measured 5.6e-11 rad and 4.3e-6 s), not the thin
#     disk's (theta down to 1.25, 0.08 rad lower);
#   - the coin's report draws the cylinder's potential and phase plane (from
#     the matched reference's run), not the thin disk's;
#   - the thin scene THIN is still the thin disk's, its f1, f2 numbers.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_analyze_thick.sh DISKVAL THIN}
thin=${2:?usage: check_analyze_thick.sh DISKVAL THIN}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
near() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= tol) }'; }

cat >"$work/circle.ini" <<'INI'
[scenario]
name = thick_circle
duration = 1
output_dt = 0.01
[disk]
radius = 0.1
mass = 1.0
thickness = 0.002
[initial]
theta = 1.0
steady_circle_radius = 0.5
INI
json=$("$dv" analyze "$work/circle.ini" --json)
read -r body lo hi steady < <(jq -r '"\(.body) \(.theta_range[0]) \(.theta_range[1]) \(.steady != null)"' <<<"$json")
echo "2 mm steady circle: $body, theta [$lo, $hi], steady $steady"
check '[ "$body" = cylinder ] && [ "$steady" = true ]' "2 mm steady circle: $body, steady $steady"
check 'near "$lo" 1 1e-12 && near "$hi" 1 1e-12' "2 mm steady circle: theta range [$lo, $hi], want [1, 1]"
check '"$dv" analyze "$work/circle.ini" | grep -q "^body *cylinder"' "the text does not name the cylinder"

cat >"$work/coin.ini" <<'INI'
[scenario]
name = euro_coin
duration = 0.4
output_dt = 0.001
[disk]
radius = 0.011625
mass = 0.0075
thickness = 0.00233
[initial]
theta = 1.4
psi_dot = 30
INI
json=$("$dv" analyze "$work/coin.ini" --json)
read -r lo hi period < <(jq -r '"\(.theta_range[0]) \(.theta_range[1]) \(.nutation.period)"' <<<"$json")
# the run's lowest theta and the times of its first two maxima after the start
read -r slo shi tmax < <("$dv" simulate "$work/coin.ini" --engine matched \
  --set scenario.output_dt=1e-5 2>/dev/null | awk -F, '
    NR == 2 { lo = $2; hi = $2 }
    NR > 1 { if ($2 < lo) lo = $2; if ($2 > hi) hi = $2
             if (NR > 3 && p1 > p2 && p1 >= $2 && !t) t = t1
             p2 = p1; p1 = $2; t1 = $1 }
    END { printf "%.17g %.17g %.17g\n", lo, hi, t }')
echo "coin: analyze [$lo, $hi], period $period; matched run [$slo, $shi], back at its top at $tmax s"
check 'near "$lo" "$slo" 1e-8 && near "$hi" "$shi" 1e-8' "coin: analyze [$lo, $hi], the matched run [$slo, $shi]"
check 'near "$period" "$tmax" 2e-5' "coin: period $period s, the matched run's $tmax s"

# the portraits of the scene's body (plot text is in character references)
"$dv" compare "$work/coin.ini" --engines ode --set scenario.duration=0.3 --out "$work/r" \
  --quiet >/dev/null 2>&1
text() { perl -pe 's/&#x([0-9a-f]+);/chr(hex($1))/ge' "$work/r/euro_coin/$1" 2>/dev/null; }
check 'text phase.svg | grep -q "phase plane of the cylinder" && text phase.svg | grep -q "reference (matched"' \
  "the coin's phase.svg is not the cylinder's"
check 'text potential.svg | grep -q "effective potential of the cylinder"' \
  "the coin's potential.svg is not the cylinder's"

json=$("$dv" analyze "$thin" --json)
body=$(jq -r .body <<<"$json")
f1=$(jq -r .f1 <<<"$json")
check '[ "$body" = "thin disk" ] && [ "$f1" != null ]' "$thin: body $body, f1 $f1"
exit $fail
