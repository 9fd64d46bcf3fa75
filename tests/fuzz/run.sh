#!/usr/bin/env bash
# Builds the API fuzzer (clang, libFuzzer, ASan + UBSan) into build-fuzz and runs each fuzz
# target for SECONDS seconds from its committed seed corpus (tests/fuzz/corpus/<target>/).
# Exits non-zero when a target crashes, trips a sanitizer, times out or runs out of memory;
# the input that did it is left in build-fuzz/findings/<target>/.
# Usage: tests/fuzz/run.sh SECONDS
set -euo pipefail
seconds=${1:?usage: tests/fuzz/run.sh SECONDS}
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${PINEDA_FUZZ_BUILD:-$root/build-fuzz}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DPINEDA_FUZZ=ON -DPINEDA_TESTS=OFF >/dev/null
targets=(api)
for target in "${targets[@]}"; do
  cmake --build "$build" -j"$(nproc)" --target "pineda_${target}_fuzzer"
done
status=0
for target in "${targets[@]}"; do
  # New inputs go to the build's corpus; the committed seeds are only read.
  corpus=$build/corpus/$target findings=$build/findings/$target
  mkdir -p "$corpus" "$findings"
  if ! "$build/tests/fuzz/pineda_${target}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -malloc_limit_mb=512 -max_len=4096 -print_final_stats=1 -artifact_prefix="$findings/" \
      "$corpus" "$root/tests/fuzz/corpus/$target"; then
    echo "fuzz target $target failed; reproducer in $findings/" >&2
    status=1
  fi
done
exit $status
