#!/usr/bin/env bash
# check_compare_jobs.sh DISKVAL SCENARIO: compare --jobs 1 and --jobs 2 write the same
# report apart from the wall times (wall_* in the JSON, the wall column of the Markdown and of the page),
# a cause is searched (ODE at 40x its step fails), and every trajectory the pool's
# processes handed back is the one `diskval simulate` writes in one process.
# Cost: 0.6 s a compare on two busy cores (time diskval compare tests/data/short_circle.ini
# --engines ode,mujoco --set engines.ode.timestep=4e-4 --jobs 1).
set -u
d=$1 sc=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=("$sc" --engines ode,mujoco --set engines.ode.timestep=4e-4 --quiet)
"$d" compare "${args[@]}" --jobs 1 --out "$work/a" >/dev/null
"$d" compare "${args[@]}" --jobs 2 --out "$work/b" >/dev/null
untimed() {
  case "$1" in
    *.json) grep -vE '"(horizon_)?wall_(s|per_sim_s)"' "$1" ;;
    *.md) sed -E 's/\| [^|]* \|$/|/' "$1" ;;
    *.html) sed -E 's#<td class="n wall">[^<]*</td>##' "$1" ;;
    *) cat "$1" ;;
  esac
}
fail=0 n=0
while IFS= read -r f; do
  rel=${f#"$work/a/"}
  n=$((n + 1))
  if [ ! -f "$work/b/$rel" ]; then echo "FAIL: $rel only with --jobs 1"; fail=1; continue; fi
  if ! cmp -s <(untimed "$f") <(untimed "$work/b/$rel"); then
    echo "FAIL: $rel differs between --jobs 1 and --jobs 2"
    diff <(untimed "$f") <(untimed "$work/b/$rel") | head -5
    fail=1
  fi
done < <(find "$work/a" -type f | sort)
[ "$(find "$work/b" -type f | wc -l)" -eq "$n" ] || { echo "FAIL: --jobs 2 wrote other files"; fail=1; }
report=$work/b/short_circle
grep -q 'ode: theta\\_max\\_err = [0-9.e-]* rad \\> .*; cause: timestep' "$report/report.md" ||
  { echo "FAIL: no cause searched for ode"; fail=1; }
for e in ode mujoco reduced; do
  set_ode=(); [ "$e" = ode ] && set_ode=(--set engines.ode.timestep=4e-4)
  "$d" simulate "$sc" --engine "$e" "${set_ode[@]}" --out "$work/$e.csv" >/dev/null 2>&1
  cmp -s "$work/$e.csv" "$report/$e.csv" ||
    { echo "FAIL: $e.csv is not the trajectory simulate writes"; fail=1; }
done
[ $fail -eq 0 ] && echo "compare_jobs: $n files identical apart from timing; trajectories whole"
exit $fail
