#!/bin/sh
# A test adapter (docs/adapters.md) in POSIX sh: it answers every "advance T"
# with the row of $DV_REPLAY_POSE (a pose-form CSV with velocities) at time T,
# its centre moved by $DV_REPLAY_NUDGE m (3e-8 unless set),
# and misbehaves as $DV_REPLAY_FAULT says, from $DV_REPLAY_AT s on: crash,
# hang, garbage, columns, extra, nan, early, time, error, quat, offset (the
# centre drifting off at 0.2 m/s, its velocity not saying so: a run that
# exceeds its path limit, its rows' own check passed), counts (steps 1.5),
# crlf (lines ending in CR LF, which must pass), lies whose rows disagree
# with themselves: stillvel (every velocity 0 while the pose moves), fastvel
# (every velocity 1.2 times the pose's: from DV_REPLAY_AT=0, a start off the
# scene's), stillcentre (the centre's vx, vy 0 while it rolls), onestep
# (steps 1 on every row), extrastep (one step more than
# the time makes), or at the start:
# noready, hangstart, bgchild (exits, a child of its own holding its output). $DV_REPLAY_MARK, when set, is created when a run starts.
if [ "$1" = --version ]; then echo "replay 1 (a test adapter)"; exit 0; fi
[ -n "${DV_REPLAY_MARK:-}" ] && : >"$DV_REPLAY_MARK" # a run started (not a version query)
dt=
while read -r key value rest; do
  [ "$key" = set ] && [ "$value" = timestep ] && dt=$rest
  [ "$key" = start ] && break
done
# a hang sleeps DV_REPLAY_SLEEP s (its own value: the test finds its children by it)
nap=${DV_REPLAY_SLEEP:-67}
case $DV_REPLAY_FAULT in
  noready) echo "hello"; exit 0 ;;
  hangstart) sleep "$nap" ;;
  bgchild) sleep "$nap" & exit 0 ;; # exits, its child holding the output open
esac
echo ready
# mawk reads its input in blocks unless interactive: a row must answer each line
case $(awk -W version 2>&1 | head -1) in mawk*) interactive="-W interactive" ;; esac
exec awk $interactive -v file="$DV_REPLAY_POSE" -v fault="$DV_REPLAY_FAULT" -v at="${DV_REPLAY_AT:-0.1}" -v nap="$nap" \
  -v dt="$dt" -v nudge="${DV_REPLAY_NUDGE:-3e-8}" '
BEGIN {
  FS = ","
  n = 0
  getline header < file
  while ((getline line < file) > 0) { split(line, f, ","); t[n] = f[1]; row[n] = line; n++ }
  FS = " "
}
$1 == "advance" {
  k = 0
  while (k < n && (t[k] - $2 > 1e-9 || $2 - t[k] > 1e-9)) k++
  if (k == n) { print "error no row at t = " $2; exit 1 }
  split(row[k], v, ","); v[2] = v[2] + nudge  # not the reference exactly: judged, not "identical"
  out = v[1]; for (i = 2; i <= 14; i++) out = out " " v[i]
  out = out " 1 " int($2 / dt + 0.5)
  if ($2 + 1e-12 >= at) {
    if (fault == "crash") exit 3
    if (fault == "hang") system("sleep " nap)
    if (fault == "garbage") out = "the solver says hello"
    if (fault == "columns") sub(/ [^ ]+$/, "", out)
    if (fault == "extra") out = out " 0"
    if (fault == "counts") out = out ".5"
    if (fault == "crlf") out = out "\r"
    if (fault == "offset") { split(out, v, " "); v[2] = v[2] + 0.2 * ($2 - at); out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "nan") { split(out, v, " "); v[2] = "nan"; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "early") exit 0
    if (fault == "time") { split(out, v, " "); v[1] = v[1] + 2 * dt; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "error") out = "error the solver failed at t = " $2
    if (fault == "stillvel") { split(out, v, " "); for (i = 9; i <= 14; i++) v[i] = 0; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "fastvel") { split(out, v, " "); for (i = 9; i <= 14; i++) v[i] *= 1.2; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "onestep") { split(out, v, " "); v[16] = 1; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "stillcentre") { split(out, v, " "); v[9] = 0; v[10] = 0; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "extrastep") { split(out, v, " "); v[16] += 1; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
    if (fault == "quat") { split(out, v, " "); v[5] = v[5] * 1.1; out = v[1]; for (i = 2; i <= 16; i++) out = out " " v[i] }
  }
  print out
  fflush()
}'
