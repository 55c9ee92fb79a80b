#!/usr/bin/env bash
# check_analyze_range.sh DISKVAL SCENARIO_DIR: analyze's range of theta (the
# turning points of the effective potential, found by root finding) against
# an independent measure of it: the reference integrated for 10 s, sampled
# every 1e-4 s, at every theta_limit from 1e-6 to 0.3. Exit status 0 from
# analyze; where the disk falls the range is [limit, top] and the run lies
# down at the limit; elsewhere both ends agree to 1e-6 rad (measured: at most
# 2.2e-9 on c_zero, 5.9e-9 on upright_unstable, 0 on a steady start; the
# sampling misses a turning point by theta'' dt^2 / 8, about 1e-8 here).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_analyze_range.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_analyze_range.sh DISKVAL SCENARIO_DIR}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
for scene in falling steady_steep c_zero upright_unstable; do
  for limit in 1e-6 1e-3 0.01 0.3; do
    set_limit=(--set "engines.reduced.theta_limit=$limit")
    json=$("$dv" analyze "$sc/$scene.ini" "${set_limit[@]}" --json)
    code=$?
    check '[ $code -eq 0 ]' "$scene, limit $limit: analyze exits $code"
    read -r lo hi falls < <(jq -r '"\(.theta_range[0]) \(.theta_range[1]) \(.falls)"' <<<"$json")
    read -r slo shi < <("$dv" simulate "$sc/$scene.ini" --engine reduced "${set_limit[@]}" \
      --set scenario.output_dt=1e-4 --set scenario.duration=10 2>/dev/null |
      awk -F, 'NR == 2 { lo = $2; hi = $2 } NR > 1 { if ($2 < lo) lo = $2; if ($2 > hi) hi = $2 }
        END { printf "%.17g %.17g\n", lo, hi }')
    echo "$scene, limit $limit: analyze [$lo, $hi] falls $falls; integrated [$slo, $shi]"
    near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6) }'; }
    check 'near "$lo" "$slo" && near "$hi" "$shi"' \
      "$scene, limit $limit: analyze [$lo, $hi] against the integrated [$slo, $shi]"
    if [ "$falls" = true ]; then
      check 'near "$lo" "$limit" || near "$hi" "$(awk -v l="$limit" "BEGIN { print 3.141592653589793 - l }")"' \
        "$scene, limit $limit: falls, yet no end of [$lo, $hi] is the limit"
    fi
  done
done
exit $fail
