#!/bin/sh
# installed_test.sh BUILD_DIR PREFIX EGL_PROGRAM: `cmake --install BUILD_DIR --prefix PREFIX`
# lays out the vendor libraries, the vendor file and the private library folder, and the installed
# pineda-run takes the vendor way by default (the library-path way with --library-path).
set -u
build=$1
prefix=$2
program=$3
fail() {
  echo "FAIL: $*"
  exit 1
}
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" > /dev/null || fail "cmake --install"
# The vendor libraries: their file name is their soname; they find libpineda.so.0 in pineda/.
for name in libGLX_pineda.so.0 libEGL_pineda.so.0; do
  dynamic=$(readelf -d "$prefix/lib/$name") || fail "no $prefix/lib/$name"
  echo "$dynamic" | grep -q "(SONAME) *Library soname: \[$name\]" || fail "$name: $dynamic"
  echo "$dynamic" | grep -q "(NEEDED) *Shared library: \[libpineda.so.0\]" || fail "$name: $dynamic"
  echo "$dynamic" | grep -q "R.*PATH) *Library r.*path: \[\$ORIGIN/pineda\]" || fail "$name: $dynamic"
done
[ ! -e "$prefix/lib/libGL.so.1" ] || fail "libGL.so.1 beside the vendor libraries"
[ -e "$prefix/lib/pineda/libGL.so.1" ] || fail "no libGL.so.1 in $prefix/lib/pineda"
json="$prefix/share/pineda/egl_vendor.d/50_pineda.json"
grep -q "\"library_path\" : \"$prefix/lib/libEGL_pineda.so.0\"" "$json" ||
  fail "$json: $(cat "$json")"

env=$(LD_LIBRARY_PATH= "$prefix/bin/pineda-run" --env)
expected="export __GLX_VENDOR_LIBRARY_NAME=pineda
export __EGL_VENDOR_LIBRARY_FILENAMES=\"$json\"
export LD_LIBRARY_PATH=\"$prefix/lib\""
[ "$env" = "$expected" ] || fail "pineda-run --env printed: $env"
env=$(LD_LIBRARY_PATH= "$prefix/bin/pineda-run" --library-path --env)
expected="export LD_LIBRARY_PATH=\"$prefix/lib/pineda\"
export PINEDA_LIB_DIR=\"$prefix/lib/pineda\""
[ "$env" = "$expected" ] || fail "pineda-run --library-path --env printed: $env"

"$prefix/bin/pineda-run" "$program" || fail "$program through the installed vendor"
echo PASS
