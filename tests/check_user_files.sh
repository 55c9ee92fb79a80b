#!/usr/bin/env bash
# check_user_files.sh DISKVAL SCENARIO_DIR: nothing a user owns is lost.
# Each case puts real user files where a careless run would write, runs a
# command, and checks every one of them byte for byte afterwards:
#   - a scenario whose name is a user's directory (scenarios/, src/) is
#     refused by compare and suite, exit 2, one line naming the path;
#   - a suite --out that holds the user's files is refused, and so are sweep
#     and map; a user's directory named like a scenario inside a report
#     directory diskval made is refused too; so is an input inside a report
#     directory the run would replace;
#   - scenarios named as the suite's own files (junit.xml, summary.json,
#     index.html) are refused at load and the suite's files stay;
#   - names that merely look like temporaries (results.old.2024/,
#     notes.tmp.88888.abcdef, .x.tmp.DEADPID.abcdef) are never removed;
#   - no output names an input or another output: suite --junit onto a
#     scenario or onto index.html, simulate --out/--forces onto the scenario,
#     simulate's metadata onto the scenario;
#   - every command run against a directory of tricky names leaves the
#     user's files as they were.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_user_files.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_user_files.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2

# scenario NAME FILE: the falling disk, 0.3 s, named NAME, into FILE
scenario() { sed -e "s/^name = .*/name = $1/" -e "s/^duration = .*/duration = 0.3/" \
  "$sc/falling.ini" >"$2"; }
# sums DIR: every file and directory under DIR with its content's hash
sums() { (cd "$1" && find . -print0 | sort -z | xargs -0 -I{} sh -c \
  'if [ -f "{}" ]; then printf "%s %s\n" "{}" "$(sha256sum <"{}")"; else echo "{}"; fi'); }
# a pid that no process has: that of a process that has ended
sleep 0 &
dead=$!
wait "$dead"

# 1. the scenario's name is the user's directory
mkdir -p proj/scenarios home/src
scenario scenarios proj/scenarios/mine.ini
echo 'int main(void) { return 0; }' >home/src/main.c
scenario src src.ini
sums proj >proj.before
sums home >home.before
(cd proj && refused "compare --out . (name = scenarios)" "scenarios: a directory that diskval did not make" \
  "$dv" compare scenarios/mine.ini --out . --engines ode)
(cd proj && refused "suite --out . (name = scenarios)" "scenarios: a directory that diskval did not make" \
  "$dv" suite scenarios/mine.ini --out . --engines ode)
refused "compare --out home (name = src)" "home/src: a directory that diskval did not make" \
  "$dv" compare src.ini --out home --engines ode
sums proj >proj.after
sums home >home.after
check 'diff proj.before proj.after >/dev/null' "name = scenarios: the project changed: $(diff proj.before proj.after)"
check 'diff home.before home.after >/dev/null' "name = src: home changed: $(diff home.before home.after)"

# a suite's --out that holds the user's files; sweep's and map's too
mkdir -p mine
echo '<p>my page</p>' >mine/index.html
echo '{"mine": true}' >mine/summary.json
scenario fast fast.ini
sums mine >mine.before
refused "suite --out (user's files)" "mine: holds files diskval did not make" \
  "$dv" suite fast.ini --out mine --engines ode
refused "sweep --out (user's files)" "mine: holds files diskval did not make" \
  "$dv" sweep fast.ini --engine ode --vary timestep=1e-3,5e-4 --out mine
refused "map --out (user's files)" "mine: holds files diskval did not make" \
  "$dv" map --c 0.2..0.4:2 --spin 5..6:2 --duration 0.1 --out mine
sums mine >mine.after
check 'diff mine.before mine.after >/dev/null' "--out of the user's: changed: $(diff mine.before mine.after)"
# a mark that only starts like diskval's ("diskval output ...") is the user's file, not ours
mkdir -p marked && echo 'diskval output of my own' >marked/.diskval-report && echo mine >marked/notes.txt
refused "suite --out (a mark of the user's)" "marked: holds files diskval did not make" \
  "$dv" suite fast.ini --out marked --engines ode
check '[ "$(cat marked/notes.txt)" = mine ] && [ "$(ls -A marked | wc -l)" -eq 2 ]' \
  "--out with a mark of the user's: changed: $(ls -A marked)"
# a directory holding only a hidden file of the user's is not empty (only
# diskval's lock and its .diskval-tmp. temporaries are ignored)
mkdir -p dots && echo mine >dots/.notes
refused "suite --out (a hidden file of the user's)" "dots: holds files diskval did not make" \
  "$dv" suite fast.ini --out dots --engines ode
check '[ "$(ls -A dots)" = .notes ] && [ "$(cat dots/.notes)" = mine ]' "--out holding a hidden file: changed: $(ls -A dots)"

# inside a directory diskval made: a user's directory under a scenario's name,
# and an input inside the report a run would replace
"$dv" suite fast.ini --out out --engines ode >/dev/null 2>&1
check '[ -f out/.diskval-report ] && [ -f out/fast/.diskval-report ]' "suite: no mark on its directories"
mkdir -p out/other
echo keep >out/other/notes.txt
scenario other other.ini
refused "suite: a user's directory named like a scenario" "out/other: a directory that diskval did not make" \
  "$dv" suite fast.ini other.ini --out out --engines ode
check '[ "$(cat out/other/notes.txt)" = keep ]' "a user's directory named like a scenario was replaced"
scenario fast out/fast/again.ini
refused "an input inside the report it replaces" "again.ini: an input of this run lies inside" \
  "$dv" suite out/fast/again.ini --out out --engines ode
check '[ -f out/fast/again.ini ]' "an input inside a replaced report was deleted"
rm out/fast/again.ini

# 2. scenario names that are the suite's own files
sums out >out.before
for name in junit.xml summary.json index.html; do
  scenario "$name" "reserved.ini"
  refused "a scenario named $name" "name: '${name//./\\.}' ends in" \
    "$dv" suite fast.ini reserved.ini --out out --engines ode
done
sums out >out.after
check 'diff out.before out.after >/dev/null' "reserved names: the suite's files changed: $(diff out.before out.after)"

# 3. names that look like temporaries, in a directory diskval made
mkdir -p out/results.old.2024 "out/.x.tmp.$dead.abcdef" "out/.fast.old.$dead"
echo data >out/results.old.2024/data.txt
echo notes >out/notes.tmp.88888.abcdef
echo mine >"out/x.csv.tmp.$dead.abcdef"
sums out | grep -e old -e tmp >looks.before
"$dv" suite fast.ini --out out --engines ode >/dev/null 2>&1
"$dv" compare fast.ini --out out --engines ode >/dev/null 2>&1
"$dv" simulate fast.ini --engine reduced --out out/x.csv 2>/dev/null
sums out | grep -e old -e tmp >looks.after
check 'diff looks.before looks.after >/dev/null' "look-alike temporaries were touched: $(diff looks.before looks.after)"

# 4. outputs over inputs, or over another output
mkdir -p sj
scenario fast sj/good.ini
cp sj/good.ini good.bak
"$dv" suite sj --out oj --engines ode >/dev/null 2>&1
cp oj/index.html index.bak
refused "suite --junit onto its scenario" "is an input of this run" \
  "$dv" suite sj --out oj --junit sj/good.ini --engines ode
refused "suite --junit onto its index.html" "is the suite's own" \
  "$dv" suite sj --out oj --junit oj/index.html --engines ode
refused "suite --junit inside a report it replaces" "lies inside oj/fast" \
  "$dv" suite sj --out oj --junit oj/fast/junit.xml --engines ode
refused "suite --junit ''" "--junit needs a file name" "$dv" suite sj --out oj --junit ''
refused "simulate --out onto its scenario" "--out 'sj/good.ini' is the scenario file" \
  "$dv" simulate sj/good.ini --engine reduced --out sj/good.ini
refused "simulate --forces onto its scenario" "--forces '\./sj/good.ini' is the scenario file" \
  "$dv" simulate sj/good.ini --engine reduced --out x.csv --forces ./sj/good.ini
cp sj/good.ini run.json
refused "simulate's metadata onto its scenario" "metadata .* is the scenario file" \
  "$dv" simulate run.json --engine reduced --out run
check 'cmp -s sj/good.ini good.bak && cmp -s run.json good.bak' "an input scenario was overwritten"
check 'cmp -s oj/index.html index.bak' "the suite's index.html was overwritten"
check '[ ! -e x.csv ] && [ ! -e run ]' "a refused simulate wrote its CSV"

# 5. every command against a directory of tricky names: the user's files stay
mkdir -p tricky/results.old.2024 tricky/fast "tricky/.fast.tmp.$dead.abcdef" "tricky/.fast.old.$dead"
echo data >tricky/results.old.2024/data.txt
echo notes >tricky/notes.tmp.88888.abcdef
echo '<p>mine</p>' >tricky/index.html
echo mine >tricky/fast/keep.txt
echo mine >"tricky/y.csv.tmp.$dead.abcdef"
echo mine >tricky/sweep.csv
sums tricky >tricky.before
"$dv" compare fast.ini --out tricky --engines ode >/dev/null 2>&1
"$dv" compare other.ini --out tricky --engines ode >/dev/null 2>&1
"$dv" suite fast.ini --out tricky --engines ode >/dev/null 2>&1
"$dv" sweep fast.ini --engine ode --vary timestep=1e-3,5e-4 --out tricky >/dev/null 2>&1
"$dv" map --c 0.2..0.4:2 --spin 5..6:2 --duration 0.1 --out tricky >/dev/null 2>&1
"$dv" simulate fast.ini --engine ode --out tricky/x.csv --forces tricky/forces.csv 2>/dev/null
(cd tricky && "$dv" analyze ../fast.ini >/dev/null 2>&1)
(cd tricky && "$dv" best ../fast.ini --engine ode --theta-tol 1e-3 >/dev/null 2>&1)
(cd tricky && "$dv" attribute ../fast.ini --engine ode >/dev/null 2>&1)
(cd tricky && "$dv" verify ../fast.ini --engines ode >/dev/null 2>&1)
sums tricky | grep -v -e '^\./other' -e '^\./x\.csv' -e '^\./forces\.csv' -e '^\./\.diskval' >tricky.after
check 'diff tricky.before tricky.after >/dev/null' "tricky names: the user's files changed: $(diff tricky.before tricky.after)"
check '[ -f tricky/other/report.json ] && [ -f tricky/x.csv ] && [ -f tricky/x.csv.json ]' \
  "tricky names: compare or simulate did not write where it may"

[ $fail -eq 0 ] && echo "user files: none lost"
exit $fail
