#!/usr/bin/env bash
# diskval set-up and entry point.
#   ./run.sh          install missing packages, build, run the default suite
#   ./run.sh test     the same set-up, then the whole test suite (CTest)
#   ./run.sh test --sanitize   the test suite built with AddressSanitizer and UBSan
#   ./run.sh bench    the same set-up, then the benchmarks
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(build-essential cmake pkg-config libgsl-dev libsundials-dev libinih-dev libcjson-dev
          libode-dev libmujoco-dev libbullet-dev libdart-dev libdart-collision-bullet-dev
          libdart-collision-ode-dev libsimbody-dev libplplot-dev libopenmpi-dev openmpi-bin
          libdouble-conversion-dev
          libdragonbox-dev)
# the tests (and the benchmarks) also check the report's XML and render its page in a real
# browser, read JSON (jq) and validate it against its schemas (python3-jsonschema)
TEST_PACKAGES=(libxml2-utils chromium valgrind clang libclang-rt-14-dev time jq python3-jsonschema)
BUILD_DIR=${BUILD_DIR:-build}
CMAKE_FLAGS=()
if [ "${2:-}" = --sanitize ]; then
  BUILD_DIR=build-sanitize
  CMAKE_FLAGS=(-DDV_SANITIZE=ON)
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
  export LSAN_OPTIONS="suppressions=$(pwd)/tests/lsan.supp"
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fi

install_missing() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
}

# the engines outside Debian (adapters/) run on Node: the machine's where it has one (18 or
# newer), else Debian's; their packages from the committed lockfile. Without them every
# other engine still runs (diskval engines says why an adapter cannot).
setup_adapters() {
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    install_missing nodejs npm || echo "adapters: Node could not be installed; they will not run" >&2
  fi
  command -v node >/dev/null && command -v npm >/dev/null || return 0
  if [ "$(node -p 'process.versions.node.split(".")[0]' 2>/dev/null || echo 0)" -lt 18 ]; then
    echo "adapters: Node $(node --version) is older than 18; they will not run" >&2
    return 0
  fi
  # npm ci replaces node_modules whole: only when the lockfile changed since the last install
  if ! cmp -s adapters/package-lock.json adapters/node_modules/.diskval-lock 2>/dev/null; then
    if (cd adapters && npm ci --no-audit --no-fund --loglevel=error >/dev/null); then
      cp adapters/package-lock.json adapters/node_modules/.diskval-lock
    else
      echo "adapters: npm ci failed; the engines outside Debian will not run" >&2
    fi
  fi
}

build() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${CMAKE_FLAGS[@]}" >/dev/null
  cmake --build "$BUILD_DIR" -j "$(nproc)"
}

if [ "${1:-run}" = test ] || [ "${1:-run}" = bench ]; then
  install_missing "${PACKAGES[@]}" "${TEST_PACKAGES[@]}"
else
  install_missing "${PACKAGES[@]}"
fi
setup_adapters
build
case "${1:-run}" in
  test)
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)"
    ;;
  bench)
    "$BUILD_DIR/props/diskval_props" --seed 2026 --count 500 || true # failures are findings, printed
    "$BUILD_DIR/bench/bench_reduced"
    "$BUILD_DIR/bench/bench_engines"
    "$BUILD_DIR/bench/bench_sweep" scenarios tests/data
    bash bench/bench_mpi.sh "$BUILD_DIR/cli/diskval" .
    bash bench/bench_output.sh baseline "$BUILD_DIR/cli/diskval" "$BUILD_DIR/bench/plain_gsl_disk"
    bash bench/bench_forecast.sh "$BUILD_DIR/cli/diskval" .
    bash bench/bench_time_limits.sh "$BUILD_DIR/cli/diskval" .
    bash bench/bench_harness.sh "$BUILD_DIR/cli/diskval" "$BUILD_DIR/bench/bare_mujoco" \
      "$BUILD_DIR/bench/bare_ode" .
    bash bench/bench_startup.sh "$BUILD_DIR/cli/diskval"
    bash bench/bench_compare.sh "$BUILD_DIR/cli/diskval" .
    bash bench/bench_league.sh "$BUILD_DIR/cli/diskval" .
    ;;
  run)
    # the default suite: every engine against the references, a report for people and CI
    status=0
    "$BUILD_DIR/cli/diskval" suite scenarios --out out --junit out/junit.xml || status=$?
    echo "report: $(pwd)/out/index.html (JUnit: out/junit.xml, summary: out/summary.json)"
    exit $status
    ;;
  *)
    echo "usage: ./run.sh [test|bench]" >&2
    exit 2
    ;;
esac
