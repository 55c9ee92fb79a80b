#!/usr/bin/env bash
# check_judge_python.sh DISKVAL TO_POSE SCENARIO README: the numpy snippet of
# README "Judge your own engine" writes a pose CSV that judge accepts: MuJoCo's
# run of SCENARIO in the pose form (TO_POSE) read into arrays, written again by
# the snippet's write_pose_csv, judged: exit 0. Skipped without python3 and numpy.
set -u
. "$(dirname "$0")/check_lib.sh"
dv=${1:?usage: check_judge_python.sh DISKVAL TO_POSE SCENARIO README}
to_pose=${2:?usage}
sc=${3:?usage}
readme=${4:?usage}
python3 -c 'import numpy' 2>/dev/null || { echo "SKIP: python3 with numpy not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
sed -n '/^## Judge your own engine/,/^## /p' "$readme" | sed -n '/^```python$/,/^```$/p' | sed '1d;$d' >snippet.py
check '[ -s snippet.py ]' "no python snippet in the README's section"
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
