#!/usr/bin/env bash
# check_thick_judging.sh DISKVAL SCENARIO THIN: a thick disk judged as a thick disk.
#   - report.json's geometry_share is 1 - err_matched / err_thin with both
#     errors (theta and contact point, max over the samples) taken over the
#     one window it states, recomputed here from the report's own CSVs
#     (agreement to 1e-9: the CSVs keep every digit);
#   - invariant_drift (the thin disk's f1, f2) is not judged for the cylinder,
#     and says why, while the thin scene THIN still judges it.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_thick_judging.sh DISKVAL SCENARIO THIN}
sc=${2:?usage: check_thick_judging.sh DISKVAL SCENARIO THIN}
thin_sc=${3:?usage: check_thick_judging.sh DISKVAL SCENARIO THIN}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$dv" compare "$sc" --engines ode --out "$work" --quiet >/dev/null
dir=$(compgen -G "$work/*/report.json" | head -1)
dir=${dir%/report.json}
share() { jq -r ".engines.ode.geometry_share.$1" "$dir/report.json"; }
window=$(share window_end)
check '[ "$window" != null ] && awk -v w="$window" "BEGIN { exit !(w > 0) }"' "no window: $window"
# max over t <= window of |theta| and contact distance between ode.csv and REF
err() {
  paste -d, "$dir/ode.csv" "$dir/$1" | awk -F, -v w="$window" -v col="$2" '
    NR > 1 && $1 <= w + 1e-12 {
      d = col == "theta" ? $2 - $14 : sqrt(($7 - $19)^2 + ($8 - $20)^2)
      if (d < 0) d = -d
      if (d > m) m = d
    } END { printf "%.17g\n", m }'
}
for pair in theta:theta_max_err path:path_max_err; do
  col=${pair%%:*} metric=${pair#*:}
  own=$(err matched-ode.csv "$col") thin=$(err reduced.csv "$col")
  want=$(awk -v a="$own" -v b="$thin" 'BEGIN { printf "%.17g\n", 1 - a / b }')
  got=$(share "$metric")
  echo "$metric over [0, $window] s: matched $own, thin $thin: share $want, report $got"
  check 'awk -v g="$got" -v w="$want" "BEGIN { d = g - w; if (d < 0) d = -d; exit !(d <= 1e-9) }"' \
    "$metric: report.json says $got, the CSVs over its window give $want"
done
inv() { jq -r ".engines.ode.limits.invariant_drift.$2" "$1"; }
check '[ "$(inv "$dir/report.json" limit)" = null ] && [[ "$(inv "$dir/report.json" from)" == "not judged: f1, f2"* ]]' \
  "the cylinder's invariant_drift: limit $(inv "$dir/report.json" limit), $(inv "$dir/report.json" from)"
"$dv" compare "$thin_sc" --engines ode --out "$work/thin" --quiet --set scenario.duration=0.3 >/dev/null
thin_report=$(compgen -G "$work/thin/*/report.json" | head -1)
check '[ -n "$thin_report" ] && [ "$(inv "$thin_report" limit)" != null ]' \
  "the thin disk's invariant_drift is not judged"
[ $fail -eq 0 ] && echo "thick judging: one window for geometry_share, no thin invariants"
exit $fail
