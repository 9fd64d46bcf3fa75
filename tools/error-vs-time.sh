#!/usr/bin/env bash
# Error against run time: renders each pineda-bench scene with every setting of Pineda that
# trades accuracy for speed, times it and measures its image error against the reference
# mode (PINEDA_REFERENCE=1), then writes a table per scene (Markdown) and a plot of error
# against time (PNG, gnuplot; installed with apt-get when missing).
# Usage: tools/error-vs-time.sh [--size WxH] [--frames N] [--build DIR] [--out DIR] [--scene NAME]...
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PINEDA_BUILD:-$root/build}
size=512x384
frames=5
out=$root/out/error-vs-time
scenes=
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --build) build=$(cd "$2" && pwd); shift 2 ;;
    --out) out=$2; shift 2 ;;
    --scene) scenes="$scenes $2"; shift 2 ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) echo "error-vs-time: unknown option $1" >&2; exit 2 ;;
  esac
done

bench=$build/bin/pineda-bench
imgdiff=$build/bin/pineda-imgdiff
for f in "$bench" "$imgdiff" "$build/lib/libEGL.so.1"; do
  if [ ! -e "$f" ]; then
    echo "error-vs-time: missing $f; build first: cmake --build $build --target pineda pineda-bench pineda-imgdiff" >&2
    exit 2
  fi
done
if ! command -v gnuplot >/dev/null; then
  echo "installing gnuplot-nox"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends gnuplot-nox >/dev/null ||
    { apt-get update -q >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends gnuplot-nox >/dev/null; } ||
    echo "error-vs-time: gnuplot could not be installed; the table is still written" >&2
fi
[ -n "$scenes" ] || scenes="overdraw blend small_tris textured lit_mesh gears state_changes"

# Every setting that trades accuracy for speed: name and environment. The reference mode is
# the ground truth (its error is 0 by definition); the others are the fast path's knobs.
settings=(
  "reference|PINEDA_REFERENCE=1"
  "threads=1,simd=baseline|PINEDA_THREADS=1 PINEDA_SIMD=baseline"
  "threads=1,simd=best|PINEDA_THREADS=1"
  "threads=2,simd=baseline|PINEDA_THREADS=2 PINEDA_SIMD=baseline"
  "threads=2,simd=best|PINEDA_THREADS=2"
)

mkdir -p "$out"
data=$out/points.dat
table=$out/table.md
: >"$data"
{
  echo "size $size, median of $frames frames after a warm-up frame; error against PINEDA_REFERENCE=1's frame 0."
  echo "Timings are wall-clock on a shared 2-core machine (other builds running): noisy, compare within one scene."
  echo
} >"$table"
status=0
for scene in $scenes; do
  {
    echo "### $scene"
    echo
    echo "| setting | ms/frame | first ms | max diff | differ % | PSNR dB |"
    echo "| --- | --- | --- | --- | --- | --- |"
  } >>"$table"
  for s in "${settings[@]}"; do
    name=${s%%|*}
    env_vars=${s#*|}
    dir=$out/$name
    mkdir -p "$dir"
    # shellcheck disable=SC2086
    line=$(env -u LD_PRELOAD LD_LIBRARY_PATH="$build/lib" $env_vars "$bench" --child "$scene" --size "$size" \
      --frames "$frames" --out "$dir" 2>/dev/null | grep '^pineda-bench-result')
    if [ -z "$line" ]; then
      echo "| $name | FAILED | | | | |" >>"$table"
      status=1
      continue
    fi
    read -r _ _ ms first _ <<<"$line"
    diff_out=$("$imgdiff" "$dir/$scene.png" "$out/reference/$scene.png" 2>&1)
    max=$(sed -n 's/^max channel difference: //p' <<<"$diff_out")
    differ=$(sed -n 's/^pixels differing: \(.*\)%$/\1/p' <<<"$diff_out")
    psnr=$(sed -n 's/^PSNR: \(.*\) dB$/\1/p' <<<"$diff_out")
    printf '| %s | %.2f | %.2f | %s | %s | %s |\n' "$name" "$ms" "$first" "${max:--}" "${differ:--}" "${psnr:--}" >>"$table"
    printf '%s\t%s\t%s\t%s\t%s\n' "$scene" "$name" "$ms" "${differ:-0}" "${max:-0}" >>"$data"
    echo "$scene $name: $ms ms, max diff ${max:--}, differ ${differ:--}%, PSNR ${psnr:--}"
  done
  echo >>"$table"
done

plot=$out/error-vs-time.png
if command -v gnuplot >/dev/null; then
  plot_cmds="set terminal pngcairo size 1100,700 noenhanced; set output '$plot';"
  plot_cmds+="set title 'Pineda: image error against the reference mode vs time per frame ($size)';"
  plot_cmds+="set xlabel 'ms per frame (log)'; set logscale x; set ylabel 'pixels differing from PINEDA_REFERENCE=1 (%)';"
  plot_cmds+="set key outside right; set grid; set datafile separator '\t'; plot "
  first=1
  for scene in $scenes; do
    [ $first = 1 ] || plot_cmds+=", "
    first=0
    plot_cmds+="'< grep \"^$scene	\" $data' using 3:4 with linespoints title '$scene', "
    plot_cmds+="'< grep \"^$scene	\" $data' using 3:4:2 with labels offset 0,0.7 font ',7' notitle"
  done
  gnuplot -e "$plot_cmds" && echo "plot: $plot"
fi
echo "table: $table"
exit $status
