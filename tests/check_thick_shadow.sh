#!/usr/bin/env bash
# check_thick_shadow.sh DISKVAL: on a thick scene the reference block, the
# amplification and every engine's shadow are the scene's body's (the matched
# cylinder), not the thin disk's (issue 48, item 4). A 50-cent coin (r 12.13 mm,
# 2.38 mm thick, 7.8 g) released at theta 1.45 with psi_dot 8 nutates every 0.417 s
# as a cylinder, every 0.275 s as the thin disk: report.json's
# reference.body_nutation_period is measured here from the matched reference's own
# CSV (`diskval simulate --engine matched`, its sampled maxima of theta), and the
# thin scene's from the reduced one's; each within 2 output_dt a period. The
# amplification of a theta nudge of the body, measured here from two matched runs
# (theta(0) + 1e-6 rad), is at most what the report gives (the largest over every
# direction), and differs from the thin disk's.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_thick_shadow.sh DISKVAL}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
cat >coin.ini <<'INI'
[scenario]
name = coin
duration = 1
output_dt = 0.002
[disk]
radius = 0.01213
mass = 0.0078
thickness = 0.00238
[initial]
theta = 1.45
psi_dot = 8
INI
# the mean time between the sampled maxima of theta in CSV (column 2)
period() {
  awk -F, 'NR > 1 { t[n] = $1; th[n++] = $2 }
    END { for (i = 1; i < n - 1; i++) if (th[i] > th[i-1] && th[i] >= th[i+1]) { if (!m++) f = t[i]; l = t[i] }
          if (m >= 2) printf "%.6f\n", (l - f) / (m - 1) }' "$1"
}
for body in thick thin; do
  set_thin=()
  [ $body = thin ] && set_thin=(--set disk.thickness=0)
  "$dv" compare coin.ini --engines mujoco --cause none "${set_thin[@]}" --out "out_$body" --quiet \
    >"$body.out" 2>&1
  engine=matched && [ $body = thin ] && engine=reduced
  "$dv" simulate coin.ini --engine $engine "${set_thin[@]}" --out "$body.csv" --quiet 2>/dev/null
  want=$(period "$body.csv")
  got=$(jq -r .reference.body_nutation_period "out_$body/coin/report.json")
  check 'awk -v g="$got" -v w="$want" "BEGIN { exit !(w > 0 && (g - w < 0.004 && w - g < 0.004)) }"' \
    "$body: the body's period $got s, its reference's samples say $want s"
  declare "period_$body=$want"
done
check 'awk -v a="$period_thick" -v b="$period_thin" "BEGIN { exit !(a > 1.3 * b) }"' \
  "the cylinder's period $period_thick s is not the thin disk's $period_thin s made longer"
h=$(jq -r .reference.body_half_thickness out_thick/coin/report.json)
check '[ "$h" = 0.00119 ]' "the body's half-thickness $h, not 0.00119 m"
check 'grep -q "The scene.s body (the matched cylinder, 2.38 mm thick) nutates every 0.41" out_thick/coin/report.md' \
  "report.md does not name the body's period: $(grep -i nutat out_thick/coin/report.md)"
# the body's amplification of a theta nudge, measured from its own runs
"$dv" simulate coin.ini --engine matched --set initial.theta=1.450001 --out nudged.csv --quiet 2>/dev/null
gain=$(paste -d, thick.csv nudged.csv | awk -F, -v k="$(head -1 thick.csv | tr , '\n' | wc -l)" \
  'NR > 1 { d = $2 - $(k + 2); if (d < 0) d = -d; if (d > m) m = d } END { printf "%.6g\n", m / 1e-6 }')
amp=$(jq -r .reference.amplification.factor out_thick/coin/report.json)
amp_thin=$(jq -r .reference.amplification.factor out_thin/coin/report.json)
check 'awk -v g="$gain" -v a="$amp" "BEGIN { exit !(g > 1 && g <= 1.01 * a) }"' \
  "the body's theta nudge grows x$gain, more than the reported amplification x$amp"
check 'awk -v a="$amp" -v b="$amp_thin" "BEGIN { exit !(a > 1.2 * b || b > 1.2 * a) }"' \
  "the thick amplification x$amp is the thin disk's x$amp_thin"
[ $fail -eq 0 ] && echo "thick: period $period_thick s (thin $period_thin s), amplification x$amp (thin x$amp_thin; theta nudge x$gain)"
exit $fail
