#include "raster/fragment_pipeline.h"

#include <array>
#include <cstring>
#include <utility>

#include "raster/blend8.h"
#include "raster/fragment_extras.h"
#include "raster/fragment_ops.h"
#include "raster/quad_colors.h"
#include "raster/quad_ops.h"
#include "raster/quad_vector.h"
#include "raster/sampler.h"
#include "raster/tex_env.h"

namespace pineda::raster {
namespace {

using namespace quad_ops;

template <bool kTex, bool kDepth, bool kStencil, bool kBlend, bool kFlat, bool kOver, bool kExtras>
[[gnu::always_inline]] inline uint32_t shade_quads_body(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                 const uint8_t* masks) {
  const DrawState& s = d.state;
  const F4 oy = quad_row_oy(p, y), ox0 = quad_row_ox0(p, x);
  const bool write_color = fb.color.base && d.color_write_any;
  // Without an alpha test no stage before depth and stencil reads the colour, so they run first
  // and only the surviving quads are coloured (the colour has no side effects).
  const bool early_tests = !s.alpha_test;
  // Occlusion queries count at run time, as the other routines do: a template flag for them would
  // double the routines (and their compile time) for a branch per quad.
  const bool count_passed = d.key.count_samples;
  uint32_t passed = 0;
  for (int q = 0; q < count; ++q) {
    unsigned mask = masks[q];
    const int qx = x + 2 * q;
    if constexpr (kExtras) mask &= stipple_mask(d, p, qx, y);
    if (!mask) continue;
    // Offsets from the reference point (exact while the primitive stays near the framebuffer).
    const F4 ox = ox0 + splat(static_cast<float>(2 * q));
    auto colors = [&] {
      QuadColor col = quad_colors<kTex, kFlat, kExtras>(d, p, ox, oy);
      if constexpr (kExtras) apply_coverage(p, qx, y, mask, col.c[3]);
      if constexpr (kExtras) {  // no alpha test here: alpha to one comes after it, and after coverage
        if (early_tests && d.alpha_to_one) col.c[3] = splat(1.f);
      }
      return col;
    };
    auto depth_and_stencil = [&] {
      if constexpr (kDepth && !kStencil) mask = depth_only(d, p, fb, qx, y, mask, ox, oy);
      else if constexpr (kStencil) mask = depth_stencil<kDepth, kStencil>(d, p, fb, qx, y, mask, ox, oy);
    };
    if (early_tests) {
      depth_and_stencil();
      if (count_passed) passed += static_cast<uint32_t>(__builtin_popcount(mask));
      if (mask && write_color) write_quad<kBlend, kOver>(d, fb, qx, y, mask, colors());
      continue;
    }
    QuadColor col = colors();
    for (int i = 0; i < 4; ++i)
      if (!alpha_passes(d, col.c[3][i])) mask &= ~(1u << i);
    if constexpr (kExtras) {
      if (d.alpha_to_one) col.c[3] = splat(1.f);
    }
    depth_and_stencil();
    if (count_passed) passed += static_cast<uint32_t>(__builtin_popcount(mask));
    if (mask && write_color) write_quad<kBlend, kOver>(d, fb, qx, y, mask, col);
  }
  return passed;
}

// Two copies of every routine: the baseline one, and an AVX2 one for CPUs that have it (the
// same operations, no FMA, no contraction, so the same results, with 256-bit doubles and
// three-operand instructions). simd_path.h chooses.
template <bool... kFlags>
uint32_t shade_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                     const uint8_t* masks) {
  return shade_quads_body<kFlags...>(d, p, fb, x, y, count, masks);
}

template <bool... kFlags>
[[gnu::target("avx2")]] uint32_t shade_quads_avx2(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x,
                                                  int y, int count, const uint8_t* masks) {
  return shade_quads_body<kFlags...>(d, p, fb, x, y, count, masks);
}

template <int kBits, bool kExtras, bool kAvx2>
constexpr QuadRoutine routine_for() {
  constexpr bool t = kBits & 1, z = kBits & 2, st = kBits & 4, b = kBits & 8, f = kBits & 16, o = kBits & 32;
  if constexpr (kAvx2) return &shade_quads_avx2<t, z, st, b, f, o, kExtras>;
  else return &shade_quads<t, z, st, b, f, o, kExtras>;
}

template <bool kExtras, bool kAvx2, int... kBits>
constexpr auto make_table(std::integer_sequence<int, kBits...>) {
  return std::array<QuadRoutine, sizeof...(kBits)>{routine_for<kBits, kExtras, kAvx2>()...};
}

constexpr auto kRoutines = make_table<false, false>(std::make_integer_sequence<int, 64>{});
constexpr auto kRoutinesAvx2 = make_table<false, true>(std::make_integer_sequence<int, 64>{});

// Fog, colour sum and stipple are rare: their routines leave out the SRC_ALPHA-over fast path
// (bit 32) to halve their count.
constexpr auto kExtrasRoutines = make_table<true, false>(std::make_integer_sequence<int, 32>{});
constexpr auto kExtrasRoutinesAvx2 = make_table<true, true>(std::make_integer_sequence<int, 32>{});

}  // namespace

QuadRoutine select_quad_routine(const FragmentKey& key, SimdPath path) {
  const int bits = (key.textured ? 1 : 0) | (key.depth ? 2 : 0) | (key.stencil ? 4 : 0) | (key.blend ? 8 : 0) |
                   (key.flat ? 16 : 0);
  const bool avx2 = uses_avx2(path);
  if (key.extras) return (avx2 ? kExtrasRoutinesAvx2 : kExtrasRoutines)[bits];
  const int over = key.blend && key.blend8 == Blend8::Over ? 32 : 0;
  return (avx2 ? kRoutinesAvx2 : kRoutines)[bits | over];
}

}  // namespace pineda::raster
