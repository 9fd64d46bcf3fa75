#include <algorithm>
#include <cmath>

#include "fill_probe.h"

namespace pineda::bench::probe {
namespace {

constexpr int kLayers = 32;

// A layer's RGBA as planes in 8.16 fixed point over the window (the colour interpolated across
// the full-screen quad; a bilinear corner blend is not affine, so the probe uses the plane through
// three corners, which costs the same per pixel).
struct Layer {
  std::int32_t at_origin[4], d_dx[4], d_dy[4];
};

Layer make_layer(int i, int frame, int width, int height) {
  const float phase = 0.4f * float(i) + 0.05f * float(frame);
  const auto corner = [&](float offset, int channel) {
    const float a = phase + offset;
    switch (channel) {
      case 0: return 0.5f + 0.5f * std::sin(a);
      case 1: return 0.5f + 0.5f * std::sin(a + 2.1f);
      case 2: return 0.5f + 0.5f * std::sin(a + 4.2f);
      default: return 0.05f + 0.25f * (0.5f + 0.5f * std::cos(a * 1.3f));
    }
  };
  Layer l;
  for (int c = 0; c < 4; ++c) {
    const float bottom_left = corner(0.0f, c), bottom_right = corner(1.5f, c), top_left = corner(4.5f, c);
    const float scale = 255.0f * 65536.0f;
    l.at_origin[c] = std::int32_t(bottom_left * scale);
    l.d_dx[c] = std::int32_t((bottom_right - bottom_left) / float(width) * scale);
    l.d_dy[c] = std::int32_t((top_left - bottom_left) / float(height) * scale);
  }
  return l;
}

// (v + 127.5) / 255 rounded, exact for v in [0, 255 * 255].
inline std::uint32_t div255(std::uint32_t v) { return (v + 128 + ((v + 128) >> 8)) >> 8; }

// One layer over one tile of n x rows pixels (`stride` pixels apart): SRC_ALPHA /
// ONE_MINUS_SRC_ALPHA, destination alpha kept.
__attribute__((target_clones("avx512f", "avx2", "default"))) void blend_tile(std::uint32_t* __restrict color, int n,
                                                                            int rows, int stride, const Layer& l,
                                                                            int tx, int ty) {
  for (int y = 0; y < rows; ++y, color += stride) {
    std::int32_t start[4];
    for (int c = 0; c < 4; ++c) start[c] = l.at_origin[c] + l.d_dx[c] * tx + l.d_dy[c] * (ty + y);
    for (int x = 0; x < n; ++x) {
      const std::uint32_t r = std::uint32_t(start[0] + l.d_dx[0] * x) >> 16, g = std::uint32_t(start[1] + l.d_dx[1] * x) >> 16;
      const std::uint32_t b = std::uint32_t(start[2] + l.d_dx[2] * x) >> 16, a = std::uint32_t(start[3] + l.d_dx[3] * x) >> 16;
      const std::uint32_t dst = color[x];
      const std::uint32_t out_r = div255(r * a + (dst & 0xff) * (255 - a));
      const std::uint32_t out_g = div255(g * a + (dst >> 8 & 0xff) * (255 - a));
      const std::uint32_t out_b = div255(b * a + (dst >> 16 & 0xff) * (255 - a));
      color[x] = out_r | out_g << 8 | out_b << 16 | (dst & 0xff000000u);
    }
  }
}

}  // namespace

void blend_frame(FrameBuffers& fb, int frame) {
  Layer layers[kLayers];
  for (int i = 0; i < kLayers; ++i) layers[i] = make_layer(i, frame, fb.width, fb.height);
  const std::uint32_t clear = 26u | 26u << 8 | 38u << 16 | 0xffu << 24;  // glClearColor(0.1, 0.1, 0.15, 1)
  for (int ty = 0; ty < fb.height; ty += kTileSize)
    for (int tx = 0; tx < fb.width; tx += kTileSize) {
      const int x1 = std::min(tx + kTileSize, fb.width), y1 = std::min(ty + kTileSize, fb.height);
      for (int y = ty; y < y1; ++y)
        std::fill(&fb.color[std::size_t(y) * fb.width + tx], &fb.color[std::size_t(y) * fb.width + x1], clear);
      for (const Layer& l : layers)
        blend_tile(&fb.color[std::size_t(ty) * fb.width + tx], x1 - tx, y1 - ty, fb.width, l, tx, ty);
    }
}

}  // namespace pineda::bench::probe
