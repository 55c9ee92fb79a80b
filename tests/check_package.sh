#!/usr/bin/env bash
# check_package.sh SOURCE_DIR BUILD_DIR [sanitize]: the installed package works
# for a project of its own. Installs the build into a fresh prefix; builds
# examples/ against it with find_package(diskval) and runs both programs on
# installed scenarios; compiles one with pkg-config's flags; checks that
# libdiskval exports only diskval_*; makes the .deb (cpack -G DEB) and reads
# its control data and contents (skipped where dpkg-deb is missing).
# Exit 77 (skipped) under the sanitizers: programs outside the build cannot
# load an ASan-built libdiskval without the sanitizer runtime preloaded.
set -euo pipefail
src=${1:?usage: check_package.sh SOURCE_DIR BUILD_DIR [sanitize]}
build=${2:?usage: check_package.sh SOURCE_DIR BUILD_DIR [sanitize]}
if [ "${3:-}" = sanitize ]; then
  echo "SKIP: the package is not checked in a sanitizer build"
  exit 77
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

cmake --install "$build" --prefix "$prefix" >/dev/null
scenarios=$prefix/share/diskval/scenarios
for f in bin/diskval include/diskval/diskval.h lib*/cmake/diskval/diskvalConfig.cmake \
  lib*/cmake/diskval/diskvalConfigVersion.cmake lib*/pkgconfig/diskval.pc \
  share/diskval/scenarios/steady_circle.ini share/doc/diskval/README.md share/doc/diskval/docs/judge.md; do
  compgen -G "$prefix/$f" >/dev/null || fail "not installed: $f"
done
if [ -f "$build/diskval.1" ]; then # built where help2man is installed
  [ -f "$prefix/share/man/man1/diskval.1" ] || fail "not installed: share/man/man1/diskval.1"
fi
lib=$(compgen -G "$prefix/lib*/libdiskval.so" | head -1)
[ -n "$lib" ] || fail "not installed: libdiskval.so"
soname=$(readelf -d "$lib" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')
[[ $soname =~ ^libdiskval\.so\.0\.[0-9]+$ ]] || fail "soname '$soname', expected libdiskval.so.0.MINOR"
echo "installed: $prefix (soname $soname)"

# only the public API is exported
others=$(nm -D --defined-only "$lib" | awk '{print $3}' | grep -v '^diskval_' || true)
[ -z "$others" ] || fail "libdiskval exports more than diskval_*: $(echo $others | head -c 400)"
echo "exports: $(nm -D --defined-only "$lib" | grep -c ' diskval_') diskval_* symbols, nothing else"

# the installed command runs from the prefix
"$prefix/bin/diskval" --help >/dev/null || fail "installed diskval --help"

# examples/ as a project of its own, against the install only
config=$(cmake -S "$src/examples" -B "$work/examples" -DCMAKE_PREFIX_PATH="$prefix")
version=$(sed -n 's/^-- diskval \([0-9.]*\): .*/\1/p' <<<"$config")
[ -n "$version" ] || fail "find_package(diskval) said no version: $config"
cmake --build "$work/examples" >/dev/null
out=$("$work/examples/reference_theta" "$scenarios/falling.ini")
echo "$out"
grep -q "^falling: theta(0\.39[0-9]* s) = 0\.05" <<<"$out" || fail "reference_theta: $out"
status=0
out=$("$work/examples/mujoco_verdict" "$scenarios/steady_circle.ini") || status=$?
echo "$out"
[ $status -le 1 ] || fail "mujoco_verdict exited $status"
grep -q "^steady_circle: mujoco: agrees" <<<"$out" || fail "mujoco_verdict: no verdict 'agrees'"

# pkg-config, as a Makefile would use it
export PKG_CONFIG_PATH
PKG_CONFIG_PATH=$(dirname "$(compgen -G "$prefix/lib*/pkgconfig/diskval.pc" | head -1)")
flags=$(pkg-config --cflags --libs diskval)
echo "pkg-config --cflags --libs diskval: $flags"
# shellcheck disable=SC2086
cc -std=c11 -o "$work/theta_pc" "$src/examples/reference_theta.c" $flags
LD_LIBRARY_PATH=$(dirname "$lib") "$work/theta_pc" "$scenarios/falling.ini" | grep -q "theta(" ||
  fail "reference_theta built with pkg-config's flags"
[ "$(pkg-config --modversion diskval)" = "$version" ] || fail "pkg-config and CMake versions differ"

# the Debian package
if ! command -v dpkg-deb >/dev/null; then
  echo "SKIP (deb): dpkg-deb is not installed"
  exit 0
fi
(cd "$work" && cpack -G DEB --config "$(cd "$build" && pwd)/CPackConfig.cmake" -B "$work/deb" >/dev/null)
deb=$(compgen -G "$work/deb/*.deb" | head -1)
[ -n "$deb" ] || fail "cpack made no .deb"
info=$(dpkg-deb -I "$deb")
depends=$(sed -n 's/^ Depends: //p' <<<"$info")
echo "Depends: $depends"
for p in libgsl27 libsundials-cvode libode8 libmujoco2.2.2; do
  grep -q "$p" <<<"$depends" || fail ".deb does not depend on $p: $depends"
done
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/diskval ./usr/lib/.*libdiskval.so.0.[0-9]* ./usr/include/diskval/diskval.h \
  ./usr/share/diskval/scenarios/steady_circle.ini ./usr/lib/.*cmake/diskval/diskvalConfig.cmake \
  ./usr/lib/.*pkgconfig/diskval.pc ./usr/share/doc/diskval/README.md ./usr/share/doc/diskval/docs/README.md; do
  grep -q " $f" <<<"$contents" || fail ".deb holds no $f"
done
echo "package: $(basename "$deb"): command, library, headers, CMake and pkg-config files, scenarios"
