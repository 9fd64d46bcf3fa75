// Level-of-detail arithmetic shared by the samplers (GL 1.5 3.8.8-3.8.9): lambda from the
// squared scale factor, and the level(s) a filter reads at that lambda.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "raster/quad_vector.h"
#include "raster/texture.h"

namespace pineda::raster {

// lambda = log2(rho) = log2(rho^2) / 2, with log2 taken piecewise linear between powers of
// two (exact at them). GL allows approximating lambda; this is the approximation llvmpipe
// uses, so that mipmap blends match it. -inf when rho is 0.
inline float lambda_from_rho2(float rho2) {
  if (!(rho2 > 0.f)) return rho2 == 0.f ? -INFINITY : NAN;
  // rho2 = m * 2^e, m in [0.5, 1), as std::frexp gives them, from the bits (frexp is a call).
  int shift = 0;
  if (rho2 < 0x1p-126f) {  // subnormal: scaled up exactly first
    rho2 *= 0x1p24f;
    shift = 24;
  }
  uint32_t bits;
  std::memcpy(&bits, &rho2, sizeof bits);
  if (bits >= 0x7f800000u) return INFINITY;  // rho2 infinite (NaN was returned above)
  const int e = static_cast<int>(bits >> 23) - 126 - shift;
  bits = (bits & 0x807fffffu) | 0x3f000000u;
  float m;
  std::memcpy(&m, &bits, sizeof m);
  return 0.5f * (static_cast<float>(e - 1) + (2.f * m - 1.f));
}

inline bool is_linear(TexFilter f) {
  return f == TexFilter::Linear || f == TexFilter::LinearMipmapNearest || f == TexFilter::LinearMipmapLinear;
}

// The levels a quad reads: `first` alone, or `first` and first + 1 blended by `blend`.
struct LevelChoice {
  int first = 0;
  float blend = 0.f;
  bool two = false;
  bool linear = false;  // filtering within a level
};

// choose_levels in two steps: the quad's level of detail `lambda` biased and clamped, then the
// levels at that lambda; `max_level`: the last level of the image (its levels are a complete
// chain when the filter mipmaps).
inline float clamped_lambda(const Sampler& sampler, float lambda) {
  if (std::isnan(lambda)) lambda = 0.f;
  lambda = std::min(std::max(lambda + sampler.lod_bias, sampler.min_lod), sampler.max_lod);
  if (!(lambda > -1e30f && lambda < 1e30f)) lambda = lambda > 0 ? 1e30f : -1e30f;
  return lambda;
}

inline LevelChoice levels_at(const Sampler& sampler, float lambda, int max_level) {
  const TexFilter min = sampler.min_filter;
  const bool mag_linear = sampler.mag_filter == TexFilter::Linear;
  const float c = mag_linear && (min == TexFilter::NearestMipmapNearest || min == TexFilter::NearestMipmapLinear)
                      ? 0.5f
                      : 0.f;
  LevelChoice out;
  if (lambda <= c || min == TexFilter::Nearest || min == TexFilter::Linear) {
    out.linear = lambda <= c ? mag_linear : min == TexFilter::Linear;
    return out;
  }
  out.linear = is_linear(min);
  if (min == TexFilter::NearestMipmapNearest || min == TexFilter::LinearMipmapNearest) {
    out.first = lambda <= 0.5f ? 0 : std::min(static_cast<int>(std::ceil(std::min(lambda, 1e6f) + 0.5f)) - 1, max_level);
    return out;
  }
  if (lambda >= static_cast<float>(max_level)) {
    out.first = max_level;
    return out;
  }
  out.first = static_cast<int>(std::floor(lambda));
  out.blend = lambda - static_cast<float>(out.first);
  out.two = true;
  return out;
}

inline LevelChoice choose_levels(const Sampler& sampler, float lambda, int max_level) {
  return levels_at(sampler, clamped_lambda(sampler, lambda), max_level);
}

// The same over four lanes (four quads' rho^2, the fill routines' groups), the same operations
// per lane: clamped_lambda's lambda of lambda_from_rho2.
[[gnu::always_inline]] inline F4 clamped_lambda_lanes(const Sampler& sampler, F4 rho2) {
  using V = F4;
  const I4 subnormal = rho2 < 0x1p-126f;
  const V scaled = subnormal ? rho2 * 0x1p24f : rho2;
  const U4 bits = reinterpret_cast<U4>(scaled);
  const I4 e = reinterpret_cast<I4>(bits >> 23) - 126 - (subnormal & 24);
  const V m = reinterpret_cast<V>((bits & 0x807fffffu) | 0x3f000000u);
  V lambda = 0.5f * (__builtin_convertvector(e - 1, V) + (2.f * m - 1.f));
  lambda = bits >= 0x7f800000u ? V{} + INFINITY : lambda;
  lambda = rho2 > 0.f ? lambda : rho2 == 0.f ? V{} - INFINITY : V{} + NAN;
  // clamped_lambda: NaN as 0; std::max(l + bias, min_lod), then std::min(that, max_lod).
  lambda = lambda != lambda ? V{} : lambda;
  lambda += sampler.lod_bias;
  lambda = lambda < sampler.min_lod ? V{} + sampler.min_lod : lambda;
  lambda = sampler.max_lod < lambda ? V{} + sampler.max_lod : lambda;
  const I4 in_range = (lambda > -1e30f) & (lambda < 1e30f);
  return in_range ? lambda : lambda > 0.f ? V{} + 1e30f : V{} - 1e30f;
}

// levels_at's choice over four lanes for the filters that blend two levels (NEAREST_ or
// LINEAR_MIPMAP_LINEAR): `first`, `two` (lanes) and the blend in 1/256 (where two).
inline void blended_levels_lanes(const Sampler& sampler, F4 lambda, int max_level, I4& first, I4& two, I4& blend256) {
  const float c = sampler.mag_filter == TexFilter::Linear && sampler.min_filter == TexFilter::NearestMipmapLinear ? 0.5f : 0.f;
  const I4 magnified = lambda <= c, top = lambda >= static_cast<float>(max_level);
  two = ~magnified & ~top;
  const F4 inside = two ? lambda : F4{};  // positive: truncation is floor
  const I4 whole = __builtin_convertvector(inside, I4);
  first = two ? whole : top ? I4{} + max_level : I4{};
  blend256 = __builtin_convertvector((inside - __builtin_convertvector(whole, F4)) * 256.f, I4);
}

}  // namespace pineda::raster
