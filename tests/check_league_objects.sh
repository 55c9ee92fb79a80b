#!/usr/bin/env bash
# check_league_objects.sh DISKVAL LEAGUE_DIR: the league's objects are what
# league/README.md says they are.
#   - every file is valid (read, checked and its steady motion solved: a run of
#     the reference over one output step exits 0), begins with its `;`
#     comments, names itself after its stem in lower_snake_case and sets only
#     [scenario], [disk], [initial] (the league chooses settings and limits);
#   - the quick set (LEAGUE_DIR itself) has 4 or 5 objects, each at most 0.5 s
#     with output every 5 ms or more, and none is repeated in more/;
#   - README.md's table lists every file, and no other;
#   - an object whose description says "centre at rest" keeps its centre
#     still in the matched reference: measured 7.5e-7 m (plate, 0.3 s) and
#     9.0e-7 m (Euler's disk, 1 s), from the 6 digits of the contact radius
#     (diskval simulate FILE --engine matched, the x and y columns); 1e-5 m
#     is 5 % of the 0.2 mm the centre moves with the radius 1e-4 off (a
#     typo in its 4th digit).
# About 0.5 s in all.
set -u
export LC_ALL=C
dv=${1:?usage: check_league_objects.sh DISKVAL LEAGUE_DIR}
dir=${2:?usage: check_league_objects.sh DISKVAL LEAGUE_DIR}
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

quick=("$dir"/*.ini)
more=("$dir"/more/*.ini)
check '[ ${#quick[@]} -ge 4 ] && [ ${#quick[@]} -le 5 ]' "the quick set has ${#quick[@]} objects, want 4 or 5"
check '[ -e "${more[0]}" ]' "no objects in $dir/more"

key() { sed -n "s/^$2 *= *//p" "$1" | head -1; }

for f in "${quick[@]}" "${more[@]}"; do
  stem=$(basename "$f" .ini)
  name=$(key "$f" name)
  check '[ "$name" = "$stem" ]' "$f: name '$name' is not the file's stem"
  check '[[ $stem =~ ^[a-z][a-z0-9_]*$ ]]' "$f: '$stem' is not lower_snake_case"
  check '[ "$(head -c 1 "$f")" = ";" ]' "$f: does not begin with its ; comments"
  sections=$(grep -E '^\[' "$f" | sort -u | tr '\n' ' ')
  check '[ "$sections" = "[disk] [initial] [scenario] " ]' "$f: sections $sections, want [scenario] [disk] [initial] only"
  "$dv" simulate "$f" --engine reduced --set "scenario.duration=$(key "$f" output_dt)" \
    --out "$work/start.csv" >"$work/err" 2>&1
  code=$?
  check '[ $code -eq 0 ]' "$f: not a valid scenario: $(head -1 "$work/err")"
  check 'grep -Fq "\`$(basename "$(dirname "$f")")/$stem.ini\`" "$dir/README.md" || grep -Fq "\`$stem.ini\`" "$dir/README.md"' \
    "$f: not in README.md's table"
  if grep -q '^description = .*centre at rest' "$f"; then
    "$dv" simulate "$f" --engine matched --out "$work/run.csv" 2>"$work/err"
    moved=$(awk -F, 'NR > 1 { if (NR == 2) { x0 = $5; y0 = $6 } d = sqrt(($5 - x0)^2 + ($6 - y0)^2); if (d > m) m = d } END { print m + 0 }' "$work/run.csv")
    echo "$stem: the centre moves $moved m"
    check 'awk -v m="$moved" "BEGIN { exit !(m < 1e-5) }"' "$f: the centre at rest moves $moved m"
  fi
done

for f in "${quick[@]}"; do
  d=$(key "$f" duration)
  o=$(key "$f" output_dt)
  check 'awk -v d="$d" -v o="$o" "BEGIN { exit !(d <= 0.5 && o >= 0.005) }"' \
    "$f: duration $d s, output_dt $o s: the quick set's objects are at most 0.5 s, output every 5 ms or more"
  check '[ ! -e "$dir/more/$(basename "$f")" ]' "$f: repeated in more/"
done

listed=$(grep -oE '^\| `[a-z0-9_/]+\.ini`' "$dir/README.md" | wc -l)
total=$((${#quick[@]} + ${#more[@]}))
check '[ "$listed" -eq "$total" ]' "README.md's table lists $listed files, the folders hold $total"
exit $fail
