#!/usr/bin/env bash
# check_determinism.sh DISKVAL SCENARIO_DIR: two runs of the default suite, each
# scene cut to 1 s (2 processes, then 1) give byte-identical reports apart from the timing
# fields: wall_* in the JSON, wall_per_sim_s in the Markdown, time= in the JUnit XML,
# and the wall column of a scenario's index.html.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the first second of each scene: every engine and reference runs and is judged,
# at a fifth of the default suite's cost (all of it: 172 s on two busy cores)
short=(--set scenario.duration=1)
"$1" suite "$2" "${short[@]}" --out "$work/a" --jobs 2 >/dev/null || true
"$1" suite "$2" "${short[@]}" --out "$work/b" --jobs 1 >/dev/null || true
untimed() { # strip the timing fields of a file to stdout
  case "$1" in
    *.json) grep -vE '"(horizon_)?wall_(s|per_sim_s)"' "$1" ;;
    *.md) sed -E 's/\| [^|]* \|$/|/' "$1" ;;
    *.xml) sed -E 's/ time="[^"]*"//g' "$1" ;;
    *.html) sed -E 's/<td class="n wall">[^<]*</(wall)</' "$1" ;;
    *) cat "$1" ;;
  esac
}
fail=0 n=0
while IFS= read -r f; do
  rel=${f#"$work/a/"}
  n=$((n + 1))
  if [ ! -f "$work/b/$rel" ]; then echo "FAIL: $rel only in the first run"; fail=1; continue; fi
  if ! cmp -s <(untimed "$f") <(untimed "$work/b/$rel"); then
    echo "FAIL: $rel differs"
    diff <(untimed "$f") <(untimed "$work/b/$rel") | head -5
    fail=1
  fi
done < <(find "$work/a" -type f | sort)
[ "$n" -gt 50 ] || { echo "FAIL: only $n files"; fail=1; }
[ $fail -eq 0 ] && echo "determinism: $n files identical apart from timing"
exit $fail
