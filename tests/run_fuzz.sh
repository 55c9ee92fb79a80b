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
# the engines layer as diskval links it: its shared files, the references and each contact
# engine's table; an engine's own code is a module (engine_module.h) a load never opens
engine_c=()
while IFS= read -r f; do
  dir=$(dirname "$f")
  if [[ $f != *_table.c ]] && grep -qs DV_ENGINE_MODULE_EXPORT "$dir"/*.c "$dir"/*.cc; then
    continue
  fi
  engine_c+=("$f")
done < <(find "$src/engines" -name '*.c' ! -name 'test_*' | sort)
# shellcheck disable=SC2086
clang -std=c11 -D_XOPEN_SOURCE=700 -g -O1 -fsanitize=fuzzer,address,undefined \
  -DDV_ENGINE_BUILD_DIR="\"$work\"" -DDV_ENGINE_INSTALL_DIR="\"$work\"" \
  -I"$src/common" -I"$src/reduced" -I"$src/scenario" \
  "$src/tests/fuzz/fuzz_scenario.c" "$src"/scenario/*.c "${engine_c[@]}" \
  "$src/common/dv_error.c" "$src/common/dv_input.c" "$src/common/dv_phase.c" "$src/common/dv_clock.c" "$src/common/dv_rng.c" "$work/dv_format.o" "$src"/reduced/*.c "$src"/reduced/*/*.c \
  -I"$src/engines" $(pkg-config --cflags --libs inih gsl) $sundials -ldl -lpthread -ldouble-conversion \
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
