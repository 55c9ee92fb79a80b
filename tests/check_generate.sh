#!/usr/bin/env bash
# check_generate.sh DISKVAL: diskval generate writes scenario files that load,
# the same for the same seed; bad arguments are one line and exit 2 with
# nothing written; a user's file of a generated name is never replaced.
set -u
dv=${1:?usage: check_generate.sh DISKVAL}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0
"$dv" generate --seed 7 --count 6 --out "$tmp/a" >/dev/null || { echo "generate failed"; bad=1; }
"$dv" generate --seed 7 --count 6 --out "$tmp/b" >/dev/null || { echo "generate failed"; bad=1; }
diff -r "$tmp/a" "$tmp/b" >/dev/null || { echo "the same seed gave other files"; bad=1; }
[ "$(ls "$tmp/a"/*.ini | wc -l)" -eq 6 ] || { echo "not 6 files"; bad=1; }
for f in "$tmp/a"/gen-7-0.ini "$tmp/a"/gen-7-3.ini; do # every scene loads: the props test
  "$dv" analyze "$f" --json >/dev/null 2>"$tmp/err" || { echo "$f does not load: $(cat "$tmp/err")"; bad=1; }
done
# again into its own directory: allowed (diskval's own files)
"$dv" generate --seed 7 --count 6 --out "$tmp/a" >/dev/null || { echo "a second run into its own --out refused"; bad=1; }
for args in "--count 3 --out $tmp/c" "--seed 1 --out $tmp/c" "--seed 1 --count 3" "--seed -1 --count 3 --out $tmp/c" \
  "--seed 1 --count 0 --out $tmp/c" "--seed 1 --count 3 --out $tmp/c --gravity nan" "--seed 1 --count 3 --out $tmp/c extra"; do
  # shellcheck disable=SC2086
  "$dv" generate $args >/dev/null 2>"$tmp/err"
  code=$?
  [ $code -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] || { echo "generate $args: exit $code: $(cat "$tmp/err")"; bad=1; }
  [ ! -e "$tmp/c" ] || { echo "generate $args wrote $tmp/c"; bad=1; }
done
# a user's file of a generated name, and a symlink, are kept byte for byte
mkdir -p "$tmp/u"
echo "my own notes" >"$tmp/u/gen-7-1.ini"
echo "target" >"$tmp/target"
ln -s "$tmp/target" "$tmp/u/gen-7-2.ini"
before=$(sha256sum "$tmp/u/gen-7-1.ini" "$tmp/target")
"$dv" generate --seed 7 --count 3 --out "$tmp/u" >/dev/null 2>"$tmp/err"
code=$?
[ $code -eq 2 ] || { echo "generate over a user's files: exit $code"; bad=1; }
[ "$before" = "$(sha256sum "$tmp/u/gen-7-1.ini" "$tmp/target")" ] || { echo "a user's file changed"; bad=1; }
[ -L "$tmp/u/gen-7-2.ini" ] || { echo "a user's symlink is gone"; bad=1; }
[ ! -e "$tmp/u/gen-7-0.ini" ] || { echo "wrote beside a user's files"; bad=1; }
[ $bad -eq 0 ] && echo "generate: loadable, reproducible, refuses bad input, keeps a user's files"
exit $bad
