#!/bin/sh
# check_html_layout: the suite's index.html and a scenario's page read at a
# laptop's width. Headless Chromium at 1366x768 renders each; neither may be
# wider than the window (no horizontal scrolling) nor have a table row taller
# than 80 px (a row is a glance, not a paragraph).
#
# usage: check_html_layout.sh MAKE_WIDE_SUITE
#   MAKE_WIDE_SUITE: tests/report/make_wide_suite.c built; it writes a suite of
#   20 scenarios x 10 engines with long names and long texts (~0.1 s)
# exit:  0 both fit, 1 not, 2 usage, 77 skipped (chromium not installed)
#
# How it measures: a copy of each page beside its SVGs gets a script that
# writes, once the page has loaded, document.documentElement.scrollWidth,
# window.innerWidth and the tallest <tr>'s height into the DOM, which
# --dump-dom prints. The pages themselves carry no script.
set -u

if [ $# -ne 1 ]; then
  echo "usage: $0 MAKE_WIDE_SUITE" >&2
  exit 2
fi
. "$(dirname "$0")/check_chromium.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/suite" && "$1" "$tmp/suite" || { echo "FAIL: $1 wrote no suite"; exit 1; }

measure='<script>window.addEventListener("load", function () {
  var rows = document.getElementsByTagName("tr"), tallest = 0;
  for (var i = 0; i < rows.length; i++)
    tallest = Math.max(tallest, Math.ceil(rows[i].getBoundingClientRect().height));
  var p = document.createElement("pre");
  p.textContent = "MEASURED scrollWidth=" + document.documentElement.scrollWidth +
    " innerWidth=" + window.innerWidth + " tallest_tr=" + tallest + " rows=" + rows.length;
  document.body.appendChild(p);
});</script>'

status=0
# check PAGE NAME MIN_ROWS: PAGE measured at 1366x768
check() {
  copy="${1%index.html}measure.html"
  sed "s#</body>#$(printf '%s' "$measure" | tr '\n' ' ')</body>#" "$1" >"$copy"
  chromium_headless 1366,768 --hide-scrollbars --virtual-time-budget=5000 --dump-dom \
    "file://$copy" >"$tmp/dom.html"
  line=$(grep -Eo 'MEASURED scrollWidth=[0-9]+ innerWidth=[0-9]+ tallest_tr=[0-9]+ rows=[0-9]+' \
    "$tmp/dom.html")
  if [ -z "$line" ]; then
    echo "FAIL: $2: Chromium measured nothing"
    chromium_log
    status=1
    return
  fi
  echo "$2: $line"
  set -- $line "$2" "$3"
  width=${2#scrollWidth=} inner=${3#innerWidth=} tallest=${4#tallest_tr=} rows=${5#rows=}
  if [ "$inner" -ne 1366 ]; then echo "FAIL: $6: the window is $inner px, not 1366"; status=1; fi
  if [ "$width" -gt "$inner" ]; then
    echo "FAIL: $6: $width px wide in a $inner px window (horizontal scrolling)"
    status=1
  fi
  if [ "$tallest" -gt 80 ]; then echo "FAIL: $6: a table row $tallest px tall (> 80)"; status=1; fi
  if [ "$rows" -lt "$7" ]; then echo "FAIL: $6: $rows table rows, expected $7 or more"; status=1; fi
}

# the matrix: a header row and 20 scenarios; a scenario's page: a header and 10 engines
check "$tmp/suite/index.html" "suite page" 21
check "$tmp/suite/s01_a_steel_euler_disk_on_glass_spinning_down/index.html" "scenario page" 11
[ "$status" -eq 0 ] && echo "PASS: both pages fit 1366 px with rows of at most 80 px"
exit "$status"
