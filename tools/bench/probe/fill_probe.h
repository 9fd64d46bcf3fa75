#pragma once
// Limit probes for pineda-bench's fill-bound scenes: hand-written loops that do the same memory
// work per pixel as a scene's frame (the same buffers, layers, tests and writes, in 64x64 tiles
// that stay in cache across the layers, as Pineda's binned rasterizer visits them), with none of
// a driver's work (no GL state, geometry, setup, coverage or dispatch). A scene's time against
// its probe's says how far the driver is from what the machine can do.
#include <cstdint>
#include <vector>

namespace pineda::bench::probe {

constexpr int kTileSize = 64;

// A frame's buffers: RGBA8 colour and 32-bit depth, rows bottom first.
struct FrameBuffers {
  int width, height;
  std::vector<std::uint32_t> color, depth;
  FrameBuffers(int w, int h) : width(w), height(h), color(std::size_t(w) * h), depth(std::size_t(w) * h) {}
};

// pineda-bench's `overdraw` frame: clear colour and depth, 32 tilted full-screen layers front to
// back with GL_LESS (nearly all fail), clear depth, the same 32 back to front (all pass).
void overdraw_frame(FrameBuffers& fb, int frame);
// pineda-bench's `blend` frame: clear, 32 full-screen layers of interpolated RGBA blended
// SRC_ALPHA / ONE_MINUS_SRC_ALPHA into RGBA8 with alpha writes masked.
void blend_frame(FrameBuffers& fb, int frame);

}  // namespace pineda::bench::probe
