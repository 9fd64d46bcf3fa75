#!/usr/bin/env bash
# Runs the fuzz targets (clang, libFuzzer, ASan + UBSan) side by side, each for SECONDS seconds from
# its committed seed corpus (tests/fuzz/corpus/<target>/): api (every exported GL entry point, OpenGL ES 1.1's
# among them, and every EGL entry point, tests/fuzz/api_fuzzer.cpp and gl_calls.h) and glsl
# (shaders compiled, linked and drawn with, tests/fuzz/glsl_fuzzer.cpp, with tests/fuzz/glsl.dict).
# The build is PINEDA_FUZZ_BUILD when that is already configured with PINEDA_FUZZ=ON (scripts/test.sh
# passes its sanitizer build), otherwise build-fuzz, configured here without the tests.
# Exits non-zero when a target crashes, trips a sanitizer, times out or runs out of memory;
# the input that did it is left in BUILD/findings/<target>/.
# PINEDA_FUZZ_SEED fixes libFuzzer's random seed (scripts/test.sh: 1, so that CI repeats the
# same mutations and a red run reproduces); unset, each run explores anew.
# Usage: tests/fuzz/run.sh SECONDS [TARGET...]
set -euo pipefail
seconds=${1:?usage: tests/fuzz/run.sh SECONDS [TARGET...]}
shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(api glsl)
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${PINEDA_FUZZ_BUILD:-$root/build-fuzz}
if ! grep -q '^PINEDA_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DPINEDA_FUZZ=ON -DPINEDA_TESTS=OFF >/dev/null
fi
for target in "${targets[@]}"; do
  cmake --build "$build" -j"$(nproc)" --target "pineda_${target}_fuzzer"
done
# The targets run side by side (each is one process), each into its own log, shown when all are done.
pids=()
for target in "${targets[@]}"; do
  # New inputs go to the build's corpus; the committed seeds are only read.
  corpus=$build/corpus/$target findings=$build/findings/$target
  mkdir -p "$corpus" "$findings"
  options=()
  [ -n "${PINEDA_FUZZ_SEED:-}" ] && options+=(-seed="$PINEDA_FUZZ_SEED")
  [ -f "$root/tests/fuzz/$target.dict" ] && options+=(-dict="$root/tests/fuzz/$target.dict")
  "$build/tests/fuzz/pineda_${target}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=512 -max_len=4096 -print_final_stats=1 -artifact_prefix="$findings/" "${options[@]}" \
    "$corpus" "$root/tests/fuzz/corpus/$target" > "$build/fuzz-$target.log" 2>&1 &
  pids+=($!)
done
status=0
for i in "${!targets[@]}"; do
  target=${targets[$i]}
  result=0
  wait "${pids[$i]}" || result=$?
  echo "== fuzz target $target ($build/fuzz-$target.log)"
  cat "$build/fuzz-$target.log"
  if [ "$result" -ne 0 ]; then
    echo "fuzz target $target failed; reproducer in $build/findings/$target/" >&2
    status=1
  fi
done
exit $status
