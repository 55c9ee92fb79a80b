#!/usr/bin/env bash
# check_adapter_faults.sh DISKVAL JUDGE_TO_POSE SCENARIO ADAPTERS: an engine
# outside the build (docs/adapters.md) is judged like a linked one, and every
# way an adapter can misbehave is a failed run with its reason, never a pass,
# a hang or a crash of diskval. The test adapter (tests/adapters/replay, POSIX
# sh: no Node needed) replays the matched reference of SCENARIO made 2 mm
# thick, its centre moved 3e-8 m (so it is judged, not "identical"):
#   - it passes compare, next to a linked engine, exit 0;
#   - crash, hang (timeout 2 s), garbage, a short row, a long one, NaN, an early exit, a
#     row at the wrong time, an "error" line, a quaternion off the unit sphere,
#     counts that are not whole, no "ready", silence at the start (a CR LF
#     line end is no fault: it passes), rows that disagree with themselves
#     (velocities 0 or 1.2 times the pose's steps, one step a row or one step
#     too many, a start 1.2 times the scene's rates, its centre 1.1e-7 m off
#     where 1e-7 is allowed; 0.9e-7 passes): each FAILs with its own words, exit 1,
#     within 20 s, the report written;
#   - a manifest that cannot be read, or an adapter whose command is missing,
#     does not stop diskval: `engines` says why, naming the line; a run of it
#     fails with the reason; a manifest that is a FIFO with no writer reads
#     as empty after 2 s, one that is /dev/zero is refused at its size cap
#     (no command waits on them, `simulate --engine reduced` neither);
#   - a run 5 cm off its path fails, its cause searched over the adapter's
#     knobs (none removes it), or with --cause none not searched;
#   - every setting reaches the adapter as given (engines --scene);
#   - no adapter runs unless named: a compare without --engines starts none.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1
to_pose=$2
scenario=$3
adapters=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

awk '/^\[disk\]/{print; print "thickness = 0.002"; next} {print}' "$scenario" >"$work/thick.ini"
"$diskval" simulate "$work/thick.ini" --engine matched --out "$work/ref.csv" --quiet ||
  { echo "FAIL: the matched reference did not run"; exit 1; }
"$to_pose" 0.1 0.001 <"$work/ref.csv" >"$work/pose.csv"
export DISKVAL_ADAPTERS=$adapters DV_REPLAY_POSE=$work/pose.csv
# the hangs sleep 67.PID s: this run's children, told apart from another checkout's tests
export DV_REPLAY_SLEEP=67.$$

run() { # run NAME [FAULT]: compare with the replay; sets code, out
  DV_REPLAY_FAULT=${2:-} timeout -k 2 20 "$diskval" compare "$work/thick.ini" --engines "$1" \
    --out "$work/out" --quiet >"$work/stdout" 2>&1
  code=$?
  out=$(cat "$work/stdout")
}

run replay,ode
check '[ $code -eq 0 ] && grep -q "replay .*pass" "$work/stdout" && grep -q "ode .*pass" "$work/stdout"' \
  "the replayed reference and ODE pass: exit $code: $out"
check 'grep -q "\"replay\"" "$work/out/short_circle/report.json"' "report.json names the adapter"
run replay crlf
check '[ $code -eq 0 ] && grep -q "replay .*pass" "$work/stdout"' "lines ending in CR LF: exit $code: $out"

while IFS='|' read -r fault words; do
  run replay "$fault"
  check '[ $code -eq 1 ] && grep -q "replay .*FAIL" "$work/stdout" && grep -q -e "$words" "$work/stdout"' \
    "$fault: exit $code, want 1, FAIL and '$words': $out"
  check '[ -s "$work/out/short_circle/report.md" ]' "$fault: no report written"
done <<'FAULTS'
crash|stopped answering: exited with status 3
hang|no answer within 2 s
garbage|not 16 numbers: field 1 is not a number
columns|not 16 numbers
extra|not 16 numbers: more than 16 fields
nan|replay: a non-finite state
early|stopped answering: exited with status 0
time|the row is at
error|replay: error the solver failed
quat|the quaternion's norm is
counts|not whole counts
noready|expected 'ready', got: hello
hangstart|while it built the model: no answer within 2 s
bgchild|stopped answering: exited with status 0
stillvel|its rows disagree: .* the trapezoid
fastvel|its rows disagree: .* the trapezoid
stillcentre|its rows disagree: the centre's . step to t = .* misses the trapezoid of its velocity
onestep|its rows disagree: 1 steps at t = 0.1 s, where the step
extrastep|its rows disagree: 101 steps at t = 0.1 s, where the step 0.001 s makes 100
FAULTS
# the start within 1e-6 of the state sent (x over the radius: 1e-7 m here) passes, past it fails
DV_REPLAY_NUDGE=0.9e-7 run replay
check '[ $code -eq 0 ]' "the centre 0.9e-7 m off from the start: exit $code, want 0: $out"
DV_REPLAY_NUDGE=1.1e-7 run replay
check '[ $code -eq 1 ] && grep -q "its state at t = 0 is not the one sent: x = 1.1e-07" "$work/stdout"' \
  "the centre 1.1e-7 m off from the start: exit $code, want 1, x named: $out"
# a start that is not the scene's: every velocity 1.2 times the pose's from t = 0
DV_REPLAY_AT=0 run replay fastvel
check '[ $code -eq 1 ] && grep -q "replay .*FAIL" "$work/stdout" && grep -q "its state at t = 0 is not the one sent: phi_dot" "$work/stdout"' \
  "fastvel from t = 0: exit $code, want 1 and the start named: $out"
for _ in 1 2 3 4 5 6 7 8 9 10; do pgrep -f "sleep $DV_REPLAY_SLEEP" >/dev/null || break; sleep 0.2; done # SIGKILL lands
check '! pgrep -f "sleep $DV_REPLAY_SLEEP" >/dev/null' "an adapter's own children outlived it: $(pgrep -af "sleep $DV_REPLAY_SLEEP")"

# a run that exceeds its limits: its cause searched over the adapter's knobs, or not (--cause none)
run replay offset
check '[ $code -eq 1 ] && grep -q "path_max_err = .*; cause: none of the knobs removes it (timestep, friction tried)" "$work/stdout"' \
  "offset: the knobs tried, none the cause: $out"
DV_REPLAY_FAULT=offset "$diskval" compare "$work/thick.ini" --engines replay --cause none \
  --out "$work/out" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 1 ] && grep -q "path_max_err = .*; cause: not searched (--cause none)" "$work/stdout"' \
  "offset, --cause none: $(cat "$work/stdout")"

# every setting reaches the adapter, as given: --set and the scene's body
"$diskval" engines --scene "$work/thick.ini" replay --set engines.replay.timestep=0.002 \
  --set engines.replay.half_thickness=0.003 --set engines.replay.friction=0.7 >"$work/scene"
check 'grep -qx "set timestep 0.002" "$work/scene" && grep -qx "half_thickness 0.003" "$work/scene" &&
  grep -qx "friction 0.7" "$work/scene" && grep -qx "set mode replay" "$work/scene" &&
  [ "$(tail -n 1 "$work/scene")" = start ]' "the scene sent: $(cat "$work/scene")"

# a broken manifest and a missing program: listed with why, diskval still runs
mkdir -p "$work/more/broken" "$work/more/absent" "$work/more/nochoices" "$work/more/intstep" \
  "$work/more/outside"
printf '[adapter]\nname = broken\ncolour = blue\n' >"$work/more/broken/manifest.ini"
sed 's/^name = replay/name = nochoices/; /^choices = replay$/d; /^default = replay$/d' \
  "$adapters/replay/manifest.ini" \
  >"$work/more/nochoices/manifest.ini"
sed 's/^name = replay/name = intstep/; /^\[setting.timestep\]/,/^type/ s/^type = real/type = int/' \
  "$adapters/replay/manifest.ini" >"$work/more/intstep/manifest.ini"
sed 's/^name = replay/name = outside/; /^\[setting.timestep\]/,/^unit/ s/^default = scene/default = 5/' \
  "$adapters/replay/manifest.ini" >"$work/more/outside/manifest.ini"
sed 's/^name = replay/name = absent/; s/^command = .*/command = no-such-program-here x/' \
  "$adapters/replay/manifest.ini" >"$work/more/absent/manifest.ini"
# a name of DV_ADAPTER_NAME - 1 = 31 characters fits; of 32 it is refused, never cut
n31=$(printf 'n%.0s' $(seq 31)) n32=$(printf 'n%.0s' $(seq 32))
mkdir -p "$work/more/long31" "$work/more/long32"
sed "s/^name = replay/name = $n31/" "$adapters/replay/manifest.ini" >"$work/more/long31/manifest.ini"
sed "s/^name = replay/name = $n32/" "$adapters/replay/manifest.ini" >"$work/more/long32/manifest.ini"
export DISKVAL_ADAPTERS=$adapters:$work/more
"$diskval" engines >"$work/engines" 2>&1
code=$?
check '[ $code -eq 0 ] && grep -q "broken/manifest.ini:3: colour: unknown key" "$work/engines"' \
  "engines names the bad manifest's line: exit $code: $(grep -i broken "$work/engines")"
check 'grep -q "nochoices/manifest.ini: mode: a choice with no choices = line" "$work/engines" &&
  grep -q "intstep/manifest.ini: timestep: a role.s setting must be of type real" "$work/engines" &&
  grep -q "outside/manifest.ini: timestep: the default is outside its range" "$work/engines"' \
  "bad settings in manifests named: $(grep manifest.ini "$work/engines")"
check 'grep -q "^$n31 " "$work/engines" && grep -q "long32/manifest.ini:4: name: too long: $n32\$" "$work/engines" &&
  ! grep -q "^$n32" "$work/engines"' "names of 31 and 32 characters: $(grep -e long3 -e nnnn "$work/engines")"
"$diskval" analyze "$work/thick.ini" >/dev/null 2>&1
check '[ $? -eq 0 ]' "analyze with bad manifests around: exit not 0"
check 'grep -q "^absent .*not available: no-such-program-here is not on PATH" "$work/engines"' \
  "engines says the absent adapter's program is missing: $(grep absent "$work/engines")"
run absent
check '[ $code -eq 1 ] && grep -q "absent is not available" "$work/stdout"' \
  "a run of an unavailable adapter fails with why: exit $code: $out"

# a manifest no writer ever fills, or one that never ends: named, never waited on
mkdir -p "$work/pipe/fifo" "$work/pipe/zero"
mkfifo "$work/pipe/fifo/manifest.ini"
ln -s /dev/zero "$work/pipe/zero/manifest.ini"
DISKVAL_ADAPTERS=$work/pipe timeout -k 2 20 "$diskval" engines >"$work/engines" 2>&1
code=$?
check '[ $code -eq 0 ] && grep -q "fifo/manifest.ini: a pipe with nothing to read" "$work/engines" &&
  grep -q "zero/manifest.ini: more than the 64 KiB a manifest may have" "$work/engines"' \
  "a FIFO and /dev/zero as manifests: exit $code: $(grep -e fifo/ -e zero/ "$work/engines")"
DISKVAL_ADAPTERS=$work/pipe timeout -k 2 20 "$diskval" simulate "$work/thick.ini" --engine reduced \
  --out "$work/reduced.csv" --quiet >"$work/stdout" 2>&1
code=$?
check '[ $code -eq 0 ]' "simulate --engine reduced beside a FIFO manifest: exit $code: $(cat "$work/stdout")"

# a machine without Node: the shipped adapters are listed as not available, the rest runs
PATH=/nonexistent "$(command -v env)" "$diskval" engines >"$work/engines" 2>&1
code=$?
check '[ $code -eq 0 ] && grep -q "^ode " "$work/engines" &&
  { ! grep -q "^mujoco3 " "$work/engines" || grep -q "^mujoco3 .*not available" "$work/engines"; }' \
  "engines without Node on PATH: exit $code: $(grep "^mujoco3" "$work/engines")"

# nothing outside the build runs unless named
DV_REPLAY_MARK=$work/started "$diskval" compare "$work/thick.ini" --out "$work/o2" \
  --set scenario.duration=0.2 \
  --quiet >/dev/null 2>&1
check '[ ! -e "$work/started" ] && ! grep -q replay "$work/o2/short_circle/report.json"' \
  "a compare with the default engines started the adapter (probe or run)"
DV_REPLAY_MARK=$work/started "$diskval" compare "$work/thick.ini" --engines replay \
  --out "$work/o3" --quiet >/dev/null 2>&1
check '[ -e "$work/started" ]' "a compare of the adapter did not start it (the mark's own check)"
exit $fail
