#!/usr/bin/env bash
# check_thick_engines.sh DISKVAL COIN: every engine judged on the body the scene describes.
#   - DART and Simbody simulate the coin's cylinder ([disk] thickness) and are
#     compared with the matched reference of its half-thickness, within the
#     default limits (report.json's reference.half_thickness);
#   - an engine given a thinner stand-in than the scene's body (geom thin on
#     the coin) is "not judged", never "agrees" against the thin disk;
#   - attribute still runs on the coin (its thin-disk run is measured, not
#     judged) and names no thin-disk geometry as the cause;
#   - the body whose reference judged a line is on compare's stdout, in a
#     suite's index.html and in its junit.xml.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_thick_engines.sh DISKVAL COIN}
coin=${2:?usage: check_thick_engines.sh DISKVAL COIN}
command -v jq >/dev/null || { echo "SKIP: jq not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
body='vs cylinder h 1\.165 mm'

"$dv" compare "$coin" --engines dart,simbody --out "$work/c" >"$work/stdout" 2>"$work/stderr"
code=$?
report=$(compgen -G "$work/c/*/report.json" | head -1)
check '[ $code -eq 0 ] && [ -n "$report" ]' "compare exit $code: $(cat "$work/stderr")"
for e in dart simbody; do
  h=$(jq -r ".engines.$e.reference.half_thickness" "$report")
  pass=$(jq -r ".engines.$e.pass" "$report")
  check '[ "$h" = 0.001165 ] && [ "$pass" = true ]' \
    "$e: compared with the reference of h $h (want the coin's 0.001165 m), pass $pass"
  check 'grep -Eq "^euro_coin +$e +agrees .* $body +pass$" "$work/stdout"' \
    "$e: stdout does not say which body judged it: $(grep "$e" "$work/stdout" | head -1)"
done

"$dv" compare "$coin" --engines ode --set engines.ode.geom=thin --out "$work/t" >"$work/stdout" \
  2>"$work/stderr"
code=$?
check '[ $code -ne 0 ] && grep -Eq "^euro_coin +ode +not judged .* vs thin disk +FAIL$" "$work/stdout"' \
  "a thin stand-in of a thick coin: exit $code: $(head -1 "$work/stdout")"
check 'grep -q "cannot model: no cylinder of the scene" "$work/stdout"' "no reason given: $(cat "$work/stdout")"

# attribution's thin-disk run of the coin is not judged, yet measured: no
# exit 2, and the thin disk is never named the cause for the coin's engine
"$dv" attribute "$coin" --engine ode >"$work/stdout" 2>"$work/stderr"
code=$?
check '[ $code -eq 0 ] && ! grep -Eq "^geometry .*removes it" "$work/stdout"' \
  "attribute on the coin: exit $code: $(cat "$work/stderr") $(grep geometry "$work/stdout")"

mkdir "$work/s" && cp "$coin" "$work/s/"
"$dv" suite "$work/s" --engines dart --out "$work/so" >"$work/stdout" 2>"$work/stderr"
code=$?
# the matrix's cell names the body (its second line, and its title with the line that decided)
check '[ $code -eq 0 ] && grep -Eq "title=\"dart on [^\"]* $body: [^\"]*\">.*<span>${body#vs }</span>" "$work/so/index.html"' \
  "suite exit $code: index.html's cell does not say the body: $(grep -o 'title="dart on [^"]*"' "$work/so/index.html")"
check 'grep -Eq "<property name=\"judged\" value=\"$body\"" "$work/so/junit.xml"' \
  "junit.xml does not say the body: $(grep -c judged "$work/so/junit.xml")"
# a suite's failure lines on stdout name the body too (a thin stand-in: not judged)
"$dv" suite "$work/s" --engines ode --set engines.ode.geom=thin --out "$work/sf" >"$work/stdout" \
  2>"$work/stderr"
code=$?
check '[ $code -ne 0 ] && grep -Eq "^euro_coin: ode: not judged: .*\[vs thin disk\]$" "$work/stdout"' \
  "suite exit $code: its failure line does not say the body: $(head -1 "$work/stdout")"
[ $fail -eq 0 ] && echo "thick engines: DART and Simbody judged on the coin's cylinder, the body on every line"
exit $fail
