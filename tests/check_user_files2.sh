#!/usr/bin/env bash
# check_user_files2.sh DISKVAL SCENARIO_DIR: nothing a user owns is lost, the
# second pass (links, inputs in the way of outputs, foreign files). Every case
# checks the user's files byte for byte (sha256) and that a link stays a link:
#   - an output that is a symbolic link is written through: the file it names
#     gets the output, the link stays; a link through /proc (a stream) is
#     written in place; a link to nothing or a loop is refused;
#   - simulate's FILE.json replaces only simulate's own metadata;
#   - judge refuses a trajectory inside the report it would replace;
#   - sweep and map refuse a scenario that is one of their outputs;
#   - --junit onto another output of the run is refused;
#   - a report directory holding a user's file is not replaced;
#   - a user's file in a map's --out is not lost to a report or to suite's files;
#   - simulate's FILE.json made by a user during the run is not replaced;
#   - judge's names never make two of a report's outputs one file;
#   - only diskval's own temporaries, lock and --out are taken for them;
#   - an --out left by '..' through a directory not there yet (OUT/NAME/..) is
#     refused with nothing made.
#   - judge's names obey the scenario names' rules, and a long file name
#     gets a default name that does.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_user_files2.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_user_files2.sh DISKVAL SCENARIO_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2

# scenario NAME FILE: the falling disk, 0.3 s, named NAME, into FILE
scenario() { sed -e "s/^name = .*/name = $1/" -e "s/^duration = .*/duration = 0.3/" \
  "$sc/falling.ini" >"$2"; }
# same FILE SUM: FILE's sha256 is SUM
same() { [ "$(sha256sum <"$1")" = "$2" ]; }
header='^t,theta,phi,psi,x,y,contact_x,contact_y'
scenario fast sc.ini

# 1. outputs through symbolic links
mkdir archive
echo old >archive/run1.csv
ln -s archive/run1.csv latest.csv
"$dv" simulate sc.ini --engine reduced --out latest.csv 2>/dev/null
check '[ -L latest.csv ] && [ "$(readlink latest.csv)" = archive/run1.csv ]' \
  "simulate --out LINK: the link was replaced"
check 'grep -Eq "$header" archive/run1.csv' "simulate --out LINK: its file did not get the CSV"
check '[ -f latest.csv.json ] && [ ! -e archive/run1.csv.json ]' \
  "simulate --out LINK: the metadata is not beside the name given"
echo old >archive/forces.csv
ln -s archive/forces.csv forces.csv
"$dv" simulate sc.ini --engine reduced --out run.csv --forces forces.csv 2>/dev/null
check '[ -L forces.csv ] && grep -q "^t,force_x" archive/forces.csv' "simulate --forces LINK: the link was replaced"
ln -s /proc/self/fd/1 mystdout
"$dv" simulate sc.ini --engine reduced --out mystdout >cap.txt 2>/dev/null
check '[ -L mystdout ] && grep -Eq "$header" cap.txt && [ ! -e mystdout.json ]' \
  "simulate --out LINK-TO-STDOUT: link kept $([ -L mystdout ] && echo yes), $(wc -l <cap.txt) lines captured, mystdout.json made $([ -e mystdout.json ] && echo yes)"
ln -s nowhere/x.csv dangling.csv
ln -s loop1 loop2
ln -s loop2 loop1
refused "simulate --out a dangling link" "dangling.csv: a symbolic link to nothing" \
  "$dv" simulate sc.ini --engine reduced --out dangling.csv
refused "simulate --out a link loop" "loop1: a symbolic link to nothing \(a loop\)" \
  "$dv" simulate sc.ini --engine reduced --out loop1
check '[ -L dangling.csv ] && [ ! -e nowhere ] && [ -L loop1 ] && [ -L loop2 ] && [ ! -e dangling.csv.json ]' \
  "a refused link was touched"
sum=$(sha256sum <sc.ini)
ln -s sc.ini to_input.csv
refused "simulate --out a link to its scenario" "is the scenario file" \
  "$dv" simulate sc.ini --engine reduced --out to_input.csv
check 'same sc.ini "$sum" && [ -L to_input.csv ]' "simulate --out a link to its scenario: changed"
echo '<testsuites/>' >archive/junit.xml
ln -s archive/junit.xml junit-link.xml
"$dv" suite sc.ini --engines ode --out out --junit junit-link.xml >/dev/null 2>&1
check '[ -L junit-link.xml ] && grep -q "testsuite name" archive/junit.xml' "suite --junit LINK: the link was replaced"
# 5. simulate's FILE.json: only simulate's own metadata is replaced
echo '{"mine": true}' >mine.csv.json
sum=$(sha256sum <mine.csv.json)
refused "simulate --out X over a user's X.json" "mine.csv.json: a file that is not simulate's metadata" \
  "$dv" simulate sc.ini --engine reduced --out mine.csv
check 'same mine.csv.json "$sum" && [ ! -e mine.csv ]' "a user's X.json was replaced, or X written"
"$dv" simulate sc.ini --engine reduced --out again.csv 2>/dev/null
"$dv" simulate sc.ini --engine reduced --out again.csv 2>/dev/null
check '[ $? -eq 0 ]' "simulate's own X.json was not replaced"
# a user's X.json that comes while the run goes is not replaced either
sed -e "s/^duration = .*/duration = 5/" "$sc/steady_circle.ini" >slow.ini
"$dv" simulate slow.ini --engine ode --out during.csv >/dev/null 2>"$work/stderr" &
pid=$!
for i in $(seq 1000); do
  ls -A | grep -q '^\.diskval-tmp\.' && break
  sleep 0.01
done
echo '{"mine": "made while the run went"}' >during.csv.json
sum=$(sha256sum <during.csv.json)
wait $pid
code=$?
check '[ $code -eq 2 ] && grep -q "during.csv.json: a file that is not simulate" "$work/stderr"' \
  "simulate over a user's X.json made during the run: exit $code: $(cat "$work/stderr")"
check 'same during.csv.json "$sum" && [ ! -e during.csv ]' \
  "a user's X.json made during the run was replaced, or X written"


# 2. judge: a trajectory inside the report the run replaces
"$dv" simulate sc.ini --engine ode --out ode_run.csv 2>/dev/null
"$dv" judge sc.ini ode_run.csv --out r >/dev/null 2>&1
check '[ -f r/fast/ode_run.csv ]' "judge wrote no report to test with"
sum=$(sha256sum <r/fast/ode_run.csv)
refused "judge of a trajectory in its own report" "r/fast/ode_run.csv: an input of this run lies inside" \
  "$dv" judge sc.ini r/fast/ode_run.csv --out r
refused "judge --name of a trajectory in its own report" "r/fast/ode_run.csv: an input of this run lies inside" \
  "$dv" judge sc.ini r/fast/ode_run.csv --name other --out r
check 'same r/fast/ode_run.csv "$sum"' "judge: its input inside the report was lost or rewritten"

# 3. sweep and map: a scenario in the marked --out under an output's name
for f in sweep.csv work_precision.svg; do
  mkdir -p "sw-$f"
  echo "diskval output directory, format 1" >"sw-$f/.diskval-report"
  cp sc.ini "sw-$f/$f"
  refused "sweep of a scenario named $f in its --out" "sw-$f/$f: an input of this run is its output" \
    "$dv" sweep "sw-$f/$f" --engine ode --vary timestep=1e-3,2e-3 --out "sw-$f"
  check 'cmp -s sc.ini "sw-$f/$f"' "sweep overwrote its scenario $f"
done
mkdir -p mp
echo "diskval output directory, format 1" >mp/.diskval-report
cp sc.ini mp/map.csv
refused "map of a scenario named map.csv in its --out" "mp/map.csv: an input of this run is its output" \
  "$dv" map mp/map.csv --engines ode --c 0.2..0.4:2 --spin 5..6:2 --duration 0.1 --out mp
check 'cmp -s sc.ini mp/map.csv' "map overwrote its scenario"

# 4. --junit onto another output of the run (out/ and r/ are from above)
for f in out/.diskval-report out/fast/report.md out/fast/report.json out/fresh/junit.xml; do
  [ -e "$f" ] && sum=$(sha256sum <"$f")
  scenario fresh fresh.ini
  refused "suite --junit $f" "--junit '$f'" \
    "$dv" suite sc.ini fresh.ini --engines ode --out out --junit "$f"
  [ -e "$f" ] && check 'same "$f" "$sum"' "suite --junit $f: changed"
done
ln -s out/.diskval-report mark-link.xml
refused "suite --junit a link to its mark" "diskval's own files" \
  "$dv" suite sc.ini --engines ode --out out --junit mark-link.xml
check '[ ! -e out/fresh ]' "a refused suite wrote a report"
sum=$(sha256sum <r/fast/report.md)
refused "judge --junit onto its report.md" "--junit 'r/fast/report.md' lies inside" \
  "$dv" judge sc.ini ode_run.csv --out r --junit r/fast/report.md
check 'same r/fast/report.md "$sum"' "judge --junit: its report.md changed"
"$dv" suite sc.ini --engines ode --out out --junit out/junit.xml >/dev/null 2>&1
check '[ $? -ne 2 ] && grep -q "testsuite name" out/junit.xml' "suite --junit OUT/junit.xml was refused"

# 5. a user's file inside a report directory diskval made
echo keep >out/fast/notes.txt
sum=$(sha256sum <out/fast/notes.txt)
refused "suite over a report holding a user's file" "out/fast/notes.txt: diskval did not make it" \
  "$dv" suite sc.ini --engines ode --out out
refused "compare over a report holding a user's file" "out/fast/notes.txt: diskval did not make it" \
  "$dv" compare sc.ini --engines ode --out out
check 'same out/fast/notes.txt "$sum"' "a user's file in a report was lost"
rm out/fast/notes.txt
# a report made before marks listed its files is still replaced; a user's file in it is not
echo "diskval output directory, format 1" >out/fast/.diskval-report
echo keep >out/fast/notes.txt
refused "a report with an old mark holding a user's file" "out/fast/notes.txt: diskval did not make it" \
  "$dv" compare sc.ini --engines ode --out out
rm out/fast/notes.txt
"$dv" compare sc.ini --engines ode --out out >/dev/null 2>&1
check '[ $? -ne 2 ] && grep -q "^report.json$" out/fast/.diskval-report' "a report with an old mark was not replaced"

# 6. the --out of map (and sweep, suite) is no report: a user's file there is not lost
# when a report of the same name replaces it, nor replaced by another command's output
sed -e "s/^name = .*/name = circ/" -e "s/^duration = .*/duration = 0.3/" "$sc/steady_circle.ini" >circ.ini
mapped() { "$dv" map circ.ini --c 0.1..0.3:2 --spin 5..20:2 --engines ode --duration 0.2 \
  --quiet --out "$1" >/dev/null 2>&1; }
mapped mo/circ
echo mine >mo/circ/measurements.csv
echo '<svg/>' >mo/circ/mine.svg
sums=$(sha256sum mo/circ/measurements.csv mo/circ/mine.svg)
refused "compare over a map's --out holding a user's CSV" "mo/circ/(measurements.csv|mine.svg): diskval did not make it" \
  "$dv" compare circ.ini --engines ode --out mo
echo "diskval output directory, format 1" >mo/circ/.diskval-report # as map marked it before
refused "compare over an old map's --out holding a user's CSV" "mo/circ/[a-z_.]+: diskval did not make it" \
  "$dv" compare circ.ini --engines ode --out mo
check '[ "$(sha256sum mo/circ/measurements.csv mo/circ/mine.svg)" = "$sums" ]' \
  "a user's file in a map's --out was lost to a report"
for f in index.html summary.json; do
  mapped "mr-$f"
  echo mine >"mr-$f/$f"
  sum=$(sha256sum <"mr-$f/$f")
  refused "suite over a user's $f in a map's --out" "mr-$f/$f: diskval did not make it" \
    "$dv" suite circ.ini --engines ode --out "mr-$f"
  check 'same "mr-$f/$f" "$sum" && [ ! -e "mr-$f/circ" ]' "suite replaced a user's $f in a map's --out"
done
mapped mr-index.html
check '[ $? -eq 0 ]' "map into its own --out again was refused"

# judge's names are file names as a scenario's are; a long file name gets a default that is one
refused "judge --name .." "name '\.\.' is not a file name" "$dv" judge sc.ini ode_run.csv --name .. --out jn
refused "judge --name .hidden" "name '\.hidden' starts with '\.'" \
  "$dv" judge sc.ini ode_run.csv --name .hidden --out jn
check '[ ! -e jn ]' "a refused judge wrote its report"
long=a_trajectory_file_whose_name_runs_well_past_forty_characters
cp ode_run.csv "$long.csv"
cp ode_run.csv .hidden.csv
"$dv" judge sc.ini "$long.csv" .hidden.csv --out jn >/dev/null 2>"$work/stderr"
check '[ -f "jn/fast/${long:0:40}.csv" ] && [ -f jn/fast/_hidden.csv ]' \
  "judge of a long or hidden file name: no report under a default name: $(cat "$work/stderr")"

# a thick scene's report holds matched-NAME.csv, NAME's matched reference: no trajectory takes it
sed -e "s/^\[disk\]/[disk]\nthickness = 0.004/" sc.ini >thick.ini
"$dv" simulate thick.ini --engine ode --out thick_run.csv 2>/dev/null
refused "judge --name x,matched-x of a thick scene" "name 'matched-x' is the file of the matched reference of 'x'" \
  "$dv" judge thick.ini thick_run.csv thick_run.csv --name x,matched-x --out jt
cp thick_run.csv x.csv
cp thick_run.csv matched-x.csv
refused "judge x.csv matched-x.csv of a thick scene" "name 'matched-x' is the file of the matched reference of 'x'" \
  "$dv" judge thick.ini matched-x.csv x.csv --out jt
check '[ ! -e jt ]' "a refused judge wrote its report"

# 7. only what diskval made is taken for its temporaries, lock or output
mkdir tm
echo mine >tm/.diskval-tmp.099999.abcdef # no PID diskval would write
mkdir tm/.diskval-tmp.99998.abcdef # a dead run's report, half written: removed
echo "diskval output directory, format 1" >tm/.diskval-tmp.99998.abcdef/.diskval-report
echo "# r" >tm/.diskval-tmp.99998.abcdef/report.md
echo half >tm/.diskval-tmp.99998.abcdef/.diskval-tmp.99998.Xyz123 # the file it was writing
mkdir tm/.diskval-tmp.99998.ghijkl # killed before its mark's rename: only that temporary file
echo "diskval output directory, format 1" >tm/.diskval-tmp.99998.ghijkl/.diskval-tmp.99998.Mark12
sums=$(sha256sum tm/.diskval-tmp.099999.abcdef)
if ! kill -0 99999 99998 2>/dev/null; then
  "$dv" simulate sc.ini --engine reduced --out tm/run.csv 2>/dev/null
  check '[ "$(sha256sum tm/.diskval-tmp.099999.abcdef)" = "$sums" ]' \
    "a user's file named like a stale temporary was removed"
  check '[ ! -e tm/.diskval-tmp.99998.abcdef ]' "a dead run's report was not removed"
  check '[ ! -e tm/.diskval-tmp.99998.ghijkl ]' "a dead run's report killed before its mark stayed"
fi
mkdir lk
echo "a user's notes" >lk/.diskval.lock
sum=$(sha256sum <lk/.diskval.lock)
refused "sweep into a directory holding a user's .diskval.lock" "lk: holds files diskval did not make" \
  "$dv" sweep sc.ini --engine ode --vary timestep=1e-3,2e-3 --out lk
check 'same lk/.diskval.lock "$sum" && [ ! -e lk/.diskval-report ]' "a user's .diskval.lock was taken for a lock"
refused "suite --junit NEW/./index.html" "--junit 'new/./index.html' is the suite's own" \
  "$dv" suite sc.ini --engines ode --out new --junit new/./index.html
check '[ ! -e new ]' "a refused suite made its --out"

# an --out through a directory not there yet, left by '..' (OUT/NAME/..): refused before
# anything is made, so no empty OUT/NAME stays in the way of the next run
mkdir F8
cp sc.ini F8/
refused "compare --out F8/fast/.." "F8/fast/\.\.: its '\.\.' leaves a directory that does not exist" \
  "$dv" compare F8/sc.ini --engines ode --out F8/fast/..
check '[ ! -e F8/fast ]' "a refused compare made F8/fast"
"$dv" compare F8/sc.ini --engines ode --out F8 --quiet >/dev/null 2>"$work/stderr"
check '[ -f F8/fast/report.md ]' "compare --out F8 after --out F8/fast/..: $(cat "$work/stderr")"

[ $fail -eq 0 ] && echo "user files (second pass): none lost"
exit $fail
