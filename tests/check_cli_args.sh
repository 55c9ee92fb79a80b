#!/usr/bin/env bash
# check_cli_args.sh DISKVAL SCENARIO_DIR: every command refuses bad arguments
# cleanly. Each case must exit 2, print exactly one line on stderr matching
# its regex, print nothing on stdout and write nothing in the working
# directory: strict numbers ("1e-3x", "2x", "nan", ""), unknown options,
# missing values, surplus arguments, unknown engines, an empty engine list,
# bad --vary, a --vary key given twice, an option of one value given twice,
# suite --stability with --verify, a map axis that does not increase.
set -u
export LC_ALL=C
dv=${1:?usage: check_cli_args.sh DISKVAL SCENARIO_DIR}
sc=${2:?usage: check_cli_args.sh DISKVAL SCENARIO_DIR}/falling.ini
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
fail=0

# expect REGEX ARGS...: exit 2, one stderr line matching REGEX, no stdout, no file
expect() {
  local regex=$1
  shift
  "$dv" "$@" >out.txt 2>err.txt
  local code=$? lines
  lines=$(wc -l <err.txt)
  if [ $code -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -Eq -e "$regex" err.txt || [ -s out.txt ] ||
    [ "$(ls -A | grep -cv '^\(out\|err\)\.txt$')" -ne 0 ]; then
    echo "FAIL: diskval $*: exit $code, stderr: $(cat err.txt), stdout: $(head -c 200 out.txt)"
    fail=1
  fi
  rm -rf ./* ./.[!.]* 2>/dev/null
}

expect "theta-tol: '1e-3x' is not a finite number" best "$sc" --engine mujoco --theta-tol 1e-3x
expect "theta-tol: 'nan' is not a finite number" best "$sc" --engine mujoco --theta-tol nan
expect "theta-tol: '' is not a finite number" best "$sc" --engine mujoco --theta-tol ''
expect "theta-tol: 'inf' is not a finite number" best "$sc" --engine mujoco --theta-tol inf
expect "jobs: '2x' is not a whole number" suite "$sc" --jobs 2x
expect "jobs: '1.5' is not a whole number" sweep "$sc" --engine ode --vary timestep=1e-4 --jobs 1.5
expect "jobs: '0' is not a whole number in \[1, 1024\]" suite "$sc" --jobs 0
expect "duration: 'nan' is not a finite number" map --duration nan
expect "duration: '5s' is not a finite number" map --duration 5s
expect "timestep: not a number: '1e-3x'" sweep "$sc" --engine mujoco --vary timestep=1e-3x
expect "bogus: unknown key" sweep "$sc" --engine mujoco --vary bogus=1,2
expect "integrator: .*rk5" sweep "$sc" --engine mujoco --vary integrator=rk5
expect "timestep: -1 is outside" sweep "$sc" --engine mujoco --vary timestep=-1
expect "engines.ode.timestep=1e-3: a mujoco sweep never runs ode" sweep "$sc" --engine mujoco \
  --vary engines.ode.timestep=1e-3
expect "^diskval verify: --engines: reduced is not a contact engine" verify "$sc" --engines mujoco,reduced
expect "engines.mujoco.timestep is varied twice" sweep "$sc" --engine mujoco --vary timestep=1e-3 \
  --vary timestep=2e-3
# an axis of the map's plots must increase: refused before any cell runs (the
# plot refused it after every cell had run and map.csv was written)
expect "^diskval map: --c 0.5..0.1:2: the values must increase \('0.1' after '0.5'\)" map \
  --c 0.5..0.1:2 --engines reduced --duration 0.1
expect "^diskval map: --spin 20..1:3: the values must increase" map --spin 20..1:3 --engines reduced \
  --duration 0.1
expect "^diskval map: --c 0.2,0.2: the values must increase" map --c 0.2,0.2 --engines reduced \
  --duration 0.1
expect "unexpected argument 'extra'" simulate "$sc" extra --engine reduced
expect "unexpected argument 'x.ini'" compare "$sc" x.ini
expect "unexpected argument 'extra'" analyze "$sc" extra
expect "unexpected argument 'extra'" attribute "$sc" extra --engine mujoco
expect "unexpected argument 'extra'" best "$sc" extra --engine mujoco --theta-tol 1e-3
expect "unexpected argument 'extra'" sweep "$sc" extra --engine mujoco --vary timestep=1e-3
expect "unexpected argument 'y'" map x y
expect "unexpected argument 'x'" engines x
expect "^diskval compare: --cause bogus: quick, full or none" compare "$sc" --cause bogus
expect "^diskval suite: --cause bogus: quick, full or none" suite "$sc" --cause bogus
expect "unknown option '--bogus'" simulate "$sc" --engine reduced --bogus
expect "jobs: '0' is not a whole number in \[1, 1024\]" compare "$sc" --jobs 0
expect "unknown option '--jobs'" simulate "$sc" --engine reduced --jobs 2
expect "--engine needs a value" simulate "$sc" --engine
expect "no scenario given" simulate --engine reduced
expect "no scenario given" suite
expect "unknown engine 'Mujoco' \(one of: .*mujoco" simulate "$sc" --engine Mujoco
# an engine list names the valid engines once, and nothing after them
for cmd in compare suite verify; do
  expect "^diskval $cmd: unknown engine 'Mujoco' \(one of: reduced, matched, mujoco, ode, bullet, dart, simbody[a-z0-9_, ]*\)\$" \
    $cmd "$sc" --engines ode,Mujoco
done
expect "^diskval map: unknown engine 'Mujoco' \(one of: reduced, matched, mujoco, ode, bullet, dart, simbody[a-z0-9_, ]*\)\$" map --engines Mujoco
# an engine named twice would be two results under one key in report.json
for cmd in compare suite verify; do
  expect "^diskval $cmd: engine 'ode' listed twice\$" $cmd "$sc" --engines ode,mujoco,ode
done
expect "^diskval map: engine 'mujoco' listed twice\$" map --engines mujoco,mujoco
# an empty engine list is no engine, as ',' is (it ran all five)
for cmd in compare suite verify map; do
  expect "^diskval $cmd: no engine in ''\$" $cmd "$sc" --engines ''
done
# an option of one value given twice: the first was dropped without a word
expect "^diskval compare: --engines given twice" compare "$sc" --engines ode --engines mujoco
expect "^diskval simulate: --engine given twice" simulate "$sc" --engine reduced --engine mujoco
expect "^diskval suite: --out given twice" suite "$sc" --out a --out b
expect "^diskval best: --theta-tol given twice" best "$sc" --engine mujoco --theta-tol 1 \
  --theta-tol 2
# suite runs one kind at a time (--verify alone ran, --stability was dropped)
expect "^diskval suite: --stability and --verify: one at a time" suite "$sc" --stability --verify
# a file that cannot be opened has no line to name
expect "^nosuch.ini: cannot open: No such file or directory\$" simulate nosuch.ini --engine reduced
expect "--set 'radius=1': expected section.key=value" simulate "$sc" --engine reduced --set radius=1
expect "same file" simulate "$sc" --engine reduced --out a.csv --forces a.csv
expect "same file" simulate "$sc" --engine reduced --out a.csv --forces ./a.csv
expect "same file" simulate "$sc" --engine reduced --out "$work/a.csv" --forces a.csv
expect "same file" simulate "$sc" --engine reduced --out - --forces -
expect "the metadata file --out writes beside it 'a.csv.json'" simulate "$sc" --engine reduced --out a.csv \
  --forces ./a.csv.json
# judge: its files are read, and its names checked, before anything is written
expect "^diskval judge: .*needs|^diskval judge: .*trajector|^diskval judge: .*argument" judge "$sc"
expect "^diskval judge: --name gives 2 names for 1 trajectories" judge "$sc" a.csv --name p,q
expect "^diskval judge: name 'mujoco' is a linked engine's" judge "$sc" mujoco.csv
expect "^diskval judge: two trajectories named 'a'" judge "$sc" a.csv x/a.csv
expect "^diskval judge: name 'a b': only letters" judge "$sc" a.csv --name 'a b'
expect "^diskval judge: 17 trajectories: at most 16" judge "$sc" a.csv b.csv c.csv d.csv e.csv f.csv g.csv \
  h.csv i.csv j.csv k.csv l.csv m.csv n.csv o.csv p.csv q.csv
expect "^diskval judge: nosuch.csv: cannot open: No such file or directory\$" judge "$sc" nosuch.csv
[ $fail -eq 0 ] && echo "every bad argument refused in one line, exit 2, nothing written"
exit $fail
