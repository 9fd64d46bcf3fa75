#include "raster/sample_quads.h"

#include <array>
#include <utility>

#include "raster/fragment_extras.h"
#include "raster/fragment_ops.h"
#include "raster/quad_colors.h"
#include "raster/quad_ops.h"

namespace pineda::raster {
namespace {

using namespace quad_ops;

// The write of the single-sampled routine of the key (those with extras leave out the
// SRC_ALPHA-over path: fragment_pipeline.cpp).
template <bool kExtras>
[[gnu::always_inline]] inline void sample_write(const DrawRecord& d, const Framebuffer& fb, int x, int y, unsigned mask,
                                                const QuadColor& col) {
  if (!d.key.blend) write_quad<false, false>(d, fb, x, y, mask, col);
  else if (!kExtras && d.key.blend8 == Blend8::Over) write_quad<true, true>(d, fb, x, y, mask, col);
  else write_quad<true, false>(d, fb, x, y, mask, col);
}

template <bool kTex, bool kFlat, bool kExtras>
[[gnu::always_inline]] inline uint32_t shade_sample_quads_body(const DrawRecord& d, const PrimSetup& p,
                                                               const SampleTargets& t, int x, int y, int count,
                                                               const uint16_t* masks) {
  const F4 oy = quad_row_oy(p, y), ox0 = quad_row_ox0(p, x);
  // Alpha to coverage makes every sample's record alpha-test (multisample.cpp).
  const bool early_tests = !d.state.alpha_test && !d.sample_draws;
  uint32_t passed = 0;
  for (int q = 0; q < count; ++q) {
    uint16_t cover = masks[q];
    const int qx = x + 2 * q;
    if constexpr (kExtras) cover &= static_cast<uint16_t>(stipple_mask(d, p, qx, y) * 0x1111u);
    if (!any_sample_mask(cover)) continue;
    const F4 ox = ox0 + splat(static_cast<float>(2 * q));
    uint16_t live = 0;  // lane 4s + i: sample s's pixel i (sample_targets.h)
    // Stencil and depth of every sample at once, as the single-sampled routines run them.
    auto tests = [&] {
      if (d.sample_tests) live = d.sample_tests(d, p, t, qx, y, ox, oy, live, nullptr);
      if (d.key.count_samples) passed += static_cast<uint32_t>(__builtin_popcount(live));
    };
    auto writes = [&](const QuadColor& col) {
      for (int s = 0; s < kMaxSamples; ++s) {
        const unsigned mask = sample_quad_mask(live, s);
        if (mask && t.plane[s].color.base && d.color_write_any)
          sample_write<kExtras>(*t.draw[s], t.plane[s], qx, y, mask, col);
      }
    };
    QuadColor col;
    if (early_tests) {  // as the single-sampled routines: no stage before the tests reads colour
      for (int s = 0; s < kMaxSamples; ++s)
        if (t.draw[s]) live |= static_cast<uint16_t>(cover & (0xfu << (4 * s)));
      tests();
      if (!live) continue;
      col = quad_colors<kTex, kFlat, kExtras>(d, p, ox, oy);
      if constexpr (kExtras) {
        apply_coverage(p, qx, y, 0xfu, col.c[3]);
        if (d.alpha_to_one) col.c[3] = splat(1.f);
      }
      writes(col);
      continue;
    }
    col = quad_colors<kTex, kFlat, kExtras>(d, p, ox, oy);
    if constexpr (kExtras) apply_coverage(p, qx, y, 0xfu, col.c[3]);
    for (int s = 0; s < kMaxSamples; ++s) {
      if (!t.draw[s]) continue;
      unsigned mask = sample_quad_mask(cover, s);
      for (int i = 0; i < 4; ++i)
        if (!alpha_passes(*t.draw[s], col.c[3][i])) mask &= ~(1u << i);
      live |= static_cast<uint16_t>(mask << (4 * s));
    }
    if constexpr (kExtras) {
      if (d.alpha_to_one) col.c[3] = splat(1.f);
    }
    tests();
    writes(col);
  }
  return passed;
}

template <bool... kFlags>
uint32_t shade_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x, int y, int count,
                            const uint16_t* masks) {
  return shade_sample_quads_body<kFlags...>(d, p, t, x, y, count, masks);
}

template <bool... kFlags>
[[gnu::target("avx2")]] uint32_t shade_sample_quads_avx2(const DrawRecord& d, const PrimSetup& p,
                                                         const SampleTargets& t, int x, int y, int count,
                                                         const uint16_t* masks) {
  return shade_sample_quads_body<kFlags...>(d, p, t, x, y, count, masks);
}

template <int kBits, bool kAvx2>
constexpr SampleQuadRoutine routine_for() {
  constexpr bool t = kBits & 1, f = kBits & 2, e = kBits & 4;
  if constexpr (kAvx2) return &shade_sample_quads_avx2<t, f, e>;
  else return &shade_sample_quads<t, f, e>;
}

template <bool kAvx2, int... kBits>
constexpr auto make_table(std::integer_sequence<int, kBits...>) {
  return std::array<SampleQuadRoutine, sizeof...(kBits)>{routine_for<kBits, kAvx2>()...};
}

constexpr auto kRoutines = make_table<false>(std::make_integer_sequence<int, 8>{});
constexpr auto kRoutinesAvx2 = make_table<true>(std::make_integer_sequence<int, 8>{});

}  // namespace

SampleQuadRoutine select_sample_quad_routine(const FragmentKey& key, SimdPath path) {
  const int bits = (key.textured ? 1 : 0) | (key.flat ? 2 : 0) | (key.extras ? 4 : 0);
  return (uses_avx2(path) ? kRoutinesAvx2 : kRoutines)[bits];
}

}  // namespace pineda::raster
