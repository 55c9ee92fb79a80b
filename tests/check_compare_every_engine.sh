#!/usr/bin/env bash
# check_compare_every_engine.sh DISKVAL COIN: every engine `diskval engines`
# lists as available (the linked ones, the references, and the adapters whose
# Node packages are installed; those that are not are left out, not failed)
# compared in ONE `diskval compare` on a thick coin, cut to 0.1 s:
#   - a verdict for each (exit 0 or 1), never a refusal (2): the plots hold
#     as many series as a comparison has engines, and the matched reference
#     beside them;
#   - report.json has one entry per engine, no more, no fewer;
#   - every scenario plot names every engine in its legend (a text element
#     that reads exactly its name; a series without data would be named in
#     the title instead).
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_compare_every_engine.sh DISKVAL COIN}
coin=${2:?usage: check_compare_every_engine.sh DISKVAL COIN}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
command -v perl >/dev/null || { echo "SKIP: perl not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# an engine's line: its name, its description, its version in brackets ("[not
# available]", or "[... not available ...]", where a module or package is missing)
"$dv" engines >"$work/engines" 2>&1
mapfile -t engines < <(grep -E '^[a-z0-9_]+ +.*\]$' "$work/engines" | grep -v 'not available' |
  awk '{print $1}')
mapfile -t missing < <(grep -E '^[a-z0-9_]+ +.*not available.*\]$' "$work/engines" | awk '{print $1}')
[ ${#missing[@]} -gt 0 ] && echo "left out, not available here: ${missing[*]}"
# the linked engines are always there: fewer than the seven of dv_engines.def is a broken list
check '[ ${#engines[@]} -ge 7 ]' "diskval engines lists ${#engines[@]} available: $(cat "$work/engines")"
list=$(IFS=,; echo "${engines[*]}")
echo "comparing ${#engines[@]} engines: $list"

# 0.1 s (20 samples of the coin's) draws every engine's curve: 9 s for all twelve, most of
# it the adapters' settings probes (measured: rapier's 7 s; at 0.05 s its probe took 11 s); no
# cause is searched, which would rerun the failing adapters (a verdict is asked for, not why)
"$dv" compare "$coin" --engines "$list" --set scenario.duration=0.1 --cause none --quiet \
  --out "$work/out" >"$work/stdout" 2>"$work/stderr"
code=$?
check '[ $code -eq 0 ] || [ $code -eq 1 ]' \
  "compare of ${#engines[@]} engines: exit $code, want a verdict (0 or 1): $(cat "$work/stderr")"
report=$(compgen -G "$work/out/*/report.json" | head -1)
check '[ -n "$report" ]' "no report.json: $(cat "$work/stderr")"
[ -n "$report" ] || exit $fail
dir=$(dirname "$report")

got=$(jq -r '.engines | keys[]' "$report" | sort | tr '\n' ' ')
want=$(printf '%s\n' "${engines[@]}" | sort | tr '\n' ' ')
check '[ "$got" = "$want" ]' "report.json's engines: $got; want $want"
for e in "${engines[@]}"; do
  check 'grep -Eq "^[^ ]+ +$e +" "$work/stdout"' "$e: no verdict line: $(cat "$work/stdout")"
done

# each text element of an SVG file on a line of its own, PLplot's &#xNN; decoded
svg_texts() {
  perl -0ne 'binmode STDOUT, ":utf8";
    while (/<text\b[^>]*>(.*?)<\/text>/gs) { my $t = $1; $t =~ s/<[^>]*>//g;
      $t =~ s/&#x([0-9a-fA-F]+);/chr(hex($1))/ge; print "$t\n" }' "$1"
}
for plot in theta.svg theta_error.svg path.svg energy.svg; do
  check '[ -s "$dir/$plot" ]' "$plot not written"
  [ -s "$dir/$plot" ] || continue
  svg_texts "$dir/$plot" >"$work/texts"
  for e in "${engines[@]}"; do
    check 'grep -qxF "$e" "$work/texts"' "$plot: $e is not in the legend: $(grep -F "no data" "$work/texts")"
  done
done
[ $fail -eq 0 ] && echo "every engine (${#engines[@]}) compared in one run, in the report and in every plot's legend"
exit $fail
