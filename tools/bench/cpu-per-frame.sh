#!/usr/bin/env bash
# CPU time per frame of one pineda-bench scene, one thread, on Pineda and on llvmpipe: the user +
# system time of `pineda-bench --scene SCENE --frames N` less that of `--frames 1`, divided by
# N - 1 (set-up, the warm-up frame and the PNG are in both runs, so they cancel). On a machine
# shared with other work this is steadier than the wall clock `--compare llvmpipe` reports.
# Pineda runs from LIB (default build/lib, PINEDA_THREADS=1); llvmpipe is the system's libEGL
# without LD_LIBRARY_PATH (LP_NUM_THREADS=1, chosen as `pineda-bench --compare` chooses it).
# Usage: tools/bench/cpu-per-frame.sh SCENE [N] [LIB]    e.g. tools/bench/cpu-per-frame.sh wireframe 201
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
scene=${1:?usage: tools/bench/cpu-per-frame.sh SCENE [N] [LIB]}
frames=${2:-41}
lib=${3:-$root/build/lib}
bench=$root/build/bin/pineda-bench
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# CPU seconds of one run on DRIVER (pineda or llvmpipe) rendering FRAMES frames.
cpu_seconds() {
  local env=(LP_NUM_THREADS=1 LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless)
  [ "$1" = pineda ] && env=(PINEDA_THREADS=1 "LD_LIBRARY_PATH=$lib")
  local TIMEFORMAT='%U %S'  # bash's own `time`: the child's user and system seconds
  { time env "${env[@]}" "$bench" --scene "$scene" --frames "$2" --out "$out" >/dev/null 2>&1; } 2>"$out/time"
  awk '{print $1 + $2}' "$out/time"
}

declare -A ms
for driver in pineda llvmpipe; do
  one=$(cpu_seconds "$driver" 1)
  many=$(cpu_seconds "$driver" "$frames")
  ms[$driver]=$(awk -v a="$one" -v b="$many" -v n="$frames" 'BEGIN {printf "%.2f", (b - a) * 1000 / (n - 1)}')
done
awk -v s="$scene" -v p="${ms[pineda]}" -v l="${ms[llvmpipe]}" \
  'BEGIN {printf "%-20s Pineda %7.2f ms  llvmpipe %7.2f ms  ratio %.2f\n", s, p, l, (p > 0 ? l / p : 0)}'
