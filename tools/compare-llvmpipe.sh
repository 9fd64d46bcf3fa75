#!/usr/bin/env bash
# Renders every demo scene on Pineda and on Mesa's llvmpipe, compares the images and prints
# a table of time per frame and image difference. Exits non-zero when a scene has fewer
# than 99.9% of its pixels within 1/255 of llvmpipe's (or fails to render).
# Usage: tools/compare-llvmpipe.sh [--size WxH] [--frames N] [--build DIR] [--scene NAME]...
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PINEDA_BUILD:-$root/build}
size=512x512
frames=10
scenes=
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --build) build=$(cd "$2" && pwd); shift 2 ;;
    --scene) scenes="$scenes $2"; shift 2 ;;
    -h|--help) sed -n '2,5p' "$0"; exit 0 ;;
    *) echo "compare-llvmpipe: unknown option $1" >&2; exit 2 ;;
  esac
done

demo=$build/bin/pineda-demo
imgdiff=$build/bin/pineda-imgdiff
for f in "$demo" "$imgdiff" "$build/lib/libEGL.so.1" "$build/lib/libGL.so.1"; do
  if [ ! -e "$f" ]; then
    echo "compare-llvmpipe: missing $f; build first: cmake --build $build" >&2
    exit 2
  fi
done

missing=()
for p in libegl-mesa0 libgl1-mesa-dri; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing llvmpipe: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q && apt-get install -y -q --no-install-recommends "${missing[@]}" || exit 2
fi

out=$root/out/compare
mkdir -p "$out/pineda" "$out/llvmpipe" "$out/diff"
rm -f "$out"/{pineda,llvmpipe,diff}/*.{png,log}

# Each scene runs in its own process so that a crash or hang costs only that scene.
render() {  # render DRIVER SCENE: prints "ms first_ms" or nothing on failure
  local driver=$1 scene=$2 log=$out/$1/$2.log
  local -a env_cmd
  if [ "$driver" = pineda ]; then
    env_cmd=(env LD_LIBRARY_PATH="$build/lib")
  else
    env_cmd=(env -u LD_LIBRARY_PATH -u LD_PRELOAD LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
             EGL_PLATFORM=surfaceless)
  fi
  timeout 300 "${env_cmd[@]}" "$demo" --out "$out/$driver" --size "$size" --frames "$frames" \
    --scene "$scene" >"$log" 2>&1
  awk -v s="$scene" '$1 == s && $2 ~ /\.png$/ { print $(NF-1), $NF }' "$log"
}

[ -n "$scenes" ] || scenes=$("$demo" --help | sed -n 's/^scenes: *//p')
renderer() { sed -n 's/^GL_RENDERER: //p' "$out/$1/$2.log" | head -1; }

failed=0
rows=()
for scene in $scenes; do
  read -r p_ms p_first <<<"$(render pineda "$scene")"
  read -r l_ms l_first <<<"$(render llvmpipe "$scene")"
  [ -z "${p_renderer:-}" ] && p_renderer=$(renderer pineda "$scene")
  [ -z "${l_renderer:-}" ] && l_renderer=$(renderer llvmpipe "$scene")
  ratio=- maxdiff=- within=- verdict=FAIL
  if [ -n "${p_ms:-}" ] && [ -n "${l_ms:-}" ]; then
    ratio=$(awk -v p="$p_ms" -v l="$l_ms" 'BEGIN { if (l > 0) printf "%.2f", p / l; else print "-" }')
    report=$("$imgdiff" "$out/pineda/$scene.png" "$out/llvmpipe/$scene.png" --diff "$out/diff/$scene.png")
    status=$?
    maxdiff=$(sed -n 's/^max channel difference: //p' <<<"$report")
    within=$(sed -n 's/^pixels within 1\/255: //p' <<<"$report")
    [ $status -eq 0 ] && verdict=pass
  else
    [ -z "${p_ms:-}" ] && echo "pineda failed on $scene: see $out/pineda/$scene.log" >&2
    [ -z "${l_ms:-}" ] && echo "llvmpipe failed on $scene: see $out/llvmpipe/$scene.log" >&2
  fi
  [ "$verdict" = pass ] || failed=1
  rows+=("$(printf '%-14s %10s %10s %7s %8s %10s  %s' "$scene" "${p_ms:--}" "${l_ms:--}" "$ratio" \
    "${maxdiff:--}" "${within:--}" "$verdict")")
  unset p_ms l_ms
done

echo "Pineda:   ${p_renderer:-?}"
echo "llvmpipe: ${l_renderer:-?}"
echo "size $size, median of $frames frames (draw + glFinish)"
printf '%-14s %10s %10s %7s %8s %10s  %s\n' scene "pineda ms" "llvmpipe" ratio "max diff" "within 1" result
printf '%s\n' "${rows[@]}"
echo "images: $out/{pineda,llvmpipe,diff}"
exit $failed
