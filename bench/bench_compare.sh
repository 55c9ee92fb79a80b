#!/usr/bin/env bash
# bench_compare.sh DISKVAL SOURCE_DIR [SCENARIO...]: what a comparison costs beyond
# its engines. For each scene (default: scenarios/*.ini, scenarios/hard/*.ini and
# tests/data/wheel_wobble.ini) compare --jobs 1 and --jobs 2 (--cause full), each wall
# time over the sum of the engines' own runs (engines.*.wall_s in the --jobs 1
# report.json: one engine at a time), and --jobs 2 over --jobs 1; then, with the
# default scenes, the default suite (diskval suite scenarios) at --jobs 1 and 2.
# All ratios come from this one run. Long: every scene twice, the suite twice.
set -u
diskval=$1 src=$2
shift 2
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] ||
  scenes=("$src"/scenarios/*.ini "$src"/scenarios/hard/*.ini "$src/tests/data/wheel_wobble.ini")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk "BEGIN{print $t1 - $t0}"; }
engines_sum() { # the engines' own wall times in a report.json
  jq '[.engines[].wall_s // 0] | add' "$1"
}
printf "%-26s %9s %9s %9s %8s %8s %8s\n" scene "engines" "jobs 1" "jobs 2" "j1/eng" "j2/eng" "j2/j1"
for sc in "${scenes[@]}"; do
  name=$(basename "$sc" .ini)
  t1=$(seconds "$diskval" compare "$sc" --cause full --quiet --jobs 1 --out "$work/j1")
  t2=$(seconds "$diskval" compare "$sc" --cause full --quiet --jobs 2 --out "$work/j2")
  json=$(ls "$work"/j1/*/report.json 2>/dev/null | head -1)
  sum=$([ -n "$json" ] && engines_sum "$json" || echo nan)
  printf "%-26s %8.2fs %8.2fs %8.2fs %8s %8s %8.2f\n" "$name" "$sum" "$t1" "$t2" \
    "$(awk "BEGIN{s=$sum; if (s > 0) printf \"%.2f\", $t1 / s; else print \"-\"}")" \
    "$(awk "BEGIN{s=$sum; if (s > 0) printf \"%.2f\", $t2 / s; else print \"-\"}")" \
    "$(awk "BEGIN{print $t2 / $t1}")"
  rm -rf "$work/j1" "$work/j2"
done
[ $# -eq 0 ] || exit 0
s1=$(seconds "$diskval" suite "$src/scenarios" --quiet --jobs 1 --out "$work/s1")
s2=$(seconds "$diskval" suite "$src/scenarios" --quiet --jobs 2 --out "$work/s2")
printf "default suite: --jobs 1 %.1f s, --jobs 2 %.1f s, jobs 1 / jobs 2 %.2f\n" "$s1" "$s2" \
  "$(awk "BEGIN{print $s1 / $s2}")"
