#!/bin/bash
# games-side-by-side.sh [SECONDS] [--build DIR] [--out DIR] [GAME...]: real programs nobody here
# wrote: Debian's OpenGL games (default chromium-bsu neverball armagetronad etr; `apt-get install
# chromium-bsu neverball armagetronad extremetuxracer`, not installed by the scripts) each run
# untouched for SECONDS (default 20: their menus animate a scene) on Pineda (DIR/lib, default
# build/lib), then on Mesa's llvmpipe, in one Xvfb of 1024x768. Prints per game and driver whether
# it still ran when stopped (ran) or ended before (ENDED), and writes the screen three seconds
# before the stop as OUT/GAME.pineda.png and OUT/GAME.llvmpipe.png (default out/games) with
# DIR/bin/pineda-x11grab.
set -u
seconds=20
build=build
out=out/games
games=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    [0-9]*) seconds=$1; shift ;;
    *) games+=("$1"); shift ;;
  esac
done
[ ${#games[@]} -gt 0 ] || games=(chromium-bsu neverball armagetronad etr)
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
case "$build" in /*) ;; *) build="$root/$build" ;; esac
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1024x768x24 -noreset" "$0" "$seconds" --build "$build" --out "$out" "${games[@]}"
fi
[ -f "$build/lib/libGL.so.1" ] || { echo "$build/lib/libGL.so.1 not found: build Pineda first" >&2; exit 2; }
[ "$seconds" -ge 5 ] || { echo "SECONDS: at least 5" >&2; exit 2; }
mkdir -p "$out"

# run DRIVER GAME: prints ran or ENDED, and the grab's outcome when it failed.
run() {
  local program
  program=$(command -v "$2" || echo "/usr/games/$2")
  [ -x "$program" ] || { echo "not installed"; return; }
  if [ "$1" = pineda ]; then
    LD_LIBRARY_PATH="$build/lib" timeout -s KILL "$seconds" "$program" > "$out/$2.$1.log" 2>&1 &
  else
    LIBGL_ALWAYS_SOFTWARE=1 timeout -s KILL "$seconds" "$program" > "$out/$2.$1.log" 2>&1 &
  fi
  local pid=$!
  sleep $((seconds - 3))
  local grab
  grab=$("$build/bin/pineda-x11grab" --root "$out/$2.$1.png" 2>&1) || grab="no picture: $grab"
  wait "$pid"
  local status=$?
  if [ $status -eq 137 ]; then echo "ran $grab"; else echo "ENDED ($status) $grab"; fi
}

printf '%-14s %-30s %s\n' game pineda llvmpipe
for g in "${games[@]}"; do
  printf '%-14s %-30s %s\n' "$g" "$(run pineda "$g")" "$(run llvmpipe "$g")"
done
echo "pictures: $out/GAME.{pineda,llvmpipe}.png"
