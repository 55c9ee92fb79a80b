#!/usr/bin/env bash
# check_phase.sh DISKVAL SCENARIO: on a steady circle smaller than the distance
# rolled (tests/data/euler_disk.ini: a 3 cm contact circle, 6.6 m rolled in
# 2 s), an engine behind the reference round the circle fails on phase_err,
# and the path limits are no larger than the motion itself.
# The trajectories are the matched reference's own (simulate --engine
# matched), its contact point turned about the circle's centre by a lag that
# grows in time to LAG rad at the end (t,theta,contact_x,contact_y):
#   - 1.5 rad (86 deg) behind: phase_err = 0.045 m > 0.003 m (0.1 rad of the
#     circle's 3 cm radius); it passed before, the path limit being 1% of the
#     6.6 m rolled, 0.066 m, over the circle's 0.06 m diameter;
#   - 0.05 rad behind, half the limit: agrees.
# Re-measure: the test prints every measured number (ctest -V -R phase_metric).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_phase.sh DISKVAL SCENARIO}
sc=${2:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(sed -n 's/^name *= *//p' "$sc" | head -1)
"$dv" simulate "$sc" --engine matched --out "$work/ref.csv" --quiet || exit 2
cd "$work" || exit 2
# behind LAG: the reference's contact point turned about the circle's centre
# (the middle of its bounding box: it runs round 35 times) by -LAG t / T
behind() {
  awk -F, -v lag="$1" -v CONVFMT=%.17g -v OFMT=%.17g '
    NR == FNR { if (FNR > 1) { T = $1; if (FNR == 2 || $7 < x0) x0 = $7; if (FNR == 2 || $7 > x1) x1 = $7
                                        if (FNR == 2 || $8 < y0) y0 = $8; if (FNR == 2 || $8 > y1) y1 = $8 }
                next }
    FNR == 1 { print "t,theta,contact_x,contact_y"; cx = (x0 + x1) / 2; cy = (y0 + y1) / 2; next }
    { a = -lag * $1 / T; dx = $7 - cx; dy = $8 - cy
      printf "%.17g,%.17g,%.17g,%.17g\n", $1, $2, cx + cos(a) * dx - sin(a) * dy, cy + sin(a) * dx + cos(a) * dy }
  ' ref.csv ref.csv
}
# judge FILE WANT_STATUS WANT_VERDICT: exit status, outcome; prints the phase and path numbers
judge() {
  local file=$1 want=$2 verdict=$3
  "$dv" judge "$sc" "$file.csv" --out "out_$file" --quiet >/dev/null 2>"$file.err"
  local code=$? report=out_$file/$name/report.json
  check '[ $code -eq $want ]' "$file: exit status $code, not $want ($(head -1 "$file.err"))"
  local outcome
  outcome=$(jq -r ".engines.$file.outcome" "$report")
  check '[ "$outcome" = "$verdict" ]' "$file: $outcome, not $verdict"
  for m in phase_err path_max_err path_rms_err path_hausdorff; do
    echo "$file: $m = $(jq -r ".engines.$file.limits.$m.value" "$report"), limit $(jq -r ".engines.$file.limits.$m.limit" "$report") ($(jq -r ".engines.$file.limits.$m.from" "$report"))"
  done
}
behind 1.5 >lag_86deg.csv
behind 0.05 >lag_small.csv
judge lag_86deg 1 "exceeds tolerance"
failures=$(jq -r '.engines.lag_86deg.failures[]' out_lag_86deg/$name/report.json)
check '[[ "$failures" == *"phase_err = 0.04"*"0.1 rad of half the motion"* ]]' \
  "lag_86deg: no failure names phase_err: $failures"
judge lag_small 0 agrees
# the phase limit (less the spread the shadow excuses) is the smaller of its arc and the path
# limit: here the arc, 0.1 rad of half
# the motion's size, which its words give
plim=$(jq -r '.engines.lag_small.limits.phase_err | .limit - .spread' out_lag_small/$name/report.json)
pfrom=$(jq -r '.engines.lag_small.limits.phase_err.from' out_lag_small/$name/report.json)
size=$(sed -nE 's/.*half the motion.s size ([0-9.e-]+) m.*/\1/p' <<<"$pfrom")
path=$(jq -r '.engines.lag_small.limits.path_max_err | .limit - .spread' out_lag_small/$name/report.json)
check 'awk -v l="$plim" -v s="$size" -v p="$path" "BEGIN { exit !(s > 0 && l < p && l - 0.05 * s <= 1e-3 * l && 0.05 * s - l <= 1e-3 * l) }"' \
  "phase_err: limit $plim, not 0.1 rad of half $size m under the path's $path ($pfrom)"
# the path limits are a share of the motion's size, under the circle's 0.06 m diameter
for m in path_max_err path_rms_err path_hausdorff; do
  limit=$(jq -r ".engines.lag_small.limits.$m | .limit - .spread" out_lag_small/$name/report.json)
  from=$(jq -r ".engines.lag_small.limits.$m.from" out_lag_small/$name/report.json)
  check 'awk -v l="$limit" "BEGIN { exit !(l > 0 && l <= 0.1 * 0.0604) }"' "$m: limit $limit, over 10% of the circle"
  check '[[ "$from" == *"motion"* ]]' "$m: the limit's words do not name the motion's size: $from"
done
exit $fail
