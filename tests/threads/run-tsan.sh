#!/usr/bin/env bash
# Builds Pineda with ThreadSanitizer in build-tsan (or BUILD_DIR) and runs under it the threads
# tests (the GLX ones under Xvfb when xvfb-run is there), a short soak run, the EGL/OSMesa driver
# tests, the rasterizer's worker-thread tests and the vertex stages spread over the rasterizer's
# threads. Any data race fails.
#   tests/threads/run-tsan.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build-tsan}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPINEDA_TSAN=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target pineda_threads_tests pineda_soak pineda_driver_tests pineda_raster_tests \
  pineda_stability_tests
export TSAN_OPTIONS="halt_on_error=1 abort_on_error=0 exitcode=66 second_deadlock_stack=1 suppressions=$root/tests/threads/tsan.supp ${TSAN_OPTIONS:-}"
# Fewer frames than the default 40: the scene runs 5-15 times slower under TSan.
export PINEDA_THREADS_TEST_FRAMES=${PINEDA_THREADS_TEST_FRAMES:-16}
# TSan needs the mappings of a non-randomized address space on some kernels.
run=()
if setarch "$(uname -m)" -R true 2>/dev/null; then run=(setarch "$(uname -m)" -R); fi
start=$(date +%s)
"${run[@]}" "$build/tests/threads/pineda_threads_tests"
if command -v xvfb-run >/dev/null; then
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "${run[@]}" "$build/tests/threads/pineda_threads_tests" \
    --gtest_filter='*Glx*'
fi
"${run[@]}" "$build/tests/driver/pineda_driver_tests"
# Memory under TSan says nothing about leaks: only the races count here.
"${run[@]}" "$build/tests/threads/pineda_soak" 10 --warmup 2 --max-growth-kib 100000000
"${run[@]}" "$build/tests/raster/pineda_raster_tests" --gtest_filter='*Worker*:*Scene*:*Thread*:*Pieces*'
"${run[@]}" "$build/tests/stability/pineda_stability_tests" --gtest_filter='VertexStageThreads*:FloatModesThreads*'
echo "ThreadSanitizer: no data race reported ($(( $(date +%s) - start )) s of tests)"
