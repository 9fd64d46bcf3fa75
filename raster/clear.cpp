#include "raster/clear.h"

#include <algorithm>
#include <cmath>

#include "raster/fragment_ops.h"
#include "raster/raster_limits.h"

namespace pineda::raster {

bool make_clear_record(const ClearState& clear, const Framebuffer& fb, ClearRecord& out) {
  out.rect = {0, 0, std::min(fb.width, kMaxRenderSize), std::min(fb.height, kMaxRenderSize)};
  if (clear.scissor_test) {
    const Rect& s = clear.scissor;
    const PixelRect sc{s.x, s.y, static_cast<int>(std::clamp<int64_t>(int64_t{s.x} + s.width, INT32_MIN, INT32_MAX)),
                       static_cast<int>(std::clamp<int64_t>(int64_t{s.y} + s.height, INT32_MIN, INT32_MAX))};
    out.rect = intersect(out.rect, sc);
  }
  if (out.rect.empty()) return false;
  const bool any_color_write = clear.color_write[0] || clear.color_write[1] || clear.color_write[2] || clear.color_write[3];
  out.color = clear.color && fb.color.base && any_color_write;
  out.depth = clear.depth && clear.depth_write && fb.depth.base && fb.depth.bits > 0;
  out.stencil = clear.stencil && fb.stencil.base && fb.stencil.bits > 0 && clear.stencil_write_mask != 0;
  for (int c = 0; c < 4; ++c) {
    out.rgba[c] = to_unorm8(clear.color_value[c]);
    out.color_write[c] = clear.color_write[c];
  }
  if (out.depth) {
    const double max = fb.depth.bits >= 32 ? 4294967295.0 : static_cast<double>((uint64_t{1} << fb.depth.bits) - 1);
    double z = clear.depth_value;
    z = z > 0.0 ? (z < 1.0 ? z : 1.0) : 0.0;
    out.depth_value = static_cast<uint32_t>(z * max + 0.5);
  }
  out.stencil_value = static_cast<uint8_t>(clear.stencil_value);
  out.stencil_write_mask = clear.stencil_write_mask;
  return out.color || out.depth || out.stencil;
}

void apply_clear(const ClearRecord& clear, const Framebuffer& fb, const PixelRect& tile) {
  const PixelRect r = intersect(clear.rect, tile);
  if (r.empty()) return;
  if (clear.color) {
    const bool bgra = fb.color.format == ColorFormat::BGRA8;
    uint8_t bytes[4] = {clear.rgba[0], clear.rgba[1], clear.rgba[2], clear.rgba[3]};
    bool write[4] = {clear.color_write[0], clear.color_write[1], clear.color_write[2], clear.color_write[3]};
    if (bgra) {
      std::swap(bytes[0], bytes[2]);
      std::swap(write[0], write[2]);
    }
    for (int y = r.y0; y < r.y1; ++y) {
      uint8_t* row = fb.color.base + static_cast<ptrdiff_t>(y) * fb.color.stride;
      for (int x = r.x0; x < r.x1; ++x)
        for (int c = 0; c < 4; ++c)
          if (write[c]) row[x * 4 + c] = bytes[c];
    }
  }
  if (clear.depth) {
    for (int y = r.y0; y < r.y1; ++y) {
      uint32_t* row = fb.depth.base + static_cast<ptrdiff_t>(y) * fb.depth.stride;
      std::fill(row + r.x0, row + r.x1, clear.depth_value);
    }
  }
  if (clear.stencil) {
    const uint8_t m = clear.stencil_write_mask;
    for (int y = r.y0; y < r.y1; ++y) {
      uint8_t* row = fb.stencil.base + static_cast<ptrdiff_t>(y) * fb.stencil.stride;
      for (int x = r.x0; x < r.x1; ++x) row[x] = static_cast<uint8_t>((row[x] & ~m) | (clear.stencil_value & m));
    }
  }
}

}  // namespace pineda::raster
