#!/usr/bin/env bash
# check_judge_thick.sh DISKVAL TO_POSE SCENARIO: nothing in judging a file
# assumes a thin disk. The rolling cylinder's exact trajectory (the matched
# reference, simulate --engine matched) of a thick coin (SCENARIO: a quarter,
# h = 0.875 mm), judged in three forms, is within 1e-12 of the matched
# reference of the scenario's thickness (as written and without its contact
# columns it is the reference's own output, state for state: not judged,
# never a pass; in the pose form it passes every metric): as written; without its
# contact columns (the contact computed from the pose, at the cylinder's rim
# corner); in the pose form (TO_POSE with the coin's radius and
# half-thickness). theta and the contact point within 1e-12 rad and m
# (measured: theta 0 and 3.5e-18 m, 4.4e-16 rad and 5.1e-18 m).
# Re-measure: the test prints every measured number (ctest -V -R NAME).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_thick.sh DISKVAL TO_POSE SCENARIO}
to_pose=${2:?usage}
sc=${3:?usage}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
name=$(sed -n 's/^name *= *//p' "$sc" | head -1)
r=$(sed -n 's/^radius *= *//p' "$sc" | head -1) thick=$(sed -n 's/^thickness *= *//p' "$sc" | head -1)
h=$(awk -v t="$thick" 'BEGIN { printf "%.17g", t / 2 }')
"$dv" simulate "$sc" --engine matched --out coin.csv --quiet
cut -d, -f1-6,9-12 coin.csv >coin_nocontact.csv
"$to_pose" "$r" "$h" <coin.csv >coin_pose.csv
# as written and without the contact columns every state is the matched
# reference's own: not judged, never a pass (its numbers are still measured);
# the pose form (converted: not bit for bit) passes
for f in coin coin_nocontact coin_pose; do
  "$dv" judge "$sc" "$f.csv" --out "out_$f" --quiet >/dev/null
  code=$?
  e=out_$f/$name/report.json
  if [ $f = coin_pose ]; then
    check '[ $code -eq 0 ]' "$f: exit status $code: $(jq -r ".engines.$f.failures[]" "$e")"
  else
    check '[ $code -eq 1 ] && jq -r ".engines.$f.failures[]" "$e" | grep -q "the reference.s own output"' \
      "$f: exit status $code: the reference's own output judged: $(jq -c ".engines.$f.failures" "$e")"
  fi
  got=$(jq -r ".engines.$f | \"\(.theta_max_err) \(.path_max_err) \(.reference_half_thickness)\"" "$e")
  echo "$f: theta_max_err, path_max_err, reference half-thickness: $got"
  check 'awk -v g="$got" -v h="$h" "BEGIN { split(g, a, \" \"); exit !(a[1] <= 1e-12 && a[2] <= 1e-12 && a[3] == h) }"' \
    "$f: $got"
done
exit $fail
