#include "raster/tile_raster.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

#include "raster/edge_row_bound.h"
#include "raster/raster_limits.h"
#include "raster/sample_point.h"
#include "raster/setup.h"
#include "raster/shader_quads.h"
#include "raster/small_area_masks.h"
#include "raster/smooth_coverage.h"

namespace pineda::raster {
namespace {

// Quad pixels of (x, y) (even) that lie inside rect.
unsigned rect_mask(int x, int y, const PixelRect& r) {
  unsigned m = 0;
  for (int i = 0; i < 4; ++i) {
    const int px = x + (i & 1), py = y + (i >> 1);
    if (px >= r.x0 && px < r.x1 && py >= r.y0 && py < r.y1) m |= 1u << i;
  }
  return m;
}

// The smallest and largest edge value over the pixel centres of r.
void edge_range(const EdgeFunction& e, const PixelRect& r, int64_t& lo, int64_t& hi) {
  const int64_t base = edge_at(e, r.x0, r.y0);
  const int64_t sx = e.a * kSubpixelOne * (r.x1 - 1 - r.x0), sy = e.b * kSubpixelOne * (r.y1 - 1 - r.y0);
  lo = base + std::min<int64_t>(sx, 0) + std::min<int64_t>(sy, 0);
  hi = base + std::max<int64_t>(sx, 0) + std::max<int64_t>(sy, 0);
}

enum class BlockCover { None, Partial, Full };

BlockCover classify(const PrimSetup& p, const PixelRect& r) {
  bool full = true;
  for (const EdgeFunction& e : p.edges) {
    int64_t lo, hi;
    edge_range(e, r, lo, hi);
    if (hi < 0) return BlockCover::None;
    full &= lo >= 0;
  }
  return full ? BlockCover::Full : BlockCover::Partial;
}

// Collects the quad masks of one quad row and hands them to the fragment routine at once.
struct QuadSink {
  const PrimSetup& p;
  const DrawRecord& d;
  const Framebuffer& fb;
  ShaderQuadBatch* batch = nullptr;  // set: the rows go there, to be shaded later
  mutable uint64_t samples_passed = 0;
  void row(int x, int y, int count, const uint8_t* masks) const {
    // Skip empty quads at both ends.
    while (count > 0 && !masks[0]) {
      ++masks;
      x += 2;
      --count;
    }
    while (count > 0 && !masks[count - 1]) --count;
    if (count <= 0) return;
    if (batch) batch->add_row(d, p, fb, x, y, count, masks);
    else samples_passed += d.routine(d, p, fb, x, y, count, masks);
  }
};

constexpr int kMaxQuadsPerRow = kTileSize / 2;
constexpr int kBatchedWidth = 8;  // pixels: the widest primitives whose quads go to a ShaderQuadBatch

// Every quad of `block`, clipped to `clip`.
template <class Sink>
void emit_full(const PixelRect& block, const PixelRect& clip, const Sink& sink) {
  const int x0 = block.x0 & ~1;
  const int count = (block.x1 - x0 + 1) / 2;
  // The masks of quad rows whose two pixel rows are inside clip: the same for every such row.
  uint8_t inner[kMaxQuadsPerRow], masks[kMaxQuadsPerRow];
  for (int q = 0; q < count; ++q) {
    const int x = x0 + 2 * q;
    inner[q] = static_cast<uint8_t>((x >= clip.x0 && x < clip.x1 ? 5 : 0) | (x + 1 >= clip.x0 && x + 1 < clip.x1 ? 10 : 0));
  }
  for (int y = block.y0 & ~1; y < block.y1; y += 2) {
    if (y >= clip.y0 && y + 1 < clip.y1) {
      sink.row(x0, y, count, inner);
      continue;
    }
    for (int q = 0; q < count; ++q) masks[q] = static_cast<uint8_t>(rect_mask(x0 + 2 * q, y, clip));
    sink.row(x0, y, count, masks);
  }
}

// Lines, points and triangles covering part of a tile: a bit mask per row of the tile, then quads.
struct TileMask {
  // Only the area's rows are cleared: a line's or small triangle's area is often a few rows of
  // a tile (wireframe, one thread: 5.26-5.53 ms a frame before, 5.25-5.36 after).
  explicit TileMask(const PixelRect& a) : area(a) {
    std::memset(rows, 0, sizeof rows[0] * static_cast<size_t>(std::max(a.y1 - a.y0, 0)));
  }
  PixelRect area;
  uint64_t rows[kTileSize];  // rows[y - area.y0], for y in [area.y0, area.y1)
  void set(int x, int y) { rows[y - area.y0] |= uint64_t{1} << (x - area.x0); }
};

// A byte of a bit row as four quads' bits of that row: its pairs of bits one to a byte.
constexpr std::array<uint32_t, 256> kPairsToBytes = [] {
  std::array<uint32_t, 256> out{};
  for (uint32_t b = 0; b < 256; ++b)
    for (int k = 0; k < 4; ++k) out[b] |= ((b >> (2 * k)) & 3u) << (8 * k);
  return out;
}();

// Each quad row's quads from its first to its last covered one, their masks from two bit rows
// (four at a time).
template <class Sink>
void emit_mask(const TileMask& mask, const Sink& sink) {
  const PixelRect& area = mask.area;
  const int x0 = area.x0 & ~1;
  const int shift = area.x0 - x0;  // bit i of a shifted row is pixel x0 + i (an odd x0 leaves bit 63 free)
  auto bits = [&](int y) { return y >= area.y0 && y < area.y1 ? mask.rows[y - area.y0] << shift : 0; };
  uint8_t masks[kMaxQuadsPerRow + 3];  // (the last four may run past the row's quads: with zeros)
  for (int y = area.y0 & ~1; y < area.y1; y += 2) {
    const uint64_t r0 = bits(y), r1 = bits(y + 1);
    if (!(r0 | r1)) continue;
    const int q0 = __builtin_ctzll(r0 | r1) / 2, q1 = (63 - __builtin_clzll(r0 | r1)) / 2;
    const uint64_t row0 = r0 >> (2 * q0), row1 = r1 >> (2 * q0);
    const int count = q1 - q0 + 1;
    for (int k = 0; k < count; k += 4) {
      const uint32_t four = kPairsToBytes[(row0 >> (2 * k)) & 0xffu] | kPairsToBytes[(row1 >> (2 * k)) & 0xffu] << 2;
      std::memcpy(masks + k, &four, sizeof four);
    }
    sink.row(x0 + 2 * q0, y, count, masks);
  }
}

// The first pixel of the span across the line at major coordinate m (a column for x-major
// lines), for m = m0, m0 + 1, ...: the line's minor coordinate there, the ceiling of num / den,
// is stepped exactly in integers (quotient and remainder), one division for the first m only.
class SpanWalk {
 public:
  SpanWalk(const LineCoverage& l, int m0) : width_(l.width) {
    const int64_t c = int64_t{m0} * kSubpixelOne + kSubpixelHalf;
    const int64_t a0 = l.x_major ? l.x0 : l.y0, a1 = l.x_major ? l.x1 : l.y1;
    const int64_t b0 = l.x_major ? l.y0 : l.x0, b1 = l.x_major ? l.y1 : l.x1;
    int64_t num = b0 * (a1 - a0) + (c - a0) * (b1 - b0), den = a1 - a0, step = kSubpixelOne * (b1 - b0);
    if (den < 0) {
      num = -num;
      den = -den;
      step = -step;
    }
    den_ = den;
    minor_ = ceil_div(num, den);  // num = minor * den - rest, rest in [0, den)
    rest_ = minor_ * den - num;
    step_q_ = floor_div(step, den);  // step = step_q * den + step_r, step_r in [0, den)
    step_r_ = step - step_q_ * den;
  }
  // Pixels whose centre lies in [minor - width/2, minor + width/2), as llvmpipe's line quads.
  int64_t start() const { return ceil_div(minor_ - kSubpixelHalf * width_ - kSubpixelHalf, kSubpixelOne); }
  void next() {
    minor_ += step_q_;
    rest_ -= step_r_;
    if (rest_ < 0) {
      ++minor_;
      rest_ += den_;
    }
  }

 private:
  int64_t width_, den_, minor_, rest_, step_q_, step_r_;
};

// The quads of pixels that come quad row after quad row (never back to an earlier one): each
// quad row's masks go to the sink when the pixels leave it, the last one at flush().
template <class Sink>
class QuadRowCollector {
 public:
  QuadRowCollector(const PixelRect& area, const Sink& sink) : x0_(area.x0 & ~1), sink_(sink) {}
  void add(int x, int y) {
    if (y >> 1 != quad_row_) {
      flush();
      quad_row_ = y >> 1;
    }
    const int q = (x - x0_) >> 1;
    masks_[q] = static_cast<uint8_t>(masks_[q] | 1u << ((x & 1) + 2 * (y & 1)));
    first_ = std::min(first_, q);
    last_ = std::max(last_, q);
  }
  void flush() {
    if (last_ < first_) return;
    sink_.row(x0_ + 2 * first_, 2 * quad_row_, last_ - first_ + 1, masks_ + first_);
    std::fill(masks_ + first_, masks_ + last_ + 1, uint8_t{0});
    first_ = kMaxQuadsPerRow;
    last_ = -1;
  }

 private:
  const int x0_;
  const Sink& sink_;
  int quad_row_ = -1, first_ = kMaxQuadsPerRow, last_ = -1;
  uint8_t masks_[kMaxQuadsPerRow] = {};
};

template <class Sink>
void rasterize_line(const PrimSetup& p, const PixelRect& area, const Sink& sink) {
  const LineCoverage& l = p.line;
  const int m_lo = std::max(l.major_min, l.x_major ? area.x0 : area.y0);
  const int m_hi = std::min(l.major_max, (l.x_major ? area.x1 : area.y1) - 1);
  const int n_lo = l.x_major ? area.y0 : area.x0, n_hi = (l.x_major ? area.y1 : area.x1) - 1;
  if (m_lo > m_hi) return;
  SpanWalk span(l, m_lo);
  if (l.width == 1) {
    // One pixel a column (a row): its minor coordinate moves one way only, so the pixels pass
    // quad row after quad row and go to the sink without an area mask first (wireframe, one
    // thread pinned: 3.81-4.14 -> 3.65-3.81 ms).
    QuadRowCollector<Sink> quads(area, sink);
    for (int m = m_lo; m <= m_hi; ++m, span.next()) {
      const int64_t n = span.start();
      if (n < n_lo || n > n_hi) continue;
      if (l.x_major) quads.add(m, static_cast<int>(n));
      else quads.add(static_cast<int>(n), m);
    }
    quads.flush();
    return;
  }
  TileMask mask{area};
  for (int m = m_lo; m <= m_hi; ++m, span.next()) {
    const int64_t start = span.start();
    const int64_t lo = std::max<int64_t>(start, n_lo), hi = std::min<int64_t>(start + l.width - 1, n_hi);
    for (int64_t n = lo; n <= hi; ++n) {
      if (l.x_major) mask.set(m, static_cast<int>(n));
      else mask.set(static_cast<int>(n), m);
    }
  }
  emit_mask(mask, sink);
}

// The triangle's pixels row by row: per row the columns between its edges' bounds, a span,
// then quads from pairs of rows. A triangle covering the whole area skips the spans.
template <class Sink>
void rasterize_triangle(const PrimSetup& p, const PixelRect& area, const Sink& sink) {
  // A small triangle (most of a dense mesh's): its few quads edge-tested directly cost less
  // than setting up the row bounds (small_tris: 11% less CPU time than spans for every size).
  if (area.x1 - area.x0 <= kSmallAreaSide && area.y1 - area.y0 <= kSmallAreaSide) {
    static const SmallAreaMasks masks_of = select_small_area_masks(simd_path_from_environment());
    uint8_t masks[kSmallAreaQuadRows][kSmallAreaRowBytes];
    const int count = masks_of(p, area, masks);
    for (int y = area.y0 & ~1, r = 0; y < area.y1; y += 2, ++r) sink.row(area.x0 & ~1, y, count, masks[r]);
    return;
  }
  if (classify(p, area) == BlockCover::Full) {  // rows as wide as the tile: fewer, longer calls
    emit_full(area, area, sink);
    return;
  }
  TileMask mask{area};
  // The edges by kind: a row takes each one's bound without a switch.
  EdgeRowBound lower[3], upper[3], level[3];
  int lowers = 0, uppers = 0, levels = 0;
  for (const EdgeFunction& e : p.edges) {
    const EdgeRowBound b(e, area.y0);
    switch (b.kind()) {
      case EdgeRowBound::Kind::Lower: lower[lowers++] = b; break;
      case EdgeRowBound::Kind::Upper: upper[uppers++] = b; break;
      case EdgeRowBound::Kind::Row: level[levels++] = b; break;
    }
  }
  for (int y = area.y0; y < area.y1; ++y) {
    int64_t lo = area.x0, hi = area.x1 - 1;
    bool none = false;
    for (int i = 0; i < lowers; ++i) {
      lo = std::max(lo, lower[i].first_column());
      lower[i].next();
    }
    for (int i = 0; i < uppers; ++i) {
      hi = std::min(hi, upper[i].last_column());
      upper[i].next();
    }
    for (int i = 0; i < levels; ++i) {
      none |= level[i].keeps_no_column();
      level[i].next();
    }
    if (none || lo > hi) continue;
    const int width = static_cast<int>(hi - lo + 1);  // at most 64: the area lies in one tile
    const uint64_t span = width == 64 ? ~uint64_t{0} : (uint64_t{1} << width) - 1;
    mask.rows[y - area.y0] = span << (lo - area.x0);
  }
  emit_mask(mask, sink);
}

// Antialiased points and lines: the pixels whose coverage is above zero.
template <class Sink>
void rasterize_smooth(const PrimSetup& p, const PixelRect& area, const Sink& sink) {
  TileMask mask{area};
  const SmoothCoverage coverage(p);
  for (int y = area.y0; y < area.y1; ++y) {
    int x0 = area.x0, x1 = area.x1;
    if (p.kind == CoverageKind::Line) smooth_row_span(p.smooth, y, x0, x1);
    for (int x = x0; x < x1; ++x)
      if (coverage.at(x, y) > 0.0) mask.set(x, y);
  }
  emit_mask(mask, sink);
}

// A multisampled point at one sample: the pixels whose centre it covers (multisample.cpp moves
// the point by the sample's offset).
template <class Sink>
void rasterize_sample_point(const PrimSetup& p, const PixelRect& area, const Sink& sink) {
  TileMask mask{area};
  for (int y = area.y0; y < area.y1; ++y)
    for (int x = area.x0; x < area.x1; ++x)
      if (sample_point_covers(p.sample_point, x * kSubpixelOne + kSubpixelHalf, y * kSubpixelOne + kSubpixelHalf))
        mask.set(x, y);
  emit_mask(mask, sink);
}

// Records a sample's quad masks as that sample's nibble of TileSampleMasks.
struct SampleMaskSink {
  TileSampleMasks& out;
  int sample;
  void row(int x, int y, int count, const uint8_t* masks) const {
    uint16_t* quads = &out.quads[(y - out.y0) / 2][(x - out.x0) / 2];
    for (int q = 0; q < count; ++q) quads[q] |= static_cast<uint16_t>(masks[q] << (4 * sample));
  }
};

// The primitive's quads in `area` (inside one tile), row by row into the sink.
template <class Sink>
void rasterize_area(const PrimSetup& prim, const PixelRect& area, const Sink& sink) {
  if (prim.smooth.size > 0.0) {
    rasterize_smooth(prim, area, sink);
    return;
  }
  switch (prim.kind) {
    case CoverageKind::Triangle: rasterize_triangle(prim, area, sink); break;
    case CoverageKind::Line: rasterize_line(prim, area, sink); break;
    case CoverageKind::Point:
      if (prim.sample_point.size > 0) rasterize_sample_point(prim, area, sink);
      else emit_full(area, area, sink);
      break;
  }
}

}  // namespace

bool triangle_may_touch(const PrimSetup& prim, const PixelRect& rect) {
  return classify(prim, rect) != BlockCover::None;
}

uint64_t rasterize_in_tile(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb, const PixelRect& tile,
                           ShaderQuadBatch* batch) {
  const PixelRect area = intersect(prim.bounds, tile);
  if (area.empty()) return 0;
  uint64_t passed = 0;
  // Rows of more than a few quads fill their own blocks: packed with others', glsl_sprites
  // (quads of 13 to 44 pixels) shaded 18% fewer blocks in the same time, and full-screen rows
  // lost the writer of adjacent quads (glsl_procedural: 2% slower).
  if (batch && area.x1 - area.x0 > kBatchedWidth) {
    passed += batch->flush();
    batch = nullptr;
  }
  const QuadSink sink{prim, draw, fb, batch};
  rasterize_area(prim, area, sink);
  return passed + sink.samples_passed;
}

void add_sample_masks(const PrimSetup& prim, const PixelRect& area, int sample, TileSampleMasks& out) {
  rasterize_area(prim, area, SampleMaskSink{out, sample});
}

}  // namespace pineda::raster
