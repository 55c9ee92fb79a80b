#!/usr/bin/env bash
# check_shadow_fall.sh DISKVAL: on a fall from near upright only the scene's
# sensitivity to an engine's early error excuses its error; what it does along
# the way is its own, and nothing it does ends its own judging (issue 48).
# The scene: a quarter's disk (r 12.13 mm, 5.67 g) released at theta 1.50 with
# psi_dot 10 rad/s falls to 0.50 rad and nutates, every 0.33 s. Here 0.8 s of it
# and ODE at its derived settings: its early error spreads the reference by
# under 1e-3 rad, while its own error grows to 0.048 rad by 0.8 s (its turns
# lead by 0.0012 s at the third, once the "timing horizon" that let it pass):
# it fails, judged over the whole window, the turning lag adding up. Planted
# wrong engines, the reference's own run altered: a theta offset 0.05 t^2 rad
# (theta_max_err), a period 5% longer after the first turn (turning_lag, its
# periods listed), a nutation 3% wider (theta_turning_err); and on a steady circle theta
# off by a constant, 0.97 and 1.03 of the limit, on either side of it. Measured with
# `diskval simulate` each engine, then `diskval judge`, report.json.
set -u
. "$(dirname "$0")/check_lib.sh"
export LC_ALL=C
dv=${1:?usage: check_shadow_fall.sh DISKVAL}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
cat >quarter.ini <<'INI'
[scenario]
name = quarter_fall
duration = 0.8
output_dt = 0.002
[disk]
radius = 0.01213
mass = 0.00567
[initial]
theta = 1.50
psi_dot = 10
INI

# keep_contact R: rows whose theta was altered, their centre x, y moved so that the
# contact point stays where the rows give it (the columns agree: docs/judge.md), to
# t..psi_dot (no energy: the altered rows have another)
keep_contact() {
  awk -F, -v r="$1" 'BEGIN { OFS = ","; CONVFMT = "%.17g" } NR == 1 { print; next }
    { c = r * cos($2); $5 = $7 - c * cos($3); $6 = $8 - c * sin($3); print }' | cut -d, -f1-11
}

# judge NAME FILE: diskval judge's stdout into NAME.out, its exit status
judge() { "$dv" judge quarter.ini "$2" --name "$1" --out out >"$1.out" 2>&1; }

"$dv" simulate quarter.ini --engine ode --out ode.csv --quiet 2>err; code=$?
check '[ $code -eq 0 ]' "simulate ode: $(cat err)"
judge e_ode ode.csv; code=$?
check '[ $code -eq 1 ] && grep -Eq "^    fails: (theta_max_err|theta_rms_err|turning_lag|phase_err|path_max_err) " e_ode.out' \
  "ode: exit $code, want 1 (its own error over the whole window): $(cat e_ode.out)"
rep=out/quarter_fall/report.json
check 'jq -e ".engines.e_ode | .pointwise_end >= .window_end - 1e-9 and .theta_max_err > 0.03 and .limits.theta_max_err.spread < 1e-3" $rep >/dev/null' \
  "ode: not judged over the whole window, or the spread excused its error: $(jq -c ".engines.e_ode | {pointwise_end, window_end, theta_max_err, l: .limits.theta_max_err}" $rep)"
check 'jq -r .engines.e_ode.decided_why $rep | grep -q "and the turning lag judge it all"' \
  "ode: decided_why does not say it is judged all over: $(jq -r .engines.e_ode.decided_why $rep)"

"$dv" simulate quarter.ini --engine reduced --out ref.csv --quiet 2>err; code=$?
check '[ $code -eq 0 ]' "simulate reduced: $(cat err)"
# the state form without the energy column (the altered rows have another energy)
awk -F, 'BEGIN { OFS = "," } NR == 1 { print; next }
  { $2 += 0.05 * $1 * $1; $9 += 0.1 * $1; print }' ref.csv | keep_contact 0.01213 >grow.csv
judge w_grow grow.csv; code=$?
check '[ $code -eq 1 ] && grep -q "quarter_fall: w_grow: theta_max_err = [0-9.e-]* rad > 0.01[0-9]* rad " w_grow.out' \
  "a growing theta offset: exit $code, want 1 on theta_max_err: $(cat w_grow.out)"

# a period 5% longer from t1 = 0.16 s: the reference sampled every 0.002 / 1.05 s,
# its times stretched by 1.05 after t1 and its rates slowed, lands on the 0.002 s grid
"$dv" simulate quarter.ini --engine reduced --set scenario.output_dt=0.0019047619047619048 \
  --set scenario.duration=0.77 --out fine.csv --quiet 2>err; code=$?
check '[ $code -eq 0 ]' "simulate reduced, finer: $(cat err)"
{
  head -1 ref.csv | cut -d, -f1-11
  awk -F, 'NR > 1 && $1 <= 0.16 + 1e-9' ref.csv | cut -d, -f1-11
  awk -F, 'BEGIN { OFS = ","; k = 1.05; t1 = 0.16 } NR > 1 && $1 > t1 + 1e-9 {
    $1 = sprintf("%.10g", t1 + k * ($1 - t1)); for (i = 9; i <= 11; i++) $i /= k; print }' fine.csv |
    cut -d, -f1-11
} >slow.csv
judge w_slow slow.csv; code=$?
check '[ $code -eq 1 ] && grep -q "quarter_fall: w_slow: turning_lag = [0-9.e-]* s > " w_slow.out && grep -q "quarter_fall: w_slow: nutation_period_err = [0-9.e-]* s > " w_slow.out' \
  "a period 5% long: exit $code, want 1 on turning_lag and nutation_period_err: $(cat w_slow.out)"
check '! grep -q "w_slow: theta_turning_err" w_slow.out' "a period 5% long fails on its turns: $(cat w_slow.out)"

awk -F, 'BEGIN { OFS = "," } NR == 1 { print; next }
  { if (NR == 2) s = $2; $2 = s + 1.03 * ($2 - s); $9 *= 1.03; print }' ref.csv | keep_contact 0.01213 >wide.csv
judge w_wide wide.csv; code=$?
check '[ $code -eq 1 ] && grep -q "quarter_fall: w_wide: theta_turning_err = [0-9.e-]* rad > 0.01[0-9]* rad " w_wide.out' \
  "a nutation 3% wide: exit $code, want 1 on theta_turning_err: $(cat w_wide.out)"

# an early error is the engine's own: theta off by a constant on a steady circle
# (tests/data/short_circle.ini, output_dt 0.01 s), eased in over its first 0.05 s, is held
# against the limit itself in the early window, whatever the spread it makes later (the
# nudge of 0.0103 rad spreads the reference by 0.01 rad at once): 0.97 of the limit
# agrees, 1.03 fails on theta_max_err (energy and invariants lifted: an offset theta is
# another energy)
circle=$here/data/short_circle.ini
"$dv" simulate "$circle" --engine reduced --out circle.csv --quiet 2>err
for k in 0.97 1.03; do
  awk -F, -v d="$(awk -v k=$k 'BEGIN { printf "%.17g", 0.01 * k }')" 'BEGIN { OFS = ","; T = 0.05 }
    NR == 1 { print; next }
    { u = $1 / T; if (u > 1) u = 1; $2 += d * u * u * (3 - 2 * u); $9 += d * 6 * u * (1 - u) / T; print }' \
    circle.csv | keep_contact 0.1 >"offset_$k.csv"
  "$dv" judge "$circle" "offset_$k.csv" --name "o_$k" --set tolerance.energy_drift=100 \
    --set tolerance.invariant_drift=100 --out out >"o_$k.out" 2>&1
  code=$?
  if [ $k = 0.97 ]; then
    check '[ $code -eq 0 ]' "theta 0.97 of the limit off: exit $code, want 0: $(cat o_$k.out)"
  else
    check '[ $code -eq 1 ] && grep -q "short_circle: o_$k: theta_max_err = 0.0103[0-9]* rad > " o_$k.out' \
      "theta 1.03 of the limit off: exit $code, want 1 on theta_max_err: $(cat o_$k.out)"
  fi
done
exit $fail
