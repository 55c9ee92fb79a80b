#!/usr/bin/env bash
# check_engine_modules.sh DISKVAL MODULE_DIR SCENARIO: an engine's module
# (engines/engine_module.h) is opened only when the engine runs, and a module
# missing or broken disables its engine alone.
#  - `diskval --help` and `simulate --engine reduced` open no module (the
#    dynamic loader's own record, LD_DEBUG=files), while `simulate --engine ode`
#    opens engine_ode.so (the record sees a module when one is opened);
#  - with DISKVAL_ENGINE_DIR a folder where bullet's module is missing and
#    DART's is a corrupt file: `diskval engines` lists both as not available
#    with the path and the loader's reason, `compare --engines ode` runs ode
#    (exit 0: short_circle agrees), and `compare --engines bullet` is refused in
#    one line naming the module, exit 2, nothing written.
set -u
diskval=${1:?usage: check_engine_modules.sh DISKVAL MODULE_DIR SCENARIO}
modules=${2:?}
scenario=${3:?}
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
bad=0
fail() { echo "FAIL: $*"; bad=1; }
unset DISKVAL_ENGINE_DIR

# the modules a command opens, as the loader reports them
opened() { LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -o 'engine_[a-z0-9]*\.so' | sort -u | tr '\n' ' '; }

got=$(opened "$diskval" --help)
[ -z "$got" ] || fail "diskval --help opened $got"
got=$(opened "$diskval" simulate "$scenario" --engine reduced --quiet --out "$tmp/reduced.csv")
[ -z "$got" ] || fail "simulate --engine reduced opened $got"
got=$(opened "$diskval" simulate "$scenario" --engine ode --quiet --out "$tmp/ode.csv")
[ "$got" = "engine_ode.so " ] || fail "simulate --engine ode opened '$got', not engine_ode.so alone"

# a folder of modules: bullet's missing, DART's corrupt, the others there
mkdir "$tmp/modules"
for m in "$modules"/engine_*.so; do
  case "$m" in */engine_bullet.so | */engine_dart.so) ;; *) ln -s "$m" "$tmp/modules/" ;; esac
done
echo "not a module" >"$tmp/modules/engine_dart.so"
export DISKVAL_ENGINE_DIR=$tmp/modules

list=$("$diskval" engines) || fail "diskval engines: exit $?"
grep -q "^bullet .*\[not available: $tmp/modules/engine_bullet.so: cannot open shared object file" <<<"$list" ||
  fail "diskval engines: bullet not listed as not available: $(grep '^bullet' <<<"$list")"
grep -q "^dart .*\[not available: $tmp/modules/engine_dart.so: .*\]" <<<"$list" ||
  fail "diskval engines: dart not listed as not available: $(grep '^dart' <<<"$list")"
grep -q "^ode .*\[ODE " <<<"$list" || fail "diskval engines: ode not available: $(grep '^ode' <<<"$list")"

"$diskval" compare "$scenario" --engines ode --quiet --out "$tmp/ode" >"$tmp/ode.out" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "compare --engines ode: exit $rc: $(cat "$tmp/ode.out")"
grep -q "ode  *agrees" "$tmp/ode.out" || fail "compare --engines ode: no ode verdict: $(cat "$tmp/ode.out")"

"$diskval" compare "$scenario" --engines bullet --quiet --out "$tmp/bullet" >"$tmp/bullet.out" 2>"$tmp/bullet.err"
rc=$?
[ $rc -eq 2 ] || fail "compare --engines bullet: exit $rc, not 2"
[ "$(wc -l <"$tmp/bullet.err")" -eq 1 ] || fail "compare --engines bullet: not one line: $(cat "$tmp/bullet.err")"
grep -q "bullet: not available: $tmp/modules/engine_bullet.so: " "$tmp/bullet.err" ||
  fail "compare --engines bullet: the line names no module: $(cat "$tmp/bullet.err")"
[ ! -e "$tmp/bullet" ] || fail "compare --engines bullet wrote $tmp/bullet"

[ $bad -eq 0 ] && echo "engine modules: opened only when run; a missing or broken one disables its engine alone"
exit $bad
