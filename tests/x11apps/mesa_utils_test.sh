#!/bin/sh
# Mesa's demo programs (Debian mesa-utils) on Pineda; run under Xvfb by ctest.
#   mesa_utils_test.sh PINEDA_RUN glxinfo
#   mesa_utils_test.sh PINEDA_RUN eglinfo
#   mesa_utils_test.sh PINEDA_RUN glxgears PNG_PROBE CAPTURE_DIR
# Exit 0 when the program ran on Pineda and showed what it should.
set -u
run=$1
what=$2

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

case "$what" in
  glxinfo)
    out=$("$run" glxinfo -B 2>&1) || fail "glxinfo -B exited with $?: $out"
    echo "$out"
    echo "$out" | grep -q "^direct rendering: Yes" || fail "no direct rendering"
    echo "$out" | grep -q "OpenGL vendor string: Pineda$" || fail "the vendor is not Pineda"
    echo "$out" | grep -q "OpenGL renderer string: Pineda" || fail "the renderer is not Pineda"
    ;;
  eglinfo)
    # eglinfo asks every platform it knows; Pineda answers the X11 and surfaceless ones.
    out=$(XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp} "$run" eglinfo 2>&1) || fail "eglinfo exited with $?"
    echo "$out"
    x11=$(echo "$out" | sed -n '/^X11 platform:/,/^[A-Z][a-z]* platform:/p')
    echo "$x11" | grep -q "EGL vendor string: Pineda" || fail "the X11 platform's vendor is not Pineda"
    echo "$x11" | grep -q "win,pb,pix" || fail "no X11 config with windows, pbuffers and pixmaps"
    surfaceless=$(echo "$out" | sed -n '/^Surfaceless platform:/,/^[A-Z][a-z]* platform:/p')
    echo "$surfaceless" | grep -q "EGL vendor string: Pineda" || fail "the surfaceless platform's vendor is not Pineda"
    ;;
  glxgears)
    probe=$3
    dir=$4
    rm -rf "$dir"
    # glxgears draws until it is killed: 3 seconds of frames, every one captured.
    PINEDA_CAPTURE="$dir" timeout 3 "$run" glxgears > "$dir.log" 2>&1
    status=$?
    [ "$status" -eq 124 ] || fail "glxgears ended with status $status: $(cat "$dir.log")"
    frames=$(ls "$dir" | grep -c '^frame-[0-9]*\.png$')
    [ "$frames" -ge 2 ] || fail "only $frames frames captured"
    # The newest file may be cut short where the timeout killed glxgears mid-write.
    last=$(ls "$dir"/frame-*.png | tail -n 2 | head -n 1)
    echo "$frames frames; checking $last"
    # The front face of each gear (flat-shaded, normal +z, so one colour whatever the gear's
    # rotation) at a point of its rotation-invariant ring between hole and teeth, projected
    # with glxgears' view (300x300 window, frustum -1..1 x -1..1 x 5..60, translate z -40,
    # rotate x 20, y 30): red gear1 at 63,208; green gear2 at 224,176; blue gear3 at 97,53.
    # The colours are Pineda's lit material colours (0.8 0.1 0, 0 0.8 0.2, 0.2 0.2 1 with
    # glxgears' light at 5 5 10), as captured.
    colours=$("$probe" "$last" 63 208 224 176 97 53) || fail "cannot read $last"
    expected="c11800
00c130
3030f2"
    [ "$colours" = "$expected" ] || fail "gear colours: got $(echo $colours), expected $(echo $expected)"
    ;;
  *)
    fail "unknown program $what"
    ;;
esac
echo PASS
