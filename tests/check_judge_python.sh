#!/usr/bin/env bash
# check_judge_python.sh DISKVAL TO_POSE SCENARIO JUDGE_DOC: the numpy snippet of
# docs/judge.md (JUDGE_DOC) writes a pose CSV that judge accepts: MuJoCo's
# run of SCENARIO in the pose form (TO_POSE) read into arrays, written again by
# the snippet's write_pose_csv, judged: exit 0. Skipped without python3 and numpy.
set -u
. "$(dirname "$0")/check_lib.sh"
dv=${1:?usage: check_judge_python.sh DISKVAL TO_POSE SCENARIO JUDGE_DOC}
to_pose=${2:?usage}
sc=${3:?usage}
doc=${4:?usage}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
sed -n '/^```python$/,/^```$/p' "$doc" | sed '1d;$d' >snippet.py
[ -s snippet.py ] || { echo "FAIL: no python snippet in $doc"; exit 1; }
python3 -c 'import numpy' 2>/dev/null || { echo "SKIP: python3 with numpy not installed"; exit 77; }
"$dv" simulate "$sc" --engine mujoco --out run.csv --quiet
"$to_pose" 0.1 0 <run.csv >pose.csv
cat >run.py <<'PY'
import numpy as np
exec(open("snippet.py").read())
a = np.loadtxt("pose.csv", delimiter=",", skiprows=1)
write_pose_csv("from_python.csv", a[:, 0], a[:, 1:4], a[:, 4:8], a[:, 8:11], a[:, 11:14])
PY
python3 run.py
check '[ $? -eq 0 ]' "the snippet failed"
"$dv" judge "$sc" from_python.csv --out out --quiet
code=$?
check '[ $code -eq 0 ]' "judge of the snippet's file: exit status $code"
exit $fail
