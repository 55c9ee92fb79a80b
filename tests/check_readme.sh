#!/usr/bin/env bash
# check_readme.sh SOURCE_DIR DISKVAL: the README says what run.sh and the tool do.
#   - the package lists README quotes ("its `PACKAGES`: `...`", "its
#     `TEST_PACKAGES`: `...`") are run.sh's PACKAGES and TEST_PACKAGES, in order;
#   - every default README quotes as "`[engines.NAME] KEY` (default VALUE" is
#     the one `diskval engines` prints (numbers compared as numbers);
#   - in README's scenario file example, every "KEY = VALUE" under an
#     "[engines.NAME]" header is that key's default, unless the default is
#     derived from the scene ("(scene)").
# Exit status: 0 consistent, 1 a difference (each one printed), 2 usage.
set -u
export LC_ALL=C
src=${1:?usage: check_readme.sh SOURCE_DIR DISKVAL}
dv=${2:?usage: check_readme.sh SOURCE_DIR DISKVAL}
readme=$src/README.md
fail=0
differ() {
  echo "FAIL: $*"
  fail=1
}

# run.sh's array NAME, one word per line
run_sh_array() {
  awk -v name="$1" 'index($0, name "=(") == 1 { on = 1; sub(/^[^(]*\(/, "") }
    on { line = $0; sub(/#.*/, "", line); done = sub(/\).*/, "", line); print line; if (done) on = 0 }' \
    "$src/run.sh" | tr -s ' \t' '\n' | sed '/^$/d'
}
# README's list after "its `NAME`: `", one word per line (the README joined into one line)
readme_list() {
  tr '\n' ' ' <"$readme" | grep -o "its \`$1\`: \`[^\`]*\`" | head -n 1 | sed -e "s/^its \`$1\`: \`//" -e 's/`$//' |
    tr -s ' ' '\n' | sed '/^$/d'
}
for list in PACKAGES TEST_PACKAGES; do
  want=$(run_sh_array $list | tr '\n' ' ')
  got=$(readme_list $list | tr '\n' ' ')
  [ -n "$want" ] || differ "run.sh has no $list"
  [ "$got" = "$want" ] || differ "README's $list '$got' is not run.sh's '$want'"
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
    differ "README ($4) quotes [engines.$1] $2, which diskval engines does not list"
  elif [ "$def" != "(scene)" ] && ! same "$3" "$def"; then
    differ "README ($4) says [engines.$1] $2 defaults to $3, diskval engines says $def"
  fi
}

quoted=0
while read -r engine key value; do
  check_default "$engine" "$key" "$value" "in the text"
  quoted=$((quoted + 1))
done < <(tr '\n' ' ' <"$readme" | grep -o '`\[engines\.[a-z]*\] [a-z_]*` (default [^,;) ]*' |
  sed -E 's/^`\[engines\.([a-z]+)\] ([a-z_]+)` \(default (.*)$/\1 \2 \3/')
[ "$quoted" -gt 0 ] || differ "README quotes no '\`[engines.NAME] KEY\` (default VALUE'"

# the scenario file example: indented INI inside "## Scenario files"
example=0
while read -r engine key value; do
  check_default "$engine" "$key" "$value" "scenario file example"
  example=$((example + 1))
done < <(sed -n '/^## Scenario files/,/^## /p' "$readme" | awk '
  /^    \[/ { section = $1; sub(/^\[/, "", section); sub(/\].*/, "", section); next }
  /^    [a-z_]+ += / && section ~ /^engines\./ { e = section; sub(/^engines\./, "", e); print e, $1, $3 }')
[ "$example" -gt 0 ] || differ "README's scenario file example sets no [engines.NAME] key"

[ $fail -eq 0 ] && echo "README agrees with run.sh ($(run_sh_array PACKAGES | wc -l) + $(run_sh_array TEST_PACKAGES | wc -l) packages) and diskval engines ($quoted defaults in the text, $example in the example)"
exit $fail
