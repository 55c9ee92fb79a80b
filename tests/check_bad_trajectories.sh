#!/usr/bin/env bash
# check_bad_trajectories.sh DISKVAL DIR SCENARIO: every bad trajectory of
# DIR (DIR/expected.txt: FILE|LINE[:COLUMN]|fragment) is refused by judge
# with exit status 2 and one line on stderr, "diskval judge: DIR/FILE:LINE[:COLUMN]: ..."
# holding the fragment, and no report written.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_bad_trajectories.sh DISKVAL DIR SCENARIO}
dir=${2:?usage}
sc=${3:?usage}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0
while IFS='|' read -r file where fragment; do
  case $file in '#'* | '') continue ;; esac
  n=$((n + 1))
  "$dv" judge "$sc" "$dir/$file" --out "$work/out" --quiet >"$work/stdout" 2>"$work/stderr"
  code=$?
  lines=$(wc -l <"$work/stderr")
  msg=$(head -1 "$work/stderr")
  prefix="diskval judge: $dir/$file:$where: "
  check '[ $code -eq 2 ]' "$file: exit status $code, not 2 ($msg)"
  check '[ "$lines" -eq 1 ]' "$file: $lines lines on stderr"
  check '[[ "$msg" == "$prefix"* ]]' "$file: '$msg' does not start with '$prefix'"
  check '[[ "$msg" == *"$fragment"* ]]' "$file: '$msg' does not say '$fragment'"
  check '[ ! -e "$work/out/short_circle" ]' "$file: a report was written"
done <"$dir/expected.txt"
check '[ $n -ge 20 ]' "only $n bad trajectories"
found=$(ls "$dir"/*.csv | wc -l)
check '[ "$found" -eq $n ]' "$found files in $dir, $n in expected.txt"
echo "$n bad trajectories refused"
exit $fail
