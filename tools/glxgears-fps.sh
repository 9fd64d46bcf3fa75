#!/bin/sh
# glxgears-fps.sh [SECONDS] [--build DIR] [--out DIR]: runs Mesa's glxgears (mesa-utils) for
# SECONDS (default 12) on Pineda and then on Mesa's llvmpipe (the system libGL.so.1 with
# LIBGL_ALWAYS_SOFTWARE=1), in the same Xvfb, and prints both frame rates (glxgears' own
# "frames in 5.0 seconds" reports; the first report of each run is left out as warm-up when
# there are several). The window of each is grabbed at the end as OUT/pineda.png and
# OUT/llvmpipe.png, by the same X-side grab for both. Starts its own Xvfb when DISPLAY is
# not set. Needs the build's libraries and bin/pineda-x11grab.
set -eu

seconds=12
build=build
out=out/glxgears-fps
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) seconds=$1; shift ;;
  esac
done

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
case "$build" in /*) ;; *) build="$root/$build" ;; esac
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$0" "$seconds" --build "$build" --out "$out"
fi
command -v glxgears > /dev/null || { echo "glxgears not found (apt-get install mesa-utils)" >&2; exit 2; }
grab="$build/bin/pineda-x11grab"
[ -x "$grab" ] || { echo "$grab not found: cmake --build $build --target pineda-x11grab" >&2; exit 2; }
mkdir -p "$out"

# run NAME COMMAND...: glxgears for $seconds, its window grabbed just before it is stopped.
run() {
  name=$1
  shift
  "$@" glxgears -info > "$out/$name.log" 2>&1 &
  pid=$!
  sleep "$seconds"
  "$grab" glxgears "$out/$name.png" || echo "($name: no window to grab)" >&2
  kill "$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null || true
}

# The mean of glxgears' FPS reports, without the first when there are several.
fps() {
  awk '/frames in .* seconds =/ { v[n++] = $(NF-1) }
       END { s = 0; c = 0; for (i = (n > 1); i < n; i++) { s += v[i]; c++ }
             if (c) printf "%.1f", s / c; else printf "n/a" }' "$1"
}

renderer() {
  sed -n 's/^GL_RENDERER *= *//p' "$1" | head -n 1
}

run pineda env PINEDA_LIB_DIR="$build/lib" "$here/pineda-run"
run llvmpipe env LIBGL_ALWAYS_SOFTWARE=1

echo "glxgears, ${seconds} s each, 300x300, same Xvfb:"
printf "  %-9s %8s FPS  (%s)  %s\n" pineda "$(fps "$out/pineda.log")" "$(renderer "$out/pineda.log")" "$out/pineda.png"
printf "  %-9s %8s FPS  (%s)  %s\n" llvmpipe "$(fps "$out/llvmpipe.log")" "$(renderer "$out/llvmpipe.log")" "$out/llvmpipe.png"
