#!/usr/bin/env bash
# check_analyze_digits.sh DISKVAL SCENARIO...: analyze prints the nutation's
# period to no more significant digits than its quadrature holds (the JSON's
# relative resolution: what halving the points moves it by), and shows it only
# where that resolution is at most 1e-8.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_analyze_digits.sh DISKVAL SCENARIO...}
shift
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
for sc in "$@"; do
  res=$("$dv" analyze "$sc" --json | jq -r '.nutation.resolution')
  period=$("$dv" analyze "$sc" | sed -n 's/^nutation *period \([0-9.e+-]*\) s.*/\1/p')
  # significant digits of the printed period: its digits without leading zeros
  shown=$(printf '%s' "$period" | sed 's/e.*//; s/[.-]//g; s/^0*//' | tr -d '\n' | wc -c)
  hold=$(awk -v r="$res" 'BEGIN { d = int(-log(r) / log(10)); print (d > 10 ? 10 : d) }')
  echo "$sc: period $period ($shown digits), resolution $res ($hold digits hold)"
  check '[ -n "$period" ] && awk -v r="$res" "BEGIN { exit !(r <= 1e-8) }"' "$sc: no resolved nutation ($res)"
  check '[ "$shown" -le "$hold" ]' "$sc: $shown digits shown where $hold hold"
done
exit $fail
