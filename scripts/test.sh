#!/usr/bin/env bash
# Builds Pineda and runs every test: the unit and end-to-end tests (ctest), the piglit
# groups Pineda claims against conformance/expectations/, the Debian package in a clean root,
# then the unit tests again built with AddressSanitizer and UndefinedBehaviorSanitizer (clang), and
# the fuzz targets of that build for a minute each.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
# Each step says how long it took, so that a slow CI run shows where its time went.
timed() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "== $name: $((SECONDS - start)) s (test.sh so far: $SECONDS s)"
}

timed build "$root/scripts/build.sh" "$root/build"
timed ctest ctest --test-dir "$root/build" -j"$jobs" --output-on-failure

timed "piglit glx" timeout 600 python3 "$root/conformance/run.py" --platform glx --lib-dir "$root/build/lib" \
  --group 'spec@!opengl 1.0' --group 'spec@!opengl 1.1' --group 'spec@!opengl 1.2' \
  --group 'spec@!opengl 1.3' --group 'spec@!opengl 1.4' --group 'spec@!opengl 1.5' \
  --group 'spec@arb_framebuffer_object' --group 'spec@ext_framebuffer_object' --group 'spec@ext_packed_depth_stencil' \
  --group 'spec@arb_pixel_buffer_object' --group 'spec@ext_framebuffer_blit' --group 'spec@arb_depth_texture' \
  --expected-total 649
# OpenGL ES 2.0, GLSL ES 1.00, GL 2.0/2.1 and GLSL 1.10/1.20, headless (5096 tests).
timed "piglit headless" timeout 900 python3 "$root/conformance/run.py" --platform surfaceless_egl --lib-dir "$root/build/lib" \
  --group 'spec@!opengl es 2.0' --group 'spec@glsl-es-1.00' \
  --group 'spec@!opengl 2.0' --group 'spec@!opengl 2.1' --group 'spec@glsl-1.10' --group 'spec@glsl-1.20' \
  --expected-total 5096

# The Debian package, made from the build above, tried in a clean Debian 12 root (as root).
timed package "$root/scripts/package-test.sh" "$root/build"

# One clang build with ASan+UBSan serves the unit tests and the libFuzzer targets (tests/fuzz);
# a build-asan of another compiler (GCC made it before) is started afresh.
if [ -f "$root/build-asan/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang++$' "$root/build-asan/CMakeCache.txt"; then
  rm -rf "$root/build-asan"
fi
timed "sanitizer build" "$root/scripts/build.sh" "$root/build-asan" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DPINEDA_SANITIZE=ON -DPINEDA_FUZZ=ON
timed "sanitizer ctest" env ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$root/build-asan" -j"$jobs" --output-on-failure
# Both fuzz targets side by side, each for 60 s from its seeds (the inputs of earlier findings
# among them), with a fixed random seed so that a failure reproduces.
timed fuzz env PINEDA_FUZZ_SEED=1 PINEDA_FUZZ_BUILD="$root/build-asan" "$root/tests/fuzz/run.sh" 60
