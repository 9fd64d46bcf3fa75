// Shared helpers of the raster tests: an owned framebuffer and vertex builders.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "raster/renderer.h"

namespace pineda::raster::test {

struct OwnedFramebuffer {
  OwnedFramebuffer(int w, int h, int depth_bits = 24, bool stencil = true, ColorFormat format = ColorFormat::RGBA8)
      : color(static_cast<size_t>(w) * h * 4), depth(static_cast<size_t>(w) * h), stencil_buf(static_cast<size_t>(w) * h) {
    fb.width = w;
    fb.height = h;
    fb.color = {color.data(), static_cast<ptrdiff_t>(w) * 4, format, {}, 0};
    if (depth_bits) fb.depth = {depth.data(), w, depth_bits};
    if (stencil) fb.stencil = {stencil_buf.data(), w, 8};
  }
  const uint8_t* pixel(int x, int y) const { return &color[(static_cast<size_t>(y) * fb.width + x) * 4]; }
  uint32_t depth_at(int x, int y) const { return depth[static_cast<size_t>(y) * fb.width + x]; }
  uint8_t stencil_at(int x, int y) const { return stencil_buf[static_cast<size_t>(y) * fb.width + x]; }
  int count_nonzero_red() const {
    int n = 0;
    for (size_t i = 0; i < color.size(); i += 4) n += color[i] != 0;
    return n;
  }
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil_buf;
  Framebuffer fb;
};

inline ClipVertex vertex(float x, float y, float z = 0.f, float w = 1.f, float r = 1.f, float g = 1.f,
                         float b = 1.f, float a = 1.f) {
  ClipVertex v{};
  v.clip[0] = x;
  v.clip[1] = y;
  v.clip[2] = z;
  v.clip[3] = w;
  const float c[4] = {r, g, b, a};
  for (int i = 0; i < 4; ++i) v.color[i] = v.back_color[i] = c[i];
  for (auto& tc : v.texcoord) {
    tc[0] = tc[1] = tc[2] = 0.f;
    tc[3] = 1.f;
  }
  v.edge_flag = true;
  return v;
}

// A vertex at window position (x, y) for a viewport equal to a w x h framebuffer.
inline ClipVertex window_vertex(double x, double y, int w, int h, float z = 0.f) {
  return vertex(static_cast<float>(x * 2.0 / w - 1.0), static_cast<float>(y * 2.0 / h - 1.0), z);
}

inline DrawState state_for(int w, int h) {
  DrawState s;
  s.viewport = {0, 0, w, h, 0.0, 1.0};
  s.cull_back = false;
  return s;
}

inline void clear_all(Renderer& r, float red = 0.f, double depth = 1.0, int stencil = 0) {
  ClearState c;
  c.color = c.depth = c.stencil = true;
  c.color_value[0] = red;
  c.depth_value = depth;
  c.stencil_value = stencil;
  r.clear(c);
}

// The reference coverage of a size x size window: snapped vertices (1/256 px), edge functions at
// every pixel centre, pixel centres on an edge belong to the triangle when the edge is a left
// edge or a bottom edge (y up). 1 where covered, row by row.
inline std::vector<uint8_t> reference_triangle_coverage(const int64_t x[3], const int64_t y[3], int size) {
  std::vector<uint8_t> out(static_cast<size_t>(size) * size, 0);
  int64_t px[3] = {x[0], x[1], x[2]}, py[3] = {y[0], y[1], y[2]};
  const int64_t area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
  if (area == 0) return out;
  if (area < 0) {
    std::swap(px[1], px[2]);
    std::swap(py[1], py[2]);
  }
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const int64_t cx = i * 256 + 128, cy = j * 256 + 128;
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) {
        const int64_t x0 = px[e], y0 = py[e], x1 = px[(e + 1) % 3], y1 = py[(e + 1) % 3];
        // Positive on the left of the directed edge, i.e. inside a counter-clockwise triangle.
        const int64_t v = (x1 - x0) * (cy - y0) - (y1 - y0) * (cx - x0);
        const bool left_or_bottom = (y1 < y0) || (y1 == y0 && x1 > x0);
        inside = left_or_bottom ? v >= 0 : v > 0;
      }
      out[static_cast<size_t>(j) * size + i] = inside;
    }
  return out;
}

}  // namespace pineda::raster::test
