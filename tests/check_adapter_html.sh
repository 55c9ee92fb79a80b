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
# and no other .md holds it raw, and the pages hold it escaped. The names
# are words too: a scenario named __x__ and an adapter named __ev__ reach
# report.md, verify.md and stability.md escaped, the JSON as given.
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
check 'grep "^html\\\\_liar ran with " "$md" | grep -qF "$esc_bold"' \
  "the setting's value, escaped, not where it ran with: $(grep "ran with" "$md")"
check 'grep "^html\\\\_liar settings chosen: " "$md" | grep -qF "$esc_bold"' \
  "the setting's value, escaped, not where the settings were chosen: $(grep "settings chosen" "$md")"
check 'grep "^- " "$md" | grep -F "$esc_script" | grep -qF "$esc_img"' \
  "the failure's error line and stderr, escaped, not in its list: $(grep "^- " "$md")"

"$diskval" suite "$work/in" --engines html_liar --out "$work/s" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 1 ] && [ -s "$work/s/$name/report.md" ]' "suite: exit $code, want 1: $(cat "$work/stdout")"
check '! grep -Eq "$raw" "$work/s/$name/report.md"' "suite: raw HTML in report.md"
"$diskval" suite "$work/in" --engines html_liar --stability --out "$work/t" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 1 ] && grep -F "| html\_liar |" "$work/t/stability.md" | grep -qF "$esc_script"' \
  "suite --stability: exit $code, want 1 and the error escaped in stability.md: $(cat "$work/stdout")"
"$diskval" suite "$work/in" --engines html_liar --verify --out "$work/v" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 2 ] && grep -F "| html\_liar |" "$work/v/verify.md" | grep -qF "$esc_script"' \
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
# names are words too: a scenario named __x__ and an adapter named __ev__ reach report.md,
# verify.md and stability.md escaped (\_\_x\_\_, not bold), the JSON as given
mkdir "$work/ev" "$work/in2"
cp "$adapter"/* "$work/ev/"
sed -i 's/^name = html_liar$/name = __ev__/' "$work/ev/manifest.ini"
sed 's/^name = .*/name = __x__/' "$work/in/thick.ini" >"$work/in2/x.ini"
DISKVAL_ADAPTERS=$work/ev timeout -k 2 30 "$diskval" compare "$work/in2/x.ini" --engines __ev__ \
  --out "$work/n" --quiet >"$work/stdout" 2>&1
md=$work/n/__x__/report.md
check '[ -s "$md" ] && [ "$(head -n 1 "$md")" = "# \_\_x\_\_: FAIL" ] && grep -qF "| \_\_ev\_\_ |" "$md" &&
  grep -q "^\\\\_\\\\_ev\\\\_\\\\_: error: " "$md" && ! grep -Eq "__(ev|x)|(ev|x)__" "$md"' \
  "names raw in report.md: $(grep -E "_(ev|x)" "$md") $(cat "$work/stdout")"
check 'grep -q "\"scenario\":[[:space:]]*\"__x__\"" "$work/n/__x__/report.json" && grep -q "\"__ev__\"" "$work/n/__x__/report.json"' \
  "report.json: the names not as given: $(grep -E "_(ev|x)" "$work/n/__x__/report.json")"
for mode in verify stability; do
  DISKVAL_ADAPTERS=$work/ev timeout -k 2 60 "$diskval" suite "$work/in2" --engines __ev__ --$mode \
    --out "$work/n$mode" --quiet >"$work/stdout" 2>&1
  check 'grep -qF "| \_\_x\_\_ | \_\_ev\_\_ |" "$work/n$mode/$mode.md" && ! grep -Eq "__(ev|x)|(ev|x)__" "$work/n$mode/$mode.md" &&
    grep -q "\"__ev__\"" "$work/n$mode/$mode.json"' "$mode.md: names raw: $(grep -E "_(ev|x)" "$work/n$mode/$mode.md")"
done
[ $fail -eq 0 ] && echo "adapter_html: an adapter's error, stderr and setting values are text, never markup"
exit $fail
