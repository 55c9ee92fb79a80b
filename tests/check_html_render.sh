#!/bin/sh
# check_html_render: headless Chromium loads OUT_DIR/index.html (the suite's page)
# and renders it to a screenshot that is not blank.
#
# usage: check_html_render.sh OUT_DIR
# exit:  0 rendered, 1 not, 2 usage, 77 skipped (chromium not installed)
#
# "Not blank" without an image decoder: a 1200x900 screenshot of one colour
# compresses to a few kB, so the page's PNG must be several times larger than
# that of an empty page rendered the same way. The DOM Chromium builds must be
# the suite page itself (not Chromium's error page for a missing file).
set -u

if [ $# -ne 1 ]; then
  echo "usage: $0 OUT_DIR" >&2
  exit 2
fi
. "$(dirname "$0")/check_chromium.sh"
out=$(cd "$1" 2>/dev/null && pwd) || { echo "FAIL: no directory $1"; exit 1; }
if [ ! -f "$out/index.html" ]; then
  echo "FAIL: no $out/index.html"
  exit 1
fi
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# file URL of a local path
file_url() {
  printf 'file://%s' "$(printf '%s' "$1" | sed -e 's/%/%25/g' -e 's/ /%20/g' -e 's/#/%23/g' -e 's/?/%3F/g')"
}

chrome() { chromium_headless 1200,900 "$@"; }

# width and height of a PNG, from its IHDR chunk
png_size() {
  hex=$(od -An -tx1 -N24 "$1" | tr -d ' \n')
  case "$hex" in
    89504e470d0a1a0a*) printf '%d %d' "0x$(echo "$hex" | cut -c33-40)" "0x$(echo "$hex" | cut -c41-48)" ;;
    *) return 1 ;;
  esac
}

start=$(date +%s)
url=$(file_url "$out/index.html")
printf '<!DOCTYPE html><html><head><title>blank</title></head><body></body></html>\n' >"$tmp/blank.html"

chrome --dump-dom "$url" >"$tmp/dom.html"
if ! grep -q '<h1>diskval suite' "$tmp/dom.html"; then
  echo "FAIL: Chromium did not load the suite page from $url"
  chromium_log
  exit 1
fi
chrome --screenshot="$tmp/shot.png" "$url" >/dev/null
chrome --screenshot="$tmp/blank.png" "$(file_url "$tmp/blank.html")" >/dev/null
for png in shot blank; do
  if ! dims=$(png_size "$tmp/$png.png"); then
    echo "FAIL: no $png screenshot (or not a PNG)"
    chromium_log
    exit 1
  fi
  # shellcheck disable=SC2086 # split "W H" on purpose
  set -- $dims
  if [ "$1" -eq 0 ] || [ "$2" -eq 0 ]; then
    echo "FAIL: $png screenshot is ${1}x$2"
    exit 1
  fi
done

shot=$(wc -c <"$tmp/shot.png")
blank=$(wc -c <"$tmp/blank.png")
echo "screenshot ${dims% *}x${dims#* }: $shot bytes; an empty page: $blank bytes; $(($(date +%s) - start)) s"
if [ "$shot" -lt $((4 * blank)) ]; then
  echo "FAIL: the page renders (nearly) blank"
  exit 1
fi
echo "PASS: $out/index.html renders"
