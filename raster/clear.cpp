#include "raster/clear.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <emmintrin.h>

#include "raster/color_reduction.h"
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
  bool any_color_write = false;
  for (int i = 0; i < fb.color_targets; ++i) {
    const std::array<bool, 4>& write = clear.color_write_of(fb.color_index + i);
    out.color_write[static_cast<size_t>(i)] = write;
    if (fb.target_color(i).base) any_color_write |= write[0] || write[1] || write[2] || write[3];
  }
  out.color = clear.color && any_color_write;
  out.depth = clear.depth && clear.depth_write && fb.depth.base && fb.depth.bits > 0;
  out.stencil = clear.stencil && fb.stencil.base && fb.stencil.bits > 0 && clear.stencil_write_mask != 0;
  for (int c = 0; c < 4; ++c) {
    out.rgba[c] = to_unorm8(clear.color_value[c]);
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

namespace {

// Stores the 32-bit `value` into [x0, x1) of every row of `r`, 16 bytes per store (unaligned:
// the buffer needs no particular alignment). Not memcpy from a pattern: for rows of a 64-pixel
// tile that became `rep movs`, whose start-up cost made the clear a sixth of a frame.
void fill_rows32(uint8_t* base, ptrdiff_t stride_bytes, const PixelRect& r, uint32_t value) {
  const __m128i v = _mm_set1_epi32(static_cast<int>(value));
  const int width = r.x1 - r.x0;
  for (int y = r.y0; y < r.y1; ++y) {
    uint8_t* row = base + static_cast<ptrdiff_t>(y) * stride_bytes + static_cast<ptrdiff_t>(r.x0) * 4;
    int x = 0;
    for (; x + 4 <= width; x += 4) _mm_storeu_si128(reinterpret_cast<__m128i*>(row + static_cast<ptrdiff_t>(x) * 4), v);
    for (; x < width; ++x) std::memcpy(row + static_cast<ptrdiff_t>(x) * 4, &value, 4);
  }
}

// As fill_rows32 for bytes (stencil values), 16 per store: a 64-byte row as `memset` calls took
// 2% of stencil_reflection's frame.
void fill_rows8(uint8_t* base, ptrdiff_t stride_bytes, const PixelRect& r, uint8_t value) {
  const __m128i v = _mm_set1_epi8(static_cast<char>(value));
  for (int y = r.y0; y < r.y1; ++y) {
    uint8_t* row = base + static_cast<ptrdiff_t>(y) * stride_bytes;
    int x = r.x0;
    for (; x + 16 <= r.x1; x += 16) _mm_storeu_si128(reinterpret_cast<__m128i*>(row + x), v);
    for (; x < r.x1; ++x) row[x] = value;
  }
}

// As fill_rows32, but only the bits of `write` change.
void fill_rows32_masked(uint8_t* base, ptrdiff_t stride_bytes, const PixelRect& r, uint32_t value, uint32_t write) {
  const uint32_t v = value & write;
  for (int y = r.y0; y < r.y1; ++y) {
    uint8_t* row = base + static_cast<ptrdiff_t>(y) * stride_bytes;
    for (int x = r.x0; x < r.x1; ++x) {
      uint32_t old;
      std::memcpy(&old, row + static_cast<ptrdiff_t>(x) * 4, 4);
      old = (old & ~write) | v;
      std::memcpy(row + static_cast<ptrdiff_t>(x) * 4, &old, 4);
    }
  }
}

// The clear colour into one colour buffer, in its byte order and format.
void clear_color(const ClearRecord& clear, const std::array<bool, 4>& mask, const ColorBuffer& cb, const PixelRect& r) {
  const bool bgra = cb.format == ColorFormat::BGRA8;
  uint8_t bytes[4] = {clear.rgba[0], clear.rgba[1], clear.rgba[2], clear.rgba[3]};
  bool write[4] = {mask[0], mask[1], mask[2], mask[3]};
  if (cb.reduction.active) reduce_bytes(cb.reduction, bytes);
  if (bgra) {
    std::swap(bytes[0], bytes[2]);
    std::swap(write[0], write[2]);
  }
  uint32_t value = 0, write_bits = 0;
  for (int c = 0; c < 4; ++c) {
    value |= uint32_t{bytes[c]} << (8 * c);
    if (write[c]) write_bits |= 0xffu << (8 * c);
  }
  if (write_bits == 0) return;
  if (write_bits == 0xffffffffu) fill_rows32(cb.base, cb.stride, r, value);
  else fill_rows32_masked(cb.base, cb.stride, r, value, write_bits);
}

}  // namespace

void apply_clear(const ClearRecord& clear, const Framebuffer& fb, const PixelRect& tile) {
  const PixelRect r = intersect(clear.rect, tile);
  if (r.empty()) return;
  if (clear.color)
    for (int i = 0; i < fb.color_targets; ++i)  // every draw buffer
      if (fb.target_color(i).base) clear_color(clear, clear.color_write[static_cast<size_t>(i)], fb.target_color(i), r);
  if (clear.depth) {
    const ptrdiff_t stride_bytes = fb.depth.stride * static_cast<ptrdiff_t>(sizeof(uint32_t));
    fill_rows32(reinterpret_cast<uint8_t*>(fb.depth.base), stride_bytes, r, clear.depth_value);
  }
  if (clear.stencil) {
    const uint8_t m = clear.stencil_write_mask;
    if (m == 0xff) return fill_rows8(fb.stencil.base, fb.stencil.stride, r, clear.stencil_value);
    for (int y = r.y0; y < r.y1; ++y) {
      uint8_t* row = fb.stencil.base + static_cast<ptrdiff_t>(y) * fb.stencil.stride;
      for (int x = r.x0; x < r.x1; ++x) row[x] = static_cast<uint8_t>((row[x] & ~m) | (clear.stencil_value & m));
    }
  }
}

}  // namespace pineda::raster
