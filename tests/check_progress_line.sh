#!/usr/bin/env bash
# check_progress_line.sh DISKVAL SCENARIO: the progress line of long runs
# (docs/commands.md, "Progress line").
#  - under a pseudo-terminal (script(1)) simulate, compare, verify, suite,
#    sweep and map draw it (\r, the engine, "t T/D s", "left"; tasks "scenario k/n"),
#    clear it at the end, and the suite's task processes draw nothing;
#  - with stderr in a file, or with --quiet, there is no line;
#  - what the commands write (CSV, JSON, reports, stdout) is byte-identical
#    with and without the terminal, apart from the timing fields;
#  - a run that will take longer than a minute says so once, terminal or not,
#    and --quiet hides that too; verify's levels too; best's choices;
#  - every line says what runs and the time left: a phase with its count
#    ("settings probe 3/8 (mujoco ...)", "verification level 2/4", "attribution
#    9/12", a pool's "comparison run 2/6") and/or the run's role ("reference",
#    "nudged references", "engine run"), 1 <= k <= n and n the same on every
#    line of one phase (its name and engine); compare --jobs draws one line,
#    its processes' runs counted by the parent (no line is two run together).
# SCENARIO is a 1 s steady circle (tests/data/short_circle.ini), run for 3 s:
# MuJoCo takes 0.9 s of wall time and ODE 1.2 s there (measured with
# `time diskval simulate ... --set scenario.duration=3`), past the line's
# 0.25 s delay with room for a machine 3x faster.
set -u
export LC_ALL=C
dv=${1:?usage: check_progress_line.sh DISKVAL SCENARIO}
sc=${2:?usage: check_progress_line.sh DISKVAL SCENARIO}
command -v script >/dev/null || { echo "SKIP: script (bsdutils) not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
fail=0
long=(--set scenario.duration=3)
# compare and suite run MuJoCo and ODE alone: every line and output checked is theirs or the
# references' (the default engines, as before, took 70-110 s of the test for nothing more)
two=(--engines mujoco,ode)

# well_formed LOG WHAT: every line drawn in LOG names a phase with k/n, 1 <= k <= n and
# n constant within a phase (its name and the engine its subject starts with,
# while k rises),
# or a role; and says the time left
phases='settings probe|verification level|attribution|comparison run|scenario|reference point|point|cell|pair|first probe of each choice|search of choice'
roles='reference|nudged references|engine run'
well_formed() {
  local bad
  bad=$(tr '\r' '\n' <"$1" | grep -av '^ *$' | grep -av '^diskval ' | awk -v ph="$phases" -v ro="$roles" '
    function fail(why) { print why ": " $0; exit }
    {
      line = $0
      if (line !~ "^((" ph ")( [0-9]+/[0-9]+)?|(" ro ")  )") fail("names no phase nor role")
      if (line !~ /([0-9hms]+ left|estimating the time left)/) fail("no time left")
      rest = line
      while (match(rest, "(" ph ") [0-9]+/[0-9]+( [(][^ ),]*)?")) {
        item = substr(rest, RSTART, RLENGTH)
        rest = substr(rest, RSTART + RLENGTH)
        split(item, w, " [(]")
        key = w[1]; sub(/ [0-9]+\/[0-9]+$/, "", key); key = key "|" w[2]
        kn = w[1]; sub(/.* /, "", kn); split(kn, q, "/")
        if (q[1] + 0 < 1 || q[1] + 0 > q[2] + 0) fail("k outside 1..n")
        if ((key in n) && q[1] + 0 > k[key] && n[key] != q[2]) fail("n changed within " key)
        n[key] = q[2]; k[key] = q[1] + 0 # k not rising: the phase again (a second pool, another scene)
      }
    }')
  if [ -n "$bad" ]; then
    echo "FAIL: $2: a progress line $bad"
    fail=1
  fi
}

# on_tty LOG CMD...: run CMD with stderr on a pseudo-terminal (stdout as CMD redirects it)
on_tty() {
  local log=$1
  shift
  script -qec "$*" /dev/null >"$log" </dev/null
}
# has_line LOG REGEX WHAT: LOG holds a progress line matching REGEX, cleared after the last one
has_line() {
  if ! grep -aEq $'\r'"$2" "$1"; then
    echo "FAIL: $3: no progress line /$2/ on the terminal: $(tr '\r' '|' <"$1" | head -c 300)"
    fail=1
  elif ! tr '\r' '\n' <"$1" | awk -v re="$2" '$0 ~ re { seen = 1; next } seen && /^ +$/ { seen = 0 }
      END { exit seen }'; then
    echo "FAIL: $3: the last progress line was not cleared"
    fail=1
  fi
}
# no_line FILE WHAT: no progress line (no \r, no "left") in FILE
no_line() {
  if grep -aq $'\r\|left' "$1"; then
    echo "FAIL: $2: progress output: $(tr '\r' '|' <"$1" | head -c 300)"
    fail=1
  fi
}
# untimed FILE: FILE without the JSON's timing fields ("wall_s", "wall_per_sim_s", ...)
untimed() { grep -v '"[a-z_]*wall[a-z_]*":' "$1"; }
# same A B WHAT: files identical, the timing fields aside
same() {
  if ! cmp -s <(untimed "$1") <(untimed "$2"); then
    echo "FAIL: $3: $1 and $2 differ"
    diff <(untimed "$1") <(untimed "$2") | head -4
    fail=1
  fi
}

# simulate: the line on a terminal; none in a file or with --quiet; the same CSV and metadata
on_tty tty.log "'$dv' simulate '$sc' --engine mujoco ${long[*]} --out tty.csv"
has_line tty.log 'engine run  short_circle mujoco  t [0-9.]+/3 s  [0-9]+s left' "simulate"
"$dv" simulate "$sc" --engine mujoco "${long[@]}" --out file.csv 2>file.err
no_line file.err "simulate, stderr in a file"
same tty.csv file.csv "simulate CSV"
same tty.csv.json file.csv.json "simulate metadata"
on_tty quiet.log "'$dv' simulate '$sc' --engine mujoco ${long[*]} --out quiet.csv --quiet"
no_line quiet.log "simulate --quiet on a terminal"
# the CSV on stdout, stdout piped: the line still goes to the terminal, the CSV is the same
on_tty pipe.log "'$dv' simulate '$sc' --engine mujoco ${long[*]} | cat > piped.csv"
has_line pipe.log 'engine run  short_circle mujoco  t ' "simulate | cat"
same piped.csv file.csv "simulate CSV through a pipe"

well_formed tty.log "simulate"

# compare: a line for each run, its role named (in this process: --jobs 1); with
# --jobs its processes' runs counted by this one; the same report and stdout
on_tty cmp.log "'$dv' compare '$sc' ${two[*]} ${long[*]} --jobs 1 --out tty > tty.out"
has_line cmp.log 'engine run  short_circle ode  t [0-9.]+/3 s' "compare"
has_line cmp.log 'settings probe [0-9]+/[0-9]+ [(]ode' "compare, ode's settings probes"
well_formed cmp.log "compare"
on_tty cmpj.log "'$dv' compare '$sc' ${two[*]} --jobs 2 --out ttyj > /dev/null"
has_line cmpj.log 'comparison run 3/3  [0-9]+s left  [(]' "compare --jobs 2"
well_formed cmpj.log "compare --jobs 2"
"$dv" compare "$sc" "${two[@]}" "${long[@]}" --out file >file.out 2>cmp.err
no_line cmp.err "compare, stderr in a file"
sed -e 's|^report: file/|report: tty/|' -e 's|^page: file/|page: tty/|' file.out | cmp -s - tty.out || { echo "FAIL: compare stdout differs"; fail=1; }
for f in reduced.csv mujoco.csv ode.csv report.json; do
  same "tty/short_circle/$f" "file/short_circle/$f" "compare $f"
done

# verify: runs in this process; the same table (3 s: its longest run of 1 s
# took about the line's 0.25 s delay)
on_tty ver.log "'$dv' verify '$sc' --engines mujoco ${long[*]} > tty.ver"
has_line ver.log 'verification level 4/4 [(]mujoco dt [0-9.e-]+ s[)]: engine run  short_circle mujoco  t ' \
  "verify, its levels"
well_formed ver.log "verify"
"$dv" verify "$sc" --engines mujoco "${long[@]}" >file.ver 2>ver.err
no_line ver.err "verify, stderr in a file"
same tty.ver file.ver "verify stdout"

# attribute: its runs counted (the split's, then each knob's: about 4 s at 1 s)
on_tty att.log "'$dv' attribute '$sc' --engine mujoco > /dev/null"
has_line att.log 'attribution [0-9]+/[0-9]+ [(]mujoco,? [a-z]' "attribute"
well_formed att.log "attribute"

# best: its choices counted, their first probes then each one's search (ODE's two
# steppers at 1 s: about 3 s)
on_tty best.log "'$dv' best '$sc' --engine ode --theta-tol 1e-3 > /dev/null"
has_line best.log 'first probe of each choice [0-9]+/2 [(]ode [a-z]+ [0-9.e-]+ s[)]: engine run  ' "best"
well_formed best.log "best"

# suite: counted by the parent; the tasks' own processes draw nothing
mkdir s
sed 's/^name = .*/name = one/' "$sc" >s/one.ini
sed 's/^name = .*/name = two/' "$sc" >s/two.ini
on_tty suite.log "'$dv' suite s ${two[*]} --out stty --jobs 2 > stty.out"
has_line suite.log 'scenario 2/2  [0-9]+s left  [(]' "suite"
well_formed suite.log "suite"
if grep -aq '  t [0-9.]*/' suite.log; then
  echo "FAIL: suite: a task's process drew its run's line"
  fail=1
fi
"$dv" suite s "${two[@]}" --out sfile --jobs 2 >sfile.out 2>suite.err
no_line suite.err "suite, stderr in a file"
sed 's|sfile|stty|' sfile.out | cmp -s - stty.out || { echo "FAIL: suite stdout differs"; fail=1; }
same stty/summary.json sfile/summary.json "suite summary.json"
on_tty squiet.log "'$dv' suite s ${two[*]} --out squiet --jobs 2 --quiet > /dev/null"
no_line squiet.log "suite --quiet on a terminal"

# map: cells counted
on_tty map.log "'$dv' map --c 0.1,0.2 --spin 20,30 --duration 3 --engines mujoco --out mp --jobs 2 > /dev/null"
has_line map.log 'cell 4/4  ' "map"
well_formed map.log "map"

# sweep: points counted
on_tty sweep.log "'$dv' sweep '$sc' --engine mujoco --vary timestep=1e-3,5e-4 --out sw --jobs 2 > /dev/null"
has_line sweep.log 'point 2/2  ' "sweep"
well_formed sweep.log "sweep"

# the warning: ODE at a 1e-6 s step costs about 1 s of wall time per simulated
# second here, so 2000 s will take half an hour (a 30x faster machine still over a
# minute); simulate says so before its first sample, from a probe, in a file too
over=(--set scenario.duration=2000 --set engines.ode.timestep=1e-6)
# until_warned ERR CMD...: CMD runs until ERR holds the warning (measured 0.16-0.2 s
# from the start on 2 busy cores), 60 s at most, then is ended: a busy machine
# delays the warning, it does not fail the check
until_warned() {
  local err=$1 pid i
  shift
  "$@" >/dev/null 2>"$err" &
  pid=$!
  for i in $(seq 600); do
    grep -q 'will take about' "$err" && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  sleep 0.1 # its last line, written as it ends
}
until_warned warn.err "$dv" simulate "$sc" --engine ode "${over[@]}" --out warn.csv
if [ "$(grep -c 'diskval simulate: short_circle: ode to t = 2000 s will take about [0-9hm]*s* ' warn.err)" -ne 1 ]; then
  echo "FAIL: no single long-run warning in a file: $(cat warn.err)"
  fail=1
fi
# (3 s, 15x the warning's time: a busy machine makes this check weaker, never false)
timeout 3 "$dv" simulate "$sc" --engine ode "${over[@]}" --out warnq.csv --quiet 2>warnq.err
[ -s warnq.err ] && { echo "FAIL: --quiet still warns: $(cat warnq.err)"; fail=1; }

# before a comparison, once for all its runs (the ODE run then says nothing more)
until_warned warnc.err "$dv" compare "$sc" --engines ode "${over[@]}" --out warnc
if [ "$(grep -c 'diskval compare: short_circle: the comparison to t = 2000 s (4 runs) will take about' \
  warnc.err)" -ne 1 ] || [ "$(wc -l <warnc.err)" -ne 1 ]; then
  echo "FAIL: no single warning before a long comparison: $(cat warnc.err)"
  fail=1
fi

# before verify's levels, once for them all (16 runs, each level's step halved)
until_warned warnv.err "$dv" verify "$sc" --engines ode "${over[@]}"
if [ "$(grep -c 'diskval verify: short_circle: the verification to t = 2000 s (4 levels x 1 engine, 16 runs) will take about' \
  warnv.err)" -ne 1 ] || [ "$(wc -l <warnv.err)" -ne 1 ]; then
  echo "FAIL: no single warning before a long verification: $(cat warnv.err)"
  fail=1
fi
timeout 4 "$dv" verify "$sc" --engines ode "${over[@]}" --quiet >/dev/null 2>warnvq.err
[ -s warnvq.err ] && { echo "FAIL: verify --quiet still warns: $(cat warnvq.err)"; fail=1; }

[ $fail -eq 0 ] && echo "progress: on a terminal only, cleared, quiet on request, outputs unchanged"
exit $fail
