#!/usr/bin/env bash
# Installs what building and testing Pineda needs on a fresh Debian 12 machine.
set -euo pipefail
packages=(
  build-essential cmake pkg-config python3 git
  khronos-api librust-khronos-api-dev   # gl.xml (khronos-api) and egl.xml (the registry crate's copy)
  libegl-dev libgl-dev libgles-dev mesa-common-dev libosmesa6-dev libglvnd-core-dev libopengl-dev libx11-dev libxext-dev mesa-utils
  xvfb xauth   # xvfb-run needs xauth, which xvfb only recommends (and we install without recommends)
  piglit waffle-utils   # conformance/run.py (piglit only recommends waffle-utils, whose wflinfo its runner calls)
  libglm-dev libpng-dev libgtest-dev googletest
  glslang-dev glslang-tools   # shader/: the GLSL front end (its CMake files need the tools package)
  clang libclang-rt-dev   # the sanitizer build and the fuzz targets (libclang-rt-dev: ASan, UBSan, libFuzzer; clang's packages only recommend it)
  freeglut3-dev libglfw3-dev libsdl2-dev apitrace apitrace-tracers   # the X program tests (tests/x11apps)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
