// The helpers pass 32-byte vectors but are always inlined into the routines of one copy (before
// the headers: framebuffer.h's swap_red_blue is one of them).
#pragma GCC diagnostic ignored "-Wpsabi"

#include "raster/fill_rows.h"

#include <immintrin.h>

#include <array>
#include <cstring>
#include <type_traits>
#include <utility>

#include "raster/mip_selection.h"
#include "raster/quad_ops.h"
#include "raster/raster_limits.h"
#include "raster/sampler.h"

// Three copies of the routines: baseline x86-64 (SSE2), AVX2, AVX-512. The same operations (no
// FMA: the build turns contraction off), so the same pixels.
namespace pineda::raster::fill_sse2 {
namespace {
constexpr bool kDoubles8 = false;
constexpr int kGatherBytes = 0;
#include "raster/fill_rows_body.inc"
}  // namespace
}  // namespace pineda::raster::fill_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace pineda::raster::fill_avx2 {
namespace {
constexpr bool kDoubles8 = false;
constexpr int kGatherBytes = kCopiesHaveTheirTargets ? 32 : 0;
#include "raster/fill_rows_body.inc"
}  // namespace
}  // namespace pineda::raster::fill_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512vl,avx512dq")
namespace pineda::raster::fill_avx512 {
namespace {
constexpr bool kDoubles8 = true;  // 512-bit vectors of 8 doubles
constexpr int kGatherBytes = kCopiesHaveTheirTargets ? 64 : 0;  // (rows of 8 lanes, 16-column windows)
#include "raster/fill_rows_body.inc"
}  // namespace
}  // namespace pineda::raster::fill_avx512
#pragma GCC pop_options

namespace pineda::raster {
namespace {

enum class Copy { Baseline, Avx2, Avx512 };

// Bits 0-4: depth, blend (kBlend), flat, sample count, stencil; bit 5: textured (MODULATE in
// lanes), which has routines only without stencil and sample count (table index bits 0-2), as
// have the additive blends.
template <int kBits, Copy kCopy, Blend8 kBlend>
constexpr QuadRoutine routine_for() {
  constexpr bool z = kBits & 1, f = kBits & 4, c = kBits & 8, st = kBits & 16, t = kBits & 32;
  constexpr Blend8 b = kBits & 2 ? kBlend : Blend8::Other;
  if constexpr (kCopy == Copy::Avx512) return &fill_avx512::fill_rows<z, st, b, f, c, t>;
  else if constexpr (kCopy == Copy::Avx2) return &fill_avx2::fill_rows<z, st, b, f, c, t>;
  else return &fill_sse2::fill_rows<z, st, b, f, c, t>;
}

template <Copy kCopy, int kTextured, Blend8 kBlend, int... kBits>
constexpr auto make_table(std::integer_sequence<int, kBits...>) {
  return std::array<QuadRoutine, sizeof...(kBits)>{routine_for<kBits | kTextured, kCopy, kBlend>()...};
}

template <Copy kCopy, Blend8 kBlend>
struct Tables {
  static constexpr auto plain = make_table<kCopy, 0, kBlend>(std::make_integer_sequence<int, kBlend == Blend8::Over ? 32 : 8>{});
  static constexpr auto textured = make_table<kCopy, 32, kBlend>(std::make_integer_sequence<int, 8>{});
};

template <Copy kCopy>
QuadRoutine pick(Blend8 blend, bool textured, int bits) {
  auto from = [&]<Blend8 kBlend>() { return textured ? Tables<kCopy, kBlend>::textured[bits] : Tables<kCopy, kBlend>::plain[bits]; };
  if (blend == Blend8::AddScaled) return from.template operator()<Blend8::AddScaled>();
  if (blend == Blend8::Add) return from.template operator()<Blend8::Add>();
  return from.template operator()<Blend8::Over>();  // (and the draws without blending)
}

}  // namespace

QuadRoutine select_fill_routine(const DrawRecord& d, const Framebuffer& fb, SimdPath path) {
  const FragmentKey& k = d.key;
  if (d.state.shader || k.extras || d.state.alpha_test) return nullptr;
  if (k.textured && (!d.texture_in_lanes || k.stencil || k.count_samples)) return nullptr;
  // Other blends and logic ops; the additive ones have no routines with stencil or a sample count.
  const Blend8 blend = k.blend ? k.blend8 : Blend8::Other;
  if (k.blend && blend != Blend8::Over && blend != Blend8::AddScaled && blend != Blend8::Add) return nullptr;
  if (blend != Blend8::Other && blend != Blend8::Over && (k.stencil || k.count_samples)) return nullptr;
  if (k.depth && !(d.depth_max < 2147483647.0)) return nullptr;  // 32-bit depth: row_depth's conversion
  if (fb.color.reduction.active) return nullptr;
  const int bits = (k.depth ? 1 : 0) | (k.blend ? 2 : 0) | (k.flat ? 4 : 0) | (k.count_samples ? 8 : 0) |
                   (k.stencil ? 16 : 0);
  if (uses_avx512(path)) return pick<Copy::Avx512>(blend, k.textured, bits);
  return uses_avx2(path) ? pick<Copy::Avx2>(blend, k.textured, bits) : pick<Copy::Baseline>(blend, k.textured, bits);
}

}  // namespace pineda::raster
