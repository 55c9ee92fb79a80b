#!/usr/bin/env bash
# diskval set-up and entry point.
#   ./run.sh          install missing packages, build, run the default suite
#   ./run.sh test     the same set-up, then the whole test suite (CTest)
#   ./run.sh bench    the same set-up, then the benchmarks
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(build-essential cmake pkg-config libgsl-dev libsundials-dev libinih-dev libcjson-dev
          libode-dev libmujoco-dev)
BUILD_DIR=${BUILD_DIR:-build}

install_missing() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
}

build() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD_DIR" -j "$(nproc)"
}

install_missing
build
case "${1:-run}" in
  test)
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)"
    ;;
  bench)
    "$BUILD_DIR/bench/bench_reduced"
    "$BUILD_DIR/bench/bench_engines"
    ;;
  run)
    mkdir -p out
    for s in scenarios/*.ini; do
      name=$(basename "$s" .ini)
      "$BUILD_DIR/harness/diskval" analyze "$s" --json >"out/$name.analysis.json"
      for engine in reduced matched mujoco ode; do
        # a contact engine may fail on a scenario (C = 0, a landing hop): that is its outcome
        "$BUILD_DIR/harness/diskval" simulate "$s" --engine "$engine" --out "out/$name.$engine.csv" \
          || echo "  ($name: $engine did not complete)"
      done
    done
    echo "trajectories and analyses written to $(pwd)/out/"
    ;;
  *)
    echo "usage: ./run.sh [test|bench]" >&2
    exit 2
    ;;
esac
