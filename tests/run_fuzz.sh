#!/usr/bin/env bash
# run_fuzz.sh SOURCE_DIR SECONDS: build the libFuzzer target for the scenario
# parser with clang (AddressSanitizer, UBSan) and run it for SECONDS with a
# seed corpus of the scenarios and the bad-scenario files. Skipped (77)
# where clang or its fuzzer runtime is missing.
set -u
src=$1
seconds=${2:-20}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v clang >/dev/null || { echo "SKIP: clang not installed"; exit 77; }
echo 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n) { return 0; }' >"$work/probe.c"
if ! clang -fsanitize=fuzzer "$work/probe.c" -o "$work/probe" 2>/dev/null; then
  echo "SKIP: clang's fuzzer runtime (libclang-rt-dev) not installed"
  exit 77
fi
sundials="-lsundials_cvode -lsundials_arkode -lsundials_nvecserial -lsundials_sunlinsoldense"
sundials="$sundials -lsundials_sunmatrixdense -lsundials_sunnonlinsolfixedpoint"
# numbers as text (dv_format) are C++ over Dragonbox and double-conversion
dragonbox=${DV_DRAGONBOX_INCLUDE:-$(ls -d /usr/include/dragonbox-* 2>/dev/null | tail -1)}
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer-no-link,address,undefined -I"$src/common" -I"$dragonbox" \
  -c "$src/common/dv_format.cc" -o "$work/dv_format.o" || exit 1
# engines written in C++, each in its folder (engines/NAME/*.cc)
cxx_engines=()
for cc in "$src"/engines/*/*.cc; do
  [ -e "$cc" ] || continue
  o="$work/$(basename "$cc" .cc).o"
  # the final link is C's: no UBSan C++ runtime for the vptr and function checks
  # (DART's aspect setters call through function pointers)
  # shellcheck disable=SC2046
  clang++ -std=c++17 -g -O1 -fsanitize=fuzzer-no-link,address,undefined \
    -fno-sanitize=vptr,function \
    -I"$src/common" -I"$src/reduced" -I"$src/scenario" -I"$src/engines" \
    $(pkg-config --cflags bullet-float64 eigen3) -I/usr/include/simbody -Wno-deprecated-declarations \
    -c "$cc" -o "$o" || exit 1
  cxx_engines+=("$o")
done
# the engines layer: its shared files and every engine's folder, without the engines' tests
mapfile -t engine_c < <(find "$src/engines" -name '*.c' ! -name 'test_*' | sort)
# shellcheck disable=SC2086
clang -std=c11 -D_XOPEN_SOURCE=700 -g -O1 -fsanitize=fuzzer,address,undefined \
  -I"$src/common" -I"$src/reduced" -I"$src/scenario" \
  "$src/tests/fuzz/fuzz_scenario.c" "$src"/scenario/*.c "${engine_c[@]}" \
  "$src/common/dv_error.c" "$src/common/dv_input.c" "$work/dv_format.o" "${cxx_engines[@]}" "$src"/reduced/*.c "$src"/reduced/*/*.c \
  -I"$src/engines" $(pkg-config --cflags --libs inih gsl ode bullet-float64) -lmujoco $sundials \
  -lSimTKsimbody -lSimTKmath -lSimTKcommon -ldart -ldart-collision-ode -ldl -ldouble-conversion \
  -lstdc++ -lm -o "$work/fuzz" || exit 1
mkdir -p "$work/corpus"
cp "$src"/scenarios/*.ini "$src"/scenarios/hard/*.ini "$src"/tests/bad/*.ini "$work/corpus/"
cd "$work" || exit 1
# a valid scene probes every engine's settings: scenarios/steady_circle.ini
# takes 5 s of user time under the sanitizers, 3.2 s of it DART's probe (its
# steps allocate), past 10 s on busy cores: a hang still ends at 30 s
./fuzz -max_total_time="$seconds" -max_len=4096 -timeout=30 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix="${FUZZ_ARTIFACTS:-$work/}" corpus 2>&1 | tail -40
status=${PIPESTATUS[0]}
rm -f /tmp/fuzz_scenario.*.ini
exit "$status"
