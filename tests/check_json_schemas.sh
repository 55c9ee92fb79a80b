#!/usr/bin/env bash
# check_json_schemas.sh DISKVAL SOURCE_DIR: the JSON files diskval writes,
# validated against their JSON Schemas (draft 2020-12) in
# tests/fixtures/schemas, so that a field a writer renames, drops or retypes
# fails here:
#   report.json   compare on a thin scene, a thick one and a coin that lies
#                 down (its event judged), a suite's scenarios, and the error
#                 report of a scenario that timed out, and judge of a recorded MuJoCo run
#                 (its entry with the interpolation's estimated error)
#   summary.json  a suite of two scenes, and a suite whose scenario timed out
#   run JSON      simulate with each engine: reduced, matched, mujoco, ode, bullet, dart, simbody
#   verify.json   suite --verify: a case that ran and one skipped
# and the schemas are not too loose: copies of a report.json with one field
# broken (a limit's margin renamed, an engine's pass dropped, a metric written
# as a string, ...) must each be rejected.
# Exit status: 0 all as expected, 1 a difference (every schema error printed
# with its JSON path), 77 skipped: python3 has no jsonschema.
set -u
. "$(dirname "$0")/check_lib.sh"
diskval=$1 src=$2
schemas=$src/tests/fixtures/schemas data=$src/tests/data
if ! python3 -c 'import jsonschema' 2>/dev/null; then
  echo "python3 jsonschema is not installed (python3-jsonschema): skipped"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# validate SCHEMA valid|invalid FILE...: every file valid against
# $schemas/SCHEMA (each error printed with its JSON path), or every file rejected
validate() { python3 "$src/tests/json_validate.py" "$schemas" "$@"; }

# diskval ARGS... --quiet; exit 0 or 1 (a verdict), not 2 (bad input, an error)
run() {
  "$diskval" "$@" --quiet >"$work/log" 2>&1
  local code=$?
  check '[ $code -lt 2 ]' "diskval $* (exit $code): $(cat "$work/log")"
}

run compare "$data/short_circle.ini" --out "$work/thin"
run compare "$data/quarter_circle.ini" --set scenario.duration=0.3 --out "$work/thick"
run compare "$data/coin_falls_flat.ini" --out "$work/flat"
mkdir "$work/two" "$work/late" "$work/verify_in"
cp "$data/short_circle.ini" "$src/scenarios/falling.ini" "$work/two/"
run suite "$work/two" --jobs 1 --out "$work/suite"
cp "$data/short_circle.ini" "$work/late/"
"$diskval" suite "$work/late" --jobs 1 --timeout 0.001 --quiet --out "$work/late_out" >/dev/null 2>&1
check 'grep -q "\"error\":.*timed out" "$work/late_out/short_circle/report.json"' \
  "a scenario timed out without an error report"
for engine in reduced matched mujoco ode bullet dart simbody; do
  run simulate "$data/short_circle.ini" --engine "$engine" --set scenario.duration=0.5 \
    --out "$work/run_$engine.csv"
done
# a recorded trajectory judged: its entry is named by the file, with no settings
run judge "$data/short_circle.ini" --set scenario.duration=0.5 "$work/run_mujoco.csv" --out "$work/judged"
# two half-second circles: one verified in both engines, one naming mujoco (ode skipped)
sed 's/^duration = .*/duration = 0.5/' "$data/short_circle.ini" >"$work/verify_in/both.ini"
sed -e 's/^name = .*/name = mujoco_only\nengines = mujoco/' "$work/verify_in/both.ini" \
  >"$work/verify_in/mujoco_only.ini"
run suite "$work/verify_in" --verify --engines mujoco,ode --jobs 1 --out "$work/verify"
check 'grep -q "\"verdict\":.*\"skipped\"" "$work/verify/verify.json"' "verify.json has no skipped case"
check 'grep -q "\"agrees\":" "$work/flat/coin_falls_flat/report.json"' "the coin's event was not judged"

check 'validate report.schema.json valid "$work"/{thin,thick,flat,suite,late_out,judged}/*/report.json' \
  "report.json does not match report.schema.json"
check 'validate summary.schema.json valid "$work"/{suite,late_out}/summary.json' \
  "summary.json does not match summary.schema.json"
check 'validate run.schema.json valid "$work"/run_*.csv.json' "a run JSON does not match run.schema.json"
check 'validate verify.schema.json valid "$work/verify/verify.json"' \
  "verify.json does not match verify.schema.json"

# what a schema cannot say: each limit's margin is its value over its limit, and
# value and limit are the engine's metric and tolerance as written beside them
consistent() {
  python3 - "$@" <<'EOF'
import json, math, sys
bad = 0
for f in sys.argv[1:]:
    for name, e in json.load(open(f)).get("engines", {}).items():
        for m, l in (e.get("limits") or {}).items():
            v, lim, mar = l["value"], l["limit"], l["margin"]
            want = v / lim if v is not None and lim else None
            if (want is None) != (mar is None) or (want is not None and math.isfinite(want)
                                                    and abs(mar - want) > 1e-12 * abs(want)):
                print(f"{f}: {name}: {m}: margin {mar}, value / limit {want}"); bad = 1
            if e.get(m) != v or e.get("tolerances", {}).get(m) != lim:
                print(f"{f}: {name}: {m}: value {v} / limit {lim}, the engine's {e.get(m)} / "
                      f"{e.get('tolerances', {}).get(m)}"); bad = 1
sys.exit(bad)
EOF
}
check 'consistent "$work"/{thin,thick,flat,suite}/*/report.json' \
  "a limit in report.json is not the engine's metric over its tolerance"

# copies of a valid report.json, each broken in one way the schema must catch
[ $fail -eq 0 ] || exit 1 # no valid report to break
mkdir "$work/broken"
python3 - "$work/thin/short_circle/report.json" "$work/broken" <<'EOF'
import json, pathlib, sys

def margin_renamed(r):
    limit = r["engines"]["mujoco"]["limits"]["theta_max_err"]
    limit["margin_ratio"] = limit.pop("margin")
def pass_dropped(r): del r["engines"]["ode"]["pass"]
def metric_as_string(r): r["engines"]["mujoco"]["theta_max_err"] = "0.1"
def outcome_unknown(r): r["engines"]["mujoco"]["outcome"] = "agreed"
def ran_with_dropped(r): del r["engines"]["mujoco"]["ran_with"]
def setting_renamed(r):
    settings = r["engines"]["ode"]["settings"]
    settings["time_step"] = settings.pop("timestep")
def limit_value_dropped(r): del r["engines"]["ode"]["limits"]["path_max_err"]["value"]

for broken in (margin_renamed, pass_dropped, metric_as_string, outcome_unknown, ran_with_dropped,
               setting_renamed, limit_value_dropped):
    report = json.loads(pathlib.Path(sys.argv[1]).read_text())
    broken(report)
    (pathlib.Path(sys.argv[2]) / f"{broken.__name__}.json").write_text(json.dumps(report))
EOF
# a judged file's entry must carry its interpolation's estimated error
python3 - "$work/judged/short_circle/report.json" "$work/broken" <<'EOF'
import json, pathlib, sys

def interpolation_dropped(r): del r["engines"]["run_mujoco"]["interpolation"]
def interpolation_theta_dropped(r): del r["engines"]["run_mujoco"]["interpolation"]["theta"]

for broken in (interpolation_dropped, interpolation_theta_dropped):
    report = json.loads(pathlib.Path(sys.argv[1]).read_text())
    broken(report)
    (pathlib.Path(sys.argv[2]) / f"{broken.__name__}.json").write_text(json.dumps(report))
EOF
check '[ "$(ls "$work/broken" | wc -l)" -eq 9 ]' "the broken copies were not all written"
check 'validate report.schema.json invalid "$work"/broken/*.json' \
  "report.schema.json accepts a broken report.json"
exit $fail
