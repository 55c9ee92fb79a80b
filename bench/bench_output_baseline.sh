#!/usr/bin/env bash
# bench_output_baseline.sh DISKVAL PLAIN_GSL_DISK [PAIRS]: `diskval simulate
# --engine reduced` at its defaults against plain_gsl_disk (GSL's rk8pd driver
# stepping onto every output) at equal theta accuracy, for a uniform disk
# (r 0.1 m) from theta 1 rad spinning at -12 rad/s: 2000 s with output every
# 1 s, and 20 s every 1 ms. Both write the trajectory CSV to a file.
#
# Accuracy: max |theta - theta_ref| over the outputs, theta_ref from
# plain_gsl_disk at eps 5e-14; the floor is how far that reference moves at
# eps 2e-14 (rounding: a 1-ulp change of theta(0) moves theta(2000 s) by
# ~5e-10). The plain driver's eps is interpolated (log-log, over a ladder of
# eps) to diskval's error, or to the floor where diskval is below it. Then
# PAIRS (default 7) paired runs, alternating which goes first; prints the
# median wall times and their ratio (diskval / plain). The 2000 s case runs
# twice: at the defaults (the reference folds the periodic motion, docs/reference.md
# "Periodic motion") and with fold = off (stepping to the end).
set -u
diskval=$1 plain=$2 pairs=${3:-7}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk "BEGIN{print $t1 - $t0}"; }
median() { sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# max |theta| difference of two trajectory CSVs, rows matched in order
theta_err() {
  awk -F, 'FNR == 1 { next } NR == FNR { a[FNR] = $2; n = FNR; next }
    { d = $2 - a[FNR]; if (d < 0) d = -d; if (d > m) m = d; k = FNR }
    END { if (k != n) print "inf"; else printf "%.4g\n", m }' "$1" "$2"
}

bench_case() {
  local duration=$1 dt=$2 target=$3 scene="$work/spin.ini" extra=("${@:4}")
  printf '[scenario]\nname = spin\nduration = %s\noutput_dt = %s\n[disk]\nradius = 0.1\nmass = 1\ngravity = 9.81\n[initial]\ntheta = 1.0\npsi_dot = -12\n' \
    "$duration" "$dt" >"$scene"
  "$plain" "$duration" "$dt" 5e-14 >"$work/ref.csv"
  "$plain" "$duration" "$dt" 2e-14 >"$work/ref2.csv"
  "$diskval" simulate "$scene" --engine reduced "${extra[@]}" --out "$work/dv.csv" 2>/dev/null
  local floor err_dv goal
  floor=$(theta_err "$work/ref.csv" "$work/ref2.csv")
  err_dv=$(theta_err "$work/ref.csv" "$work/dv.csv")
  goal=$(awk "BEGIN{print ($err_dv > $floor) ? $err_dv : $floor}")
  # the plain driver's error over eps 1e-8 ... 3e-14, four steps a decade
  : >"$work/ladder"
  for k in $(seq 32 54); do
    local eps
    eps=$(awk "BEGIN{printf \"%.3g\", 10 ^ (-$k / 4)}")
    "$plain" "$duration" "$dt" "$eps" >"$work/p.csv"
    echo "$eps $(theta_err "$work/ref.csv" "$work/p.csv")" >>"$work/ladder"
  done
  local eps_eq
  eps_eq=$(awk -v g="$goal" '{ e[NR] = $1; r[NR] = $2 }
    END { for (i = 2; i <= NR; i++) if (r[i] <= g) {
            if (r[i - 1] <= r[i] || r[i] <= 0) { printf "%.3g", e[i]; exit }
            f = log(g / r[i]) / log(r[i - 1] / r[i]); if (f > 1) f = 1
            printf "%.3g", e[i] * exp(f * log(e[i - 1] / e[i])); exit }
          printf "%.3g", e[NR] }' "$work/ladder")
  "$plain" "$duration" "$dt" "$eps_eq" >"$work/p.csv"
  local err_plain
  err_plain=$(theta_err "$work/ref.csv" "$work/p.csv")
  run_plain() { "$plain" "$duration" "$dt" "$eps_eq" >"$work/p.csv"; }
  run_diskval() { "$diskval" simulate "$scene" --engine reduced "${extra[@]}" --out "$work/dv.csv"; }
  : >"$work/td" && : >"$work/tp"
  for ((i = 0; i < pairs; i++)); do
    if ((i % 2)); then
      seconds run_plain >>"$work/tp"
      seconds run_diskval >>"$work/td"
    else
      seconds run_diskval >>"$work/td"
      seconds run_plain >>"$work/tp"
    fi
  done
  local td tp
  td=$(median <"$work/td") tp=$(median <"$work/tp")
  printf "%s s, output every %s s%s: theta error diskval %s, plain GSL %s at eps %s (floor %s)\n" \
    "$duration" "$dt" "${extra[*]:+ (${extra[*]})}" "$err_dv" "$err_plain" "$eps_eq" "$floor"
  printf "  median of %d pairs: diskval %.3f s, plain GSL %.3f s, ratio %.2f (goal <= %s)\n" \
    "$pairs" "$td" "$tp" "$(awk "BEGIN{print $td / $tp}")" "$target"
}

# the start-up floor: `diskval --help` against the same plain run, so a ratio
# can be read with the loading of diskval's libraries taken out
startup_floor() {
  local i
  : >"$work/th" && : >"$work/tp"
  for ((i = 0; i < pairs; i++)); do
    seconds "$diskval" --help >>"$work/th"
    seconds "$plain" 20 0.001 5e-9 >>"$work/tp"
  done
  printf "start-up: diskval --help %.3f s (median of %d), plain GSL 20 s every 1 ms %.3f s\n" \
    "$(median <"$work/th")" "$pairs" "$(median <"$work/tp")"
}

# the goals, start-up included: issue 37 (folded coarse output, 1 ms grid)
bench_case 2000 1 0.2
bench_case 2000 1 1.0 --set engines.reduced.fold=off
bench_case 20 0.001 0.5
startup_floor
