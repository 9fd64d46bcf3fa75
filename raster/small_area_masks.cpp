#include "raster/small_area_masks.h"

#include <immintrin.h>

#include <cstdlib>
#include <cstring>

#include "raster/raster_limits.h"

namespace pineda::raster {
namespace {

// The area's pixels of quad row y (bits 0-1: row y, bits 2-3: row y + 1) and of the quad at
// column x (bits 0 and 2: column x, bits 1 and 3: column x + 1).
unsigned row_bits(int y, const PixelRect& area) {
  return (y >= area.y0 && y < area.y1 ? 3u : 0u) | (y + 1 >= area.y0 && y + 1 < area.y1 ? 12u : 0u);
}
unsigned column_bits(int x, const PixelRect& area) {
  return (x >= area.x0 && x < area.x1 ? 5u : 0u) | (x + 1 >= area.x0 && x + 1 < area.x1 ? 10u : 0u);
}

int count_of(const PixelRect& area) { return (area.x1 - (area.x0 & ~1) + 1) / 2; }

// Each edge stepped quad by quad along the row, four pixel tests per quad and edge.
int masks_scalar(const PrimSetup& p, const PixelRect& area, uint8_t (*masks)[kSmallAreaRowBytes]) {
  const int x0 = area.x0 & ~1, y0 = area.y0 & ~1, count = count_of(area);
  int64_t sx[3], sy[3];
  for (int e = 0; e < 3; ++e) {
    sx[e] = p.edges[e].a * kSubpixelOne;
    sy[e] = p.edges[e].b * kSubpixelOne;
  }
  for (int y = y0, r = 0; y < area.y1; y += 2, ++r) {
    const unsigned rows = row_bits(y, area);
    int64_t v[3];
    for (int e = 0; e < 3; ++e) v[e] = edge_at(p.edges[e], x0, y);
    for (int q = 0; q < count; ++q) {
      unsigned m = rows & column_bits(x0 + 2 * q, area);
      for (int e = 0; e < 3; ++e) {
        m &= (v[e] >= 0 ? 1u : 0u) | (v[e] + sx[e] >= 0 ? 2u : 0u) | (v[e] + sy[e] >= 0 ? 4u : 0u) |
             (v[e] + sx[e] + sy[e] >= 0 ? 8u : 0u);
        v[e] += 2 * sx[e];
      }
      masks[r][q] = static_cast<uint8_t>(m);
    }
  }
  return count;
}

// Eight quads a vector of 64-bit edge values: the same sums and comparisons as masks_scalar.
using L8 = int64_t __attribute__((vector_size(64)));
using M8 = int8_t __attribute__((vector_size(8)));
using I16 = int32_t __attribute__((vector_size(64)));

// An area within two quads by two from (x0, y0) (a dense mesh's triangle of a few pixels): its 16
// pixels' edge values in one vector of 32-bit lanes, lane 8 r + 4 q + i for pixel i of quad q of
// quad row r. Exact when every edge's values there fit 32 bits, which holds near the triangle's
// vertices but not on an area far from them (a large triangle's corner in a tile, under a
// scissor): false then, and nothing written.
__attribute__((target("avx512f,avx512bw,avx512vl,avx512dq"))) bool masks_of_four_quads(
    const PrimSetup& p, const PixelRect& area, int x0, int y0, uint8_t (*masks)[kSmallAreaRowBytes]) {
  constexpr int64_t kLimit = int64_t{1} << 31;
  const I16 dx = {0, 1, 0, 1, 2, 3, 2, 3, 0, 1, 0, 1, 2, 3, 2, 3};
  const I16 dy = {0, 0, 1, 1, 0, 0, 1, 1, 2, 2, 3, 3, 2, 2, 3, 3};
  // The area's pixels: x0 + dx in [x0, x1) and y0 + dy in [y0, y1).
  const I16 inside_area = (dx >= area.x0 - x0) & (dy >= area.y0 - y0) & (dx < area.x1 - x0) & (dy < area.y1 - y0);
  __mmask16 inside = _mm512_test_epi32_mask(reinterpret_cast<__m512i>(inside_area), reinterpret_cast<__m512i>(inside_area));
  for (const EdgeFunction& e : p.edges) {
    const int64_t v = edge_at(e, x0, y0), sx = e.a * kSubpixelOne, sy = e.b * kSubpixelOne;
    if (std::llabs(v) + 3 * (std::llabs(sx) + std::llabs(sy)) >= kLimit) return false;
    const I16 values = static_cast<int32_t>(v) + dx * static_cast<int32_t>(sx) + dy * static_cast<int32_t>(sy);
    inside &= _mm512_cmpge_epi32_mask(reinterpret_cast<__m512i>(values), _mm512_setzero_si512());
  }
  masks[0][0] = static_cast<uint8_t>(inside & 15);
  masks[0][1] = static_cast<uint8_t>((inside >> 4) & 15);
  masks[1][0] = static_cast<uint8_t>((inside >> 8) & 15);
  masks[1][1] = static_cast<uint8_t>(inside >> 12);
  return true;
}

// An area within four quads by four from (x0, y0) (a dense mesh's triangle of a dozen pixels):
// each quad row's 16 pixels in one vector of 32-bit lanes, lane 4q + i for pixel i of quad q, each
// row the previous one's values plus two rows' steps. Exact under masks_of_four_quads' condition,
// for offsets up to 7: false then, and nothing written.
__attribute__((target("avx512f,avx512bw,avx512vl,avx512dq"))) bool masks_of_quad_rows(
    const PrimSetup& p, const PixelRect& area, int x0, int y0, uint8_t (*masks)[kSmallAreaRowBytes]) {
  constexpr int64_t kLimit = int64_t{1} << 31;
  const I16 dx = {0, 1, 0, 1, 2, 3, 2, 3, 4, 5, 4, 5, 6, 7, 6, 7};
  const I16 dy = {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1};
  I16 values[3], two_rows[3];
  for (int e = 0; e < 3; ++e) {
    const EdgeFunction& edge = p.edges[e];
    const int64_t v = edge_at(edge, x0, y0), sx = edge.a * kSubpixelOne, sy = edge.b * kSubpixelOne;
    if (std::llabs(v) + 7 * (std::llabs(sx) + std::llabs(sy)) >= kLimit) return false;
    values[e] = static_cast<int32_t>(v) + dx * static_cast<int32_t>(sx) + dy * static_cast<int32_t>(sy);
    two_rows[e] = I16{} + 2 * static_cast<int32_t>(sy);
  }
  const I16 columns = (dx >= area.x0 - x0) & (dx < area.x1 - x0);
  for (int y = y0, r = 0; y < area.y1; y += 2, ++r) {
    const I16 rows = (dy + (y - y0) >= area.y0 - y0) & (dy + (y - y0) < area.y1 - y0);
    const I16 in_area = columns & rows;
    __mmask16 inside = _mm512_test_epi32_mask(reinterpret_cast<__m512i>(in_area), reinterpret_cast<__m512i>(in_area));
    for (int e = 0; e < 3; ++e) {
      if (r > 0) values[e] += two_rows[e];  // (not past the last row: there it might not fit)
      inside &= _mm512_cmpge_epi32_mask(reinterpret_cast<__m512i>(values[e]), _mm512_setzero_si512());
    }
    for (int q = 0; q < 4; ++q) masks[r][q] = static_cast<uint8_t>((inside >> (4 * q)) & 15);
  }
  return true;
}

__attribute__((target("avx512f,avx512bw,avx512vl,avx512dq"))) int masks_avx512(const PrimSetup& p,
                                                                              const PixelRect& area,
                                                                              uint8_t (*masks)[kSmallAreaRowBytes]) {
  const int x0 = area.x0 & ~1, y0 = area.y0 & ~1, count = count_of(area);
  if (area.x1 - x0 <= 4 && area.y1 - y0 <= 4 && masks_of_four_quads(p, area, x0, y0, masks)) return count;
  if (area.x1 - x0 <= 8 && area.y1 - y0 <= 8 && masks_of_quad_rows(p, area, x0, y0, masks)) return count;
  const L8 quad = {0, 1, 2, 3, 4, 5, 6, 7};
  uint64_t columns[2] = {};  // the area's column bits of each quad, a byte each
  for (int q = 0; q < count; ++q) columns[q / 8] |= uint64_t{column_bits(x0 + 2 * q, area)} << (8 * (q % 8));
  L8 offset[3][2];  // each group's quads' offsets from the row's first quad, per edge
  for (int e = 0; e < 3; ++e)
    for (int g = 0; g < 2; ++g) offset[e][g] = (quad + 8 * g) * (2 * p.edges[e].a * kSubpixelOne);
  for (int y = y0, r = 0; y < area.y1; y += 2, ++r) {
    const uint64_t rows = row_bits(y, area) * 0x0101010101010101u;
    for (int g = 0; 8 * g < count; ++g) {
      L8 m = {};
      m += 15;
      for (int e = 0; e < 3; ++e) {
        const int64_t sx = p.edges[e].a * kSubpixelOne, sy = p.edges[e].b * kSubpixelOne;
        const L8 v = edge_at(p.edges[e], x0, y) + offset[e][g];
        m &= ((v >= 0) & 1) | ((v + sx >= 0) & 2) | ((v + sy >= 0) & 4) | ((v + sx + sy >= 0) & 8);
      }
      uint64_t bytes;
      const M8 narrow = __builtin_convertvector(m, M8);
      std::memcpy(&bytes, &narrow, 8);
      bytes &= rows & columns[g];
      std::memcpy(&masks[r][8 * g], &bytes, 8);
    }
  }
  return count;
}

}  // namespace

SmallAreaMasks select_small_area_masks(SimdPath path) { return uses_avx512(path) ? masks_avx512 : masks_scalar; }

}  // namespace pineda::raster
