#!/usr/bin/env bash
# check_generate_edited.sh DISKVAL: generate into its own --out replaces only
# what it wrote (issue 49, item 6). A scene the user edited since is refused:
# exit 2, one line naming the file, nothing written (the edit, every other
# file and the mark byte for byte), whatever the run's options; the same
# scene put back as diskval wrote it is diskval's again. A file diskval
# wrote is replaced by a run of other options, and a file whose digest the
# mark does not hold (a mark from before digests) is diskval's when it is
# what this run writes; a run killed as it writes leaves every file known.
set -u
. "$(dirname "$0")/check_lib.sh"
dv=${1:?usage: check_generate_edited.sh DISKVAL}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
g=$work/G
state() { (cd "$g" && ls -A && sha256sum -- * .diskval-report); }

"$dv" generate --seed 1 --count 2 --out "$g" >/dev/null 2>"$work/stderr"
check '[ $? -eq 0 ]' "the first run: $(cat "$work/stderr")"
cp "$g/gen-1-0.ini" "$work/original.ini"
sed -i 's/^friction = .*/friction = 0.5 ; my own/' "$g/gen-1-0.ini"
before=$(state)
refused "the same run over an edited scene" "gen-1-0\.ini" \
  "$dv" generate --seed 1 --count 2 --out "$g"
check '[ "$before" = "$(state)" ]' "the refused run changed $g: $(diff <(echo "$before") <(state))"
check 'grep -q "my own" "$g/gen-1-0.ini"' "the edit is gone"
refused "another gravity over an edited scene" "gen-1-0\.ini" \
  "$dv" generate --seed 1 --count 2 --gravity 3 --out "$g"
check '[ "$before" = "$(state)" ]' "the refused run (--gravity 3) changed $g"

# the edit undone: diskval's file again, replaced by a run of other options
cp "$work/original.ini" "$g/gen-1-0.ini"
"$dv" generate --seed 1 --count 2 --gravity 3 --out "$g" >/dev/null 2>"$work/stderr"
check '[ $? -eq 0 ]' "the edit undone, --gravity 3 refused: $(cat "$work/stderr")"
check 'grep -q "^gravity = 3$" "$g/gen-1-0.ini"' "--gravity 3 did not replace gen-1-0.ini"
"$dv" generate --seed 1 --count 2 --out "$g" >/dev/null 2>"$work/stderr"
check '[ $? -eq 0 ]' "back to 9.81 over --gravity 3's files refused: $(cat "$work/stderr")"
check 'cmp -s "$work/original.ini" "$g/gen-1-0.ini"' "the scene is not the first run's"

# a run killed while it writes: the files it wrote are diskval's for a run of other options
"$dv" generate --seed 2 --count 300 --gravity 3 --out "$work/k" >/dev/null 2>&1 &
for _ in $(seq 200); do # its first file written (after 256 scenes drawn), or 20 s
  [ -n "$(ls "$work/k" 2>/dev/null)" ] && break
  sleep 0.1
done
kill -9 $! 2>/dev/null
wait $! 2>/dev/null
echo "killed after $(ls "$work/k" | wc -l) of 300 scenes"
"$dv" generate --seed 2 --count 300 --gravity 5 --out "$work/k" >/dev/null 2>"$work/stderr"
check '[ $? -eq 0 ]' "after a run killed as it wrote: $(cat "$work/stderr")"

# no digest recorded (a mark from before digests): what this run writes is diskval's,
# anything else is not
sed -i '/^sums:$/,/^files:$/{/^files:$/!d}' "$g/.diskval-report"
"$dv" generate --seed 1 --count 2 --out "$g" >/dev/null 2>"$work/stderr"
check '[ $? -eq 0 ]' "no digests, the same bytes: refused: $(cat "$work/stderr")"
sed -i '/^sums:$/,/^files:$/{/^files:$/!d}' "$g/.diskval-report"
refused "no digests, other bytes (--gravity 3)" "gen-1-0\.ini" \
  "$dv" generate --seed 1 --count 2 --gravity 3 --out "$g"
[ $fail -eq 0 ] && echo "generate: an edited scene refused and kept, diskval's own replaced"
exit $fail
