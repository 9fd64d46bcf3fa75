#!/bin/sh
# apitrace (Debian apitrace, apitrace-tracers) on Pineda: a demo scene traced through EGL and
# replayed with eglretrace, headless and on X11; run under Xvfb by ctest.
#   apitrace_test.sh PINEDA_RUN PINEDA_DEMO PINEDA_IMGDIFF WORK_DIR
set -u
run=$1
demo=$2
imgdiff=$3
work=$4

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
"$run" apitrace trace -a egl -o "$work/cube.trace" "$demo" --out "$work/demo" --frames 1 --scene cube \
  || fail "tracing the demo exited with $?"
# The demo reads its frame back once; that call is where the replay is compared.
call=$(apitrace dump "$work/cube.trace" 2>/dev/null | sed -n 's/^\([0-9]*\) glReadPixels(.*/\1/p' | head -n 1)
[ -n "$call" ] || fail "no glReadPixels in the trace"

# Headless (waffle's surfaceless EGL): the replay draws exactly the demo's image.
WAFFLE_PLATFORM=surfaceless_egl "$run" eglretrace -S "$call" -s "$work/surfaceless-" "$work/cube.trace" \
  || fail "eglretrace (surfaceless) exited with $?"
out=$("$imgdiff" "$work/surfaceless-$(printf %010d "$call").png" "$work/demo/cube.png")
echo "$out"
echo "$out" | grep -q "^max channel difference: 0$" || fail "the surfaceless replay differs from the demo"

# On X11 eglretrace resolves glX functions through eglGetProcAddress. (It replays the pbuffer
# as a window of its own default size, on llvmpipe too, so only the run is checked here.)
"$run" eglretrace -S "$call" -s "$work/x11-" "$work/cube.trace" || fail "eglretrace (X11) exited with $?"
[ -f "$work/x11-$(printf %010d "$call").png" ] || fail "eglretrace (X11) wrote no snapshot"
echo "eglretrace replayed the demo trace on X11 and headless"
