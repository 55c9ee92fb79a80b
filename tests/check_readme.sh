#!/usr/bin/env bash
# check_readme.sh SOURCE_DIR DISKVAL: README.md and the manual (docs/*.md) say
# what run.sh and the tool do.
#   - README.md is at most 300 lines (the manual is docs/);
#   - the package lists the docs quote ("its `PACKAGES`: `...`", "its
#     `TEST_PACKAGES`: `...`") are run.sh's PACKAGES and TEST_PACKAGES, in order;
#   - every default the docs quote as "`[engines.NAME] KEY` (default VALUE" is
#     the one `diskval engines` prints (numbers compared as numbers);
#   - in the scenario file example of docs/scenarios.md, every "KEY = VALUE"
#     under an "[engines.NAME]" header is that key's default, unless the
#     default is derived from the scene ("(scene)");
#   - README's first object (its indented scenario file) loads;
#   - every relative link in README.md and docs/*.md names a file that exists,
#     and its #anchor a heading of that file;
#   - docs/README.md, the manual's index, links every file of docs/;
#   - README's command table names every command `diskval --help` lists, and
#     no other.
# Exit status: 0 consistent, 1 a difference (each one printed), 2 usage.
set -u
export LC_ALL=C
src=${1:?usage: check_readme.sh SOURCE_DIR DISKVAL}
dv=${2:?usage: check_readme.sh SOURCE_DIR DISKVAL}
readme=$src/README.md
docs=("$readme" "$src"/docs/*.md)
fail=0
differ() {
  echo "FAIL: $*"
  fail=1
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

lines=$(wc -l <"$readme")
[ "$lines" -le 300 ] || differ "README.md has $lines lines, more than 300: move the detail to docs/"

# run.sh's array NAME, one word per line
run_sh_array() {
  awk -v name="$1" 'index($0, name "=(") == 1 { on = 1; sub(/^[^(]*\(/, "") }
    on { line = $0; sub(/#.*/, "", line); done = sub(/\).*/, "", line); print line; if (done) on = 0 }' \
    "$src/run.sh" | tr -s ' \t' '\n' | sed '/^$/d'
}
# the first list after "its `NAME`: `" in the docs, one word per line (each file joined into one line)
docs_list() {
  local f
  for f in "${docs[@]}"; do
    tr '\n' ' ' <"$f" | grep -o "its \`$1\`: \`[^\`]*\`" | head -n 1
  done | head -n 1 | sed -e "s/^its \`$1\`: \`//" -e 's/`$//' | tr -s ' ' '\n' | sed '/^$/d'
}
for list in PACKAGES TEST_PACKAGES; do
  want=$(run_sh_array $list | tr '\n' ' ')
  got=$(docs_list $list | tr '\n' ' ')
  [ -n "$want" ] || differ "run.sh has no $list"
  [ "$got" = "$want" ] || differ "the docs' $list '$got' is not run.sh's '$want'"
done

# the defaults diskval engines prints: "ENGINE KEY DEFAULT" per line
defaults=$("$dv" engines | awk '/^[a-z]/ { engine = $1 } /^    [a-z_]+ +default / { print engine, $1, $3 }')
[ -n "$defaults" ] || differ "diskval engines printed no settings"
# same VALUE as DEFAULT: equal text, or both numbers and equal as numbers
same() {
  [ "$1" = "$2" ] && return 0
  awk -v a="$1" -v b="$2" 'BEGIN { n = "^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$"; exit !(a ~ n && b ~ n && a + 0 == b + 0) }'
}
check_default() { # engine key value where
  local def
  def=$(awk -v e="$1" -v k="$2" '$1 == e && $2 == k { print $3 }' <<<"$defaults")
  if [ -z "$def" ]; then
    differ "$4 quotes [engines.$1] $2, which diskval engines does not list"
  elif [ "$def" != "(scene)" ] && ! same "$3" "$def"; then
    differ "$4 says [engines.$1] $2 defaults to $3, diskval engines says $def"
  fi
}

quoted=0
for f in "${docs[@]}"; do
  while read -r engine key value; do
    check_default "$engine" "$key" "$value" "${f#"$src"/}"
    quoted=$((quoted + 1))
  done < <(tr '\n' ' ' <"$f" | grep -o '`\[engines\.[a-z]*\] [a-z_]*` (default [^,;) ]*' |
    sed -E 's/^`\[engines\.([a-z]+)\] ([a-z_]+)` \(default (.*)$/\1 \2 \3/')
done
[ "$quoted" -gt 0 ] || differ "the docs quote no '\`[engines.NAME] KEY\` (default VALUE'"

# the scenario file example: indented INI in docs/scenarios.md
example=0
while read -r engine key value; do
  check_default "$engine" "$key" "$value" "docs/scenarios.md (the example)"
  example=$((example + 1))
done < <(awk '
  /^    \[/ { section = $1; sub(/^\[/, "", section); sub(/\].*/, "", section); next }
  /^    [a-z_]+ += / && section ~ /^engines\./ { e = section; sub(/^engines\./, "", e); print e, $1, $3 }' \
  "$src/docs/scenarios.md")
[ "$example" -gt 0 ] || differ "docs/scenarios.md's scenario file example sets no [engines.NAME] key"

# README's first object: the first indented block that holds "[scenario]", as a file
awk '/^    / { block = block substr($0, 5) "\n"; next }
  /^$/ && block != "" { block = block "\n"; next }
  { if (block ~ /\[scenario\]/) { printf "%s", block; exit } block = "" }' "$readme" >"$work/first.ini"
if ! grep -q '^\[scenario\]' "$work/first.ini"; then
  differ "README.md shows no scenario file (an indented block with [scenario])"
elif ! err=$("$dv" analyze "$work/first.ini" 2>&1 >/dev/null); then
  differ "README.md's first object does not load: $err"
fi

# every relative link resolves: ](PATH) or ](PATH#ANCHOR), PATH from the linking file's folder
slug() { # a heading as GitHub makes its anchor
  sed -E 's/^#+ +//' | tr 'A-Z' 'a-z' | sed -E 's/[^a-z0-9 _-]//g; s/ /-/g'
}
links=0
for f in "${docs[@]}"; do
  dir=$(dirname "$f")
  while IFS= read -r link; do
    links=$((links + 1))
    path=${link%%#*}
    anchor=
    [ "$path" != "$link" ] && anchor=${link#*#}
    target=$f
    [ -n "$path" ] && target=$dir/$path
    if [ ! -e "$target" ]; then
      differ "${f#"$src"/}: link ($link) names $path, which does not exist"
    elif [ -n "$anchor" ] && ! grep -E '^#+ ' "$target" | slug | grep -qxF "$anchor"; then
      differ "${f#"$src"/}: link ($link): no heading of ${target#"$src"/} has the anchor #$anchor"
    fi
  done < <(grep -oE '\]\([^)[:space:]]+\)' "$f" | sed -E 's/^\]\(//; s/\)$//' | grep -vE '^[a-z]+:')
done
[ "$links" -gt 0 ] || differ "README.md and docs/ link to nothing"

# the manual's index, docs/README.md, links every file of docs/
for f in "$src"/docs/*.md; do
  name=$(basename "$f")
  [ "$name" = README.md ] && continue
  grep -qF "]($name)" "$src/docs/README.md" || differ "docs/README.md (the index) does not link $name"
done

# README's command table against diskval --help's command list
"$dv" --help | awk '/^commands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }' | sort >"$work/known"
grep -oE '^\| `diskval [a-z]+`' "$readme" | sed -E 's/^\| `diskval //; s/`$//' | sort >"$work/table"
[ -s "$work/known" ] || differ "diskval --help lists no command"
for cmd in $(comm -13 "$work/known" "$work/table"); do
  differ "README.md's command table names 'diskval $cmd', which diskval --help does not list"
done
for cmd in $(comm -23 "$work/known" "$work/table"); do
  differ "README.md's command table leaves out 'diskval $cmd'"
done

[ $fail -eq 0 ] && echo "README ($lines lines) and docs/ agree with run.sh ($(run_sh_array PACKAGES | wc -l) + $(run_sh_array TEST_PACKAGES | wc -l) packages), diskval engines ($quoted defaults in the text, $example in the example) and diskval --help ($(wc -l <"$work/table") commands); $links links resolve; the first object loads"
exit $fail
