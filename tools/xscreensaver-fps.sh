#!/bin/bash
# xscreensaver-fps.sh [SECONDS] [--build DIR] [HACK...]: real programs nobody here wrote, side by
# side: each OpenGL hack of Debian's xscreensaver-gl (all of /usr/libexec/xscreensaver that link
# libEGL, or the HACKs named) runs with -delay 0 for SECONDS (default 4) on Pineda, then on Mesa's
# llvmpipe, both with one thread, in one Xvfb. Prints per hack the frames per second of each (swaps
# after the first over the time between them, counted by tools/swap_counter) and their ratio; a
# hack that swapped at most once is marked DIED or STALLED. Starts its own Xvfb when DISPLAY is
# not set. Needs a C compiler for the counter and `apt-get install xscreensaver-gl`.
set -u

seconds=4
build=build
hacks=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    [0-9]*) seconds=$1; shift ;;
    *) hacks+=("$1"); shift ;;
  esac
done

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
case "$build" in /*) ;; *) build="$root/$build" ;; esac
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1024x768x24 -noreset" "$0" "$seconds" --build "$build" "${hacks[@]}"
fi
libexec=/usr/libexec/xscreensaver
[ -d "$libexec" ] || { echo "$libexec not found (apt-get install xscreensaver-gl)" >&2; exit 2; }
[ -f "$build/lib/libEGL.so.1" ] || { echo "$build/lib/libEGL.so.1 not found: build Pineda first" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc -shared -fPIC -O2 -o "$work/swap_counter.so" "$here/swap_counter/swap_counter.c" -ldl || exit 2
if [ ${#hacks[@]} -eq 0 ]; then
  for h in "$libexec"/*; do
    [ -x "$h" ] && [ -f "$h" ] && nm -D "$h" 2> /dev/null | grep -q ' U eglSwapBuffers' && hacks+=("$(basename "$h")")
  done
fi

# frames_per_second FILE: (swaps - 1) / seconds between the first and the last.
frames_per_second() {
  [ -s "$1" ] || { echo 0; return; }
  awk '{ if ($1 > 1 && $2 > 0) printf "%.1f", ($1 - 1) / $2; else print 0 }' "$1"
}

# run DRIVER HACK: the hack for $seconds; prints its frames per second, or DIED (it ended by
# itself) or STALLED (at most one swap).
run() {
  local count="$work/$1.count"
  rm -f "$count"
  if [ "$1" = pineda ]; then
    SWAPCOUNT_FILE=$count LD_PRELOAD="$work/swap_counter.so" PINEDA_THREADS=1 LD_LIBRARY_PATH="$build/lib" \
      timeout -s KILL "$seconds" "$libexec/$2" -delay 0 > "$work/$1.log" 2>&1
  else
    SWAPCOUNT_FILE=$count LD_PRELOAD="$work/swap_counter.so" LP_NUM_THREADS=1 LIBGL_ALWAYS_SOFTWARE=1 \
      timeout -s KILL "$seconds" "$libexec/$2" -delay 0 > "$work/$1.log" 2>&1
  fi
  local status=$? fps
  fps=$(frames_per_second "$count")
  if [ $status -ne 137 ]; then echo DIED
  elif [ "$fps" = 0 ]; then echo STALLED
  else echo "$fps"; fi
}

printf '%-18s %9s %9s %7s\n' hack pineda llvmpipe ratio
for h in "${hacks[@]}"; do
  p=$(run pineda "$h")
  l=$(run llvmpipe "$h")
  ratio=$(awk -v p="$p" -v l="$l" 'BEGIN { if (p + 0 > 0 && l + 0 > 0) printf "%.2f", p / l; else print "-" }')
  printf '%-18s %9s %9s %7s\n' "$h" "$p" "$l" "$ratio"
done
