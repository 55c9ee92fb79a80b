#!/usr/bin/env bash
# check_adapter_html.sh DISKVAL SCENARIO ADAPTER: an adapter's words are text
# in every report, never markup (issue 49, item 9). The test adapter
# (tests/adapters/html_liar) has a choice value <b>bold</b>, writes
# <img src=x ...> on standard error and answers its first advance with
# "error <script>alert(1)</script>". After `compare`, `suite`, `suite
# --stability` and `suite --verify` of SCENARIO made 2 mm thick: report.md
# holds none of it raw, and holds each escaped on its own line (the settings
# it ran with, the settings chosen, the failure); stability.md and verify.md
# hold the error escaped; no page (index.html, stability.html), no junit.xml
# and no other .md holds it raw, and the pages hold it escaped.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
scenario=$2
adapter=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/in"
awk '/^\[disk\]/{print; print "thickness = 0.002"; next} {print}' "$scenario" >"$work/in/thick.ini"
name=$(awk -F' *= *' '$1 == "name" {print $2; exit}' "$scenario")
export DISKVAL_ADAPTERS=$adapter

raw='(^|[^\\])<(script|/?b>|img|/?i>)' # markup, unless Markdown-escaped (\<)
timeout -k 2 30 "$diskval" compare "$work/in/thick.ini" --engines html_liar --out "$work/c" \
  --quiet >"$work/stdout" 2>&1
code=$?
md=$work/c/$name/report.md
check '[ $code -eq 1 ] && [ -s "$md" ]' "compare: exit $code, want 1 and report.md: $(cat "$work/stdout")"
check '! grep -Eq "$raw" "$md"' "raw HTML in report.md: $(grep -En "$raw" "$md")"
esc_script='\<script\>alert(1)\</script\>'
esc_bold='\<b\>bold\</b\>'
esc_img='\<img src=x onerror=alert(2)\>'
check 'grep "^html_liar ran with " "$md" | grep -qF "$esc_bold"' \
  "the setting's value, escaped, not where it ran with: $(grep "ran with" "$md")"
check 'grep "^html_liar settings chosen: " "$md" | grep -qF "$esc_bold"' \
  "the setting's value, escaped, not where the settings were chosen: $(grep "settings chosen" "$md")"
check 'grep "^- " "$md" | grep -F "$esc_script" | grep -qF "$esc_img"' \
  "the failure's error line and stderr, escaped, not in its list: $(grep "^- " "$md")"

"$diskval" suite "$work/in" --engines html_liar --out "$work/s" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 1 ] && [ -s "$work/s/$name/report.md" ]' "suite: exit $code, want 1: $(cat "$work/stdout")"
check '! grep -Eq "$raw" "$work/s/$name/report.md"' "suite: raw HTML in report.md"
"$diskval" suite "$work/in" --engines html_liar --stability --out "$work/t" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 1 ] && grep -F "| html_liar |" "$work/t/stability.md" | grep -qF "$esc_script"' \
  "suite --stability: exit $code, want 1 and the error escaped in stability.md: $(cat "$work/stdout")"
"$diskval" suite "$work/in" --engines html_liar --verify --out "$work/v" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 2 ] && grep -F "| html_liar |" "$work/v/verify.md" | grep -qF "$esc_script"' \
  "suite --verify: exit $code, want 2 and the error escaped in verify.md: $(cat "$work/stdout")"
pages=$(find "$work/c" "$work/s" "$work/t" "$work/v" -name '*.html' -o -name '*.xml' -o -name '*.md' | sort)
check '[ "$(echo "$pages" | wc -l)" -ge 5 ]' "not every page written: $pages"
for f in $pages; do # a page's own <img>, <b>, a Markdown-escaped \< are not the adapter's
  bad='<script>alert|<b>bold|<img src=x|<i>1'
  case $f in *.md) bad=$raw ;; esac
  check '! grep -Eq "$bad" "$f"' "raw HTML in ${f#"$work"/}: $(grep -Eo ".{0,30}($bad).{0,20}" "$f")"
done
for f in "$work/c/$name/index.html" "$work/s/$name/index.html"; do
  check 'grep -qF "&lt;script&gt;alert(1)&lt;/script&gt;" "$f" && grep -qF "&lt;b&gt;bold&lt;/b&gt;" "$f"' \
    "${f#"$work"/}: the adapter's words, escaped, not found"
done
[ $fail -eq 0 ] && echo "adapter_html: an adapter's error, stderr and setting values are text, never markup"
exit $fail
