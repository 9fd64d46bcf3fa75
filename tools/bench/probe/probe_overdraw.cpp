#include <algorithm>

#include "fill_probe.h"

namespace pineda::bench::probe {
namespace {

constexpr int kLayersPerPass = 32;
constexpr double kDepthScale = 16777215.0;  // 24-bit depth values

// A layer's window depth as a plane in 24-bit integers stepped per pixel, and its colour.
struct Layer {
  std::int32_t z_at_origin, dz_dx, dz_dy;
  std::uint32_t color;
};

// The layers of pineda-bench's overdraw scene (tools/bench/scene_overdraw.cpp) at this size:
// normalized-device depth base + tiltX (x + shift) + tiltY y, mapped to [0, 1].
Layer make_layer(int i, int frame, int width, int height, bool second_pass) {
  const double shift = 0.01 * double(frame % 16);
  const double base = -0.8 + 1.6 * double(i) / double(kLayersPerPass - 1);
  const double tilt_x = (i % 3 - 1) * 0.1, tilt_y = (i % 2 ? 0.08 : -0.08);
  // ndc x = 2 (px + 0.5) / width - 1; window z = (ndc z + 1) / 2.
  const double dz_dx = tilt_x * 2.0 / width * 0.5, dz_dy = tilt_y * 2.0 / height * 0.5;
  const double z0 = (base + tilt_x * (-1.0 + 1.0 / width + shift) + tilt_y * (-1.0 + 1.0 / height) + 1.0) * 0.5;
  const int tint = second_pass ? 0 : 100;
  const std::uint32_t r = 55 + (i * 97 + tint) % 200, g = 55 + (i * 57 + tint) % 200, b = 55 + (i * 29 + tint) % 200;
  return {std::int32_t(z0 * kDepthScale), std::int32_t(dz_dx * kDepthScale), std::int32_t(dz_dy * kDepthScale),
          r | g << 8 | b << 16 | 0xffu << 24};
}

// One layer over one tile of n x rows pixels (`stride` pixels apart): depth test GL_LESS,
// masked depth and colour writes.
__attribute__((target_clones("avx512f", "avx2", "default"))) void depth_tile(
    std::uint32_t* __restrict color, std::uint32_t* __restrict depth, int n, int rows, int stride, std::int32_t z,
    std::int32_t dz_dx, std::int32_t dz_dy, std::uint32_t c) {
  for (int y = 0; y < rows; ++y, z += dz_dy, color += stride, depth += stride)
    for (int x = 0; x < n; ++x) {
      const std::uint32_t fragment = std::uint32_t(z + dz_dx * x);
      const bool pass = fragment < depth[x];
      depth[x] = pass ? fragment : depth[x];
      color[x] = pass ? c : color[x];
    }
}

void fill_rect(std::vector<std::uint32_t>& buffer, int width, int x0, int y0, int x1, int y1, std::uint32_t value) {
  for (int y = y0; y < y1; ++y) std::fill(&buffer[std::size_t(y) * width + x0], &buffer[std::size_t(y) * width + x1], value);
}

}  // namespace

void overdraw_frame(FrameBuffers& fb, int frame) {
  Layer front_to_back[kLayersPerPass], back_to_front[kLayersPerPass];
  for (int i = 0; i < kLayersPerPass; ++i) {
    front_to_back[i] = make_layer(i, frame, fb.width, fb.height, false);
    back_to_front[i] = make_layer(kLayersPerPass - 1 - i, frame, fb.width, fb.height, true);
  }
  for (int ty = 0; ty < fb.height; ty += kTileSize)
    for (int tx = 0; tx < fb.width; tx += kTileSize) {
      const int x1 = std::min(tx + kTileSize, fb.width), y1 = std::min(ty + kTileSize, fb.height);
      const auto pass = [&](const Layer* layers) {
        const std::size_t corner = std::size_t(ty) * fb.width + tx;
        for (int i = 0; i < kLayersPerPass; ++i) {
          const Layer& l = layers[i];
          depth_tile(&fb.color[corner], &fb.depth[corner], x1 - tx, y1 - ty, fb.width,
                     l.z_at_origin + l.dz_dx * tx + l.dz_dy * ty, l.dz_dx, l.dz_dy, l.color);
        }
      };
      fill_rect(fb.color, fb.width, tx, ty, x1, y1, 0xff000000u);
      fill_rect(fb.depth, fb.width, tx, ty, x1, y1, 0xffffffu);
      pass(front_to_back);
      fill_rect(fb.depth, fb.width, tx, ty, x1, y1, 0xffffffu);
      pass(back_to_front);
    }
}

}  // namespace pineda::bench::probe
