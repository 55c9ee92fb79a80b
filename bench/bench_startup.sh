#!/usr/bin/env bash
# bench_startup.sh DISKVAL [RUNS]: what every diskval process pays before its work:
# `diskval --help` (no engine module, no MPI opened) against /bin/true, RUNS runs of
# each (default 41), alternating; prints the medians in ms and their difference (the
# start-up's own cost: the dynamic loader and the libraries every command links).
set -u
diskval=$1 runs=${2:-41}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ms() { local t0 t1; t0=$(date +%s%N); "$@" >/dev/null 2>&1; t1=$(date +%s%N); echo $(((t1 - t0) / 1000)); }
median() { sort -n | awk '{ v[NR] = $1 } END { printf "%.1f", (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) / 1000 }'; }
for ((i = 0; i < runs; i++)); do
  ms "$diskval" --help >>"$work/help"
  ms /bin/true >>"$work/true"
done
h=$(median <"$work/help") t=$(median <"$work/true")
printf "start-up: diskval --help %s ms, /bin/true %s ms (median of %d)\n" "$h" "$t" "$runs"
printf "  --help beyond /bin/true: %.1f ms (goal < 5 ms for --help)\n" "$(awk "BEGIN{print $h - $t}")"
