#!/usr/bin/env bash
# The main job: builds Pineda and renders the demo scenes headless (EGL, no X, no GPU)
# into PNG files, printing where they are and the time per frame.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh" "$root/build"
out=${PINEDA_DEMO_OUT:-$root/out/demo}
mkdir -p "$out"
LD_LIBRARY_PATH="$root/build/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
  "$root/build/bin/pineda-demo" --out "$out" --frames "${PINEDA_DEMO_FRAMES:-20}" "$@"
echo "demo images: $out"
