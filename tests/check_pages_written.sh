#!/bin/sh
# check_pages_written: compare and judge each write their report directory's
# page, index.html, naming it on stdout; the page shows the report's plots and
# a row per engine; a thick body's page names the reference that judged each
# engine. Planted: report_scenario.c without its page call fails it; every
# engine said judged by the thin disk fails it.
#
# usage: check_pages_written.sh DISKVAL SCENARIO   (tests/data/short_circle.ini:
#        1 s, ode alone: compare about 1 s, judge under 1 s)
# exit:  0 pass, 1 fail, 2 usage
set -u
if [ $# -ne 2 ]; then
  echo "usage: $0 DISKVAL SCENARIO" >&2
  exit 2
fi
dv=$1 sc=$2
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail=0
# page DIR WHAT ENGINE: DIR/index.html is the page of its report with ENGINE's row
page() {
  p="$1/index.html"
  if [ ! -f "$p" ]; then echo "FAIL: $2 wrote no $p"; fail=1; return; fi
  grep -q '<h1>short_circle: <span class="pass">PASS</span></h1>' "$p" ||
    { echo "FAIL: $2: $p has not the scenario's verdict"; fail=1; }
  grep -q "<a href=\"#e-$3\">$3</a>" "$p" || { echo "FAIL: $2: no row of $3 in $p"; fail=1; }
  for svg in theta.svg theta_error.svg path.svg; do
    grep -q "<img src=\"$svg\"" "$p" || { echo "FAIL: $2: $p shows no $svg"; fail=1; }
  done
  if grep -q '<script' "$p"; then echo "FAIL: $2: $p has a script"; fail=1; fi
}
"$dv" compare "$sc" --engines ode --cause none --out "$tmp/c" >"$tmp/c.out" 2>"$tmp/c.err" ||
  { echo "FAIL: compare exited $?"; cat "$tmp/c.err"; fail=1; }
grep -qx "page: $tmp/c/short_circle/index.html" "$tmp/c.out" ||
  { echo "FAIL: compare does not name its page"; fail=1; }
page "$tmp/c/short_circle" compare ode
"$dv" judge "$sc" "$tmp/c/short_circle/ode.csv" --name recorded --out "$tmp/j" >"$tmp/j.out" 2>&1 ||
  { echo "FAIL: judge exited $?"; cat "$tmp/j.out"; fail=1; }
grep -qx "page: $tmp/j/short_circle/index.html" "$tmp/j.out" ||
  { echo "FAIL: judge does not name its page"; fail=1; }
page "$tmp/j/short_circle" judge recorded
# a thick body's page names the reference that judged it, the thin disk's judging nothing
sed -e 's/^mass = 1.0$/mass = 1.0\nthickness = 0.004/' "$sc" >"$tmp/thick.ini"
"$dv" compare "$tmp/thick.ini" --engines ode --cause none --out "$tmp/t" >"$tmp/t.out" 2>&1 ||
  { echo "FAIL: thick compare exited $?"; cat "$tmp/t.out"; fail=1; }
grep -q '<p>Reference of the thin disk: [^<]*; it judged no engine\.</p>' "$tmp/t/short_circle/index.html" ||
  { echo "FAIL: the thick page says the thin disk judged an engine"; fail=1; }
grep -q '<p>Reference of the cylinder of half-thickness 2 mm: [^<]*; it judged ode\.</p>' \
  "$tmp/t/short_circle/index.html" || { echo "FAIL: the thick page does not name ode's reference"; fail=1; }
[ "$fail" -eq 0 ] && echo "PASS: compare and judge write their pages"
exit "$fail"
