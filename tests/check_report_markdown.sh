#!/usr/bin/env bash
# check_report_markdown.sh DISKVAL SCENARIO_DIR: the scenario's description
# reaches report.md as literal text: its HTML, link and control bytes do not
# (they were copied raw); the escaper itself is test_escape's.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
scenarios=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
desc=$'<img src=x onerror=alert(1)> [link](javascript:x) \x1b[2J\x07bell'
timeout -k 2 60 "$diskval" compare "$scenarios/steady_circle.ini" --engines ode --quiet \
  --set scenario.duration=0.5 --set "scenario.description=$desc" --out "$work/out" \
  >/dev/null 2>"$work/err"
code=$?
md=$work/out/steady_circle/report.md
check '[ $code -le 1 ] && [ -f "$md" ]' "exit $code, no report.md: $(cat "$work/err")"
check '! grep -Eq "(^|[^\\])<img" "$md"' "raw HTML in report.md: $(grep "<img" "$md")"
check '! LC_ALL=C grep -q "[[:cntrl:]]" <(tr -d "\n" <"$md")' "control bytes in report.md"
check 'grep -qF "\<img src=x onerror=alert(1)\> \[link\](javascript:x) ?\[2J?bell" "$md"' \
  "the description, escaped, not found: $(sed -n 3p "$md" | cat -v)"
exit $fail
