#!/usr/bin/env bash
# check_judge_memory.sh DISKVAL SCENARIO: judge's memory is bounded before the
# work (run_trajfile.h: DV_TRAJ_ROW_BYTES a row, with the comparison's need,
# within [scenario] memory_budget). SCENARIO: tests/data/short_circle.ini (1 s).
#   - 10^6 rows within the duration: refused at the row over the budget, one
#     line, exit 2, at a peak RSS of 164 MB measured (it took 1.04 GB before);
#   - 3 x 10^5 rows over 3 s: the rows past the duration are not read (peak
#     130 MB measured; all of them: 333 MB).
# The limits on the peak RSS (400 and 250 MB) sit between. Re-measure:
# ctest -V -R NAME prints the peaks.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_judge_memory.sh DISKVAL SCENARIO}
sc=${2:?usage}
[ -x /usr/bin/time ] || { echo "SKIP: /usr/bin/time not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
# gen N T: N + 1 rows of a consistent state-form file from t = 0 to T s
gen() {
  awk -v n="$1" -v T="$2" 'BEGIN {
    w = 3.038043841609511; p = -15.190219208047555; r = 0.1; a = 0.5; c = cos(1)
    print "t,theta,phi,psi,x,y,contact_x,contact_y,theta_dot,phi_dot,psi_dot,energy"
    for (i = 0; i <= n; i++) {
      t = T * i / n; ph = w * t; x = a * sin(ph); y = a * (1 - cos(ph))
      printf "%.12g,1,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,0,%.17g,%.17g,2.210418322052009\n",
        t, ph, p * t, x, y, x + r * c * cos(ph), y + r * c * sin(ph), w, p
    } }'
}
# peak FILE: the peak RSS in MB /usr/bin/time -v wrote into FILE
peak() { awk '/Maximum resident/ { printf "%d", $NF / 1024 }' "$1"; }
gen 1000000 1 >big.csv
/usr/bin/time -v -o big.time "$dv" judge "$sc" big.csv --out big --quiet >big.out 2>big.err
code=$?
echo "10^6 rows: exit $code, peak $(peak big.time) MB: $(cat big.err)"
check '[ $code -eq 2 ]' "10^6 rows: exit status $code, not 2"
check '[ "$(wc -l <big.err)" -eq 1 ] && grep -q "^diskval judge: big.csv:[0-9]*: more than [0-9]* rows: .*memory_budget = 1 GiB" big.err' \
  "10^6 rows: not one line naming the budget: $(head -3 big.err)"
check '[ "$(peak big.time)" -lt 400 ]' "10^6 rows: peak $(peak big.time) MB"
check '[ ! -e big/short_circle/report.json ]' "10^6 rows: a report written"
gen 300000 3 >long.csv
/usr/bin/time -v -o long.time "$dv" judge "$sc" long.csv --out long --quiet >long.out 2>long.err
code=$?
echo "3 x 10^5 rows over 3 s: exit $code, peak $(peak long.time) MB"
check '[ $code -le 1 ]' "3 x 10^5 rows over 3 s: exit status $code: $(head -1 long.err)"
check '[ "$(peak long.time)" -lt 250 ]' "3 x 10^5 rows over 3 s: peak $(peak long.time) MB: rows past the duration read"
exit $fail
