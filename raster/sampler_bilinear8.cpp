#include "raster/sampler_bilinear8.h"

#include "raster/mip_selection.h"
#include "raster/sampler.h"

namespace pineda::raster {
namespace {

inline F4 floor4(F4 v) {
  const F4 t = __builtin_convertvector(__builtin_convertvector(v, I4), F4);
  return t > v ? t - 1.f : t;
}

// sane() per lane: coordinates where float-to-int conversions are defined; NaN becomes 0.
inline F4 sane4(F4 v) {
  const F4 hi = splat(1e6f), lo = splat(-1e6f);
  return v > lo ? (v < hi ? v : hi) : (v <= lo ? lo : splat(0.f));
}

// One axis: the two texel indices and the second one's weight in 1/256, for each lane. The
// coordinate u is the float one of linear_indices (texel_addressing.h), so the indices are too.
template <TexWrap kWrap>
[[gnu::always_inline]] inline void axis8(F4 s, int size, I4& i0, I4& i1, I4& weight) {
  const float n = static_cast<float>(size);
  F4 u;
  if constexpr (kWrap == TexWrap::Repeat) {
    u = (s - floor4(s)) * n - 0.5f;
  } else {
    const F4 x = s * n, lo = splat(0.5f), hi = splat(n - 0.5f);
    u = (x < lo ? lo : (hi < x ? hi : x)) - 0.5f;  // std::clamp's order
  }
  const I4 fixed = __builtin_convertvector(floor4(u * 256.f), I4);
  i0 = fixed >> 8;
  weight = fixed & 0xff;
  i1 = i0 + 1;
  if constexpr (kWrap == TexWrap::Repeat) {
    // u lies in [-0.5, size - 0.5], so one step wraps each index.
    i0 = i0 < 0 ? i0 + size : i0;
    i1 = i1 >= size ? i1 - size : i1;
  } else {
    i1 = i1 > size - 1 ? size - 1 : i1;
  }
}

inline I4 channel(U4 texels, int c) { return reinterpret_cast<I4>((texels >> (8 * c)) & 0xffu); }

// Bilinear samples of one level, channel c in out[c] scaled by 65536 (at most 255 * 65536).
template <TexWrap kWrapS, TexWrap kWrapT>
[[gnu::always_inline]] inline void bilinear_level(const TextureLevel& level, F4 s, F4 t, I4 out[4]) {
  I4 i0, i1, a, j0, j1, b;
  axis8<kWrapS>(s, level.width, i0, i1, a);
  axis8<kWrapT>(t, level.height, j0, j1, b);
  const I4 row0 = j0 * level.width, row1 = j1 * level.width;
  const uint32_t* texels = level.texels.data();
  U4 t00, t10, t01, t11;
  for (int i = 0; i < 4; ++i) {
    t00[i] = texels[row0[i] + i0[i]];
    t10[i] = texels[row0[i] + i1[i]];
    t01[i] = texels[row1[i] + i0[i]];
    t11[i] = texels[row1[i] + i1[i]];
  }
  for (int c = 0; c < 4; ++c) {
    const I4 c00 = channel(t00, c), c01 = channel(t01, c);
    const I4 top = (c00 << 8) + (channel(t10, c) - c00) * a;
    const I4 bottom = (c01 << 8) + (channel(t11, c) - c01) * a;
    out[c] = (top << 8) + (bottom - top) * b;
  }
}

template <TexWrap kWrapS, TexWrap kWrapT>
[[gnu::always_inline]] inline void sample_body(const TextureImage& image, const Sampler& sampler, F4 s_in, F4 t_in,
                                               F4 out[4]) {
  const F4 s = sane4(s_in), t = sane4(t_in);
  float sa[4], ta[4];
  store4(sa, s);
  store4(ta, t);
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  // Without mipmaps both magnification and minification filter level 0 bilinearly: the level
  // of detail changes nothing (choose_levels returns level 0 for any lambda).
  const LevelChoice choice = sampler.min_filter == TexFilter::Linear
                                 ? LevelChoice{}
                                 : choose_levels(sampler, quad_lambda(image.levels[0], sa, ta), max_level);
  I4 v[4];
  bilinear_level<kWrapS, kWrapT>(image.levels[choice.first], s, t, v);
  if (choice.two) {
    I4 w[4];
    bilinear_level<kWrapS, kWrapT>(image.levels[choice.first + 1], s, t, w);
    const int f = static_cast<int>(choice.blend * 256.f);  // blend < 1: f <= 255
    for (int c = 0; c < 4; ++c) v[c] = ((v[c] + 128) >> 8) * (256 - f) + ((w[c] + 128) >> 8) * f;
  }
  // As from_unorm8 when every weight is 0 or 1: the texel's own float value.
  for (int c = 0; c < 4; ++c) out[c] = __builtin_convertvector(v[c], F4) * (1.f / 65536.f) * (1.f / 255.f);
}

// The baseline copy and an AVX2 one (native 32-bit multiplies and lane inserts); integers only,
// so both give the same texels.
template <TexWrap kWrapS, TexWrap kWrapT>
void sample_bilinear8(const TextureImage& image, const Sampler& sampler, F4 s, F4 t, F4 out[4]) {
  sample_body<kWrapS, kWrapT>(image, sampler, s, t, out);
}

template <TexWrap kWrapS, TexWrap kWrapT>
[[gnu::target("avx2")]] void sample_bilinear8_avx2(const TextureImage& image, const Sampler& sampler, F4 s, F4 t,
                                                   F4 out[4]) {
  sample_body<kWrapS, kWrapT>(image, sampler, s, t, out);
}

template <TexWrap kWrapS, TexWrap kWrapT>
QuadSampler for_path(bool avx2) {
  return avx2 ? &sample_bilinear8_avx2<kWrapS, kWrapT> : &sample_bilinear8<kWrapS, kWrapT>;
}

template <TexWrap kWrapS>
QuadSampler for_wrap_t(TexWrap t, bool avx2) {
  return t == TexWrap::Repeat ? for_path<kWrapS, TexWrap::Repeat>(avx2) : for_path<kWrapS, TexWrap::ClampToEdge>(avx2);
}

bool wrap_supported(TexWrap w) { return w == TexWrap::Repeat || w == TexWrap::ClampToEdge; }

}  // namespace

QuadSampler select_bilinear8_sampler(const TextureImage& image, const Sampler& sampler, SimdPath path) {
  if (image.depth || image.kind != TexKind::Planar || image.levels.empty() || image.levels[0].srgb) return nullptr;
  const TexFilter min = sampler.min_filter;
  if (sampler.mag_filter != TexFilter::Linear ||
      !(min == TexFilter::Linear || min == TexFilter::LinearMipmapNearest || min == TexFilter::LinearMipmapLinear))
    return nullptr;
  if (!wrap_supported(sampler.wrap_s) || !wrap_supported(sampler.wrap_t)) return nullptr;
  const bool avx2 = uses_avx2(path);
  return sampler.wrap_s == TexWrap::Repeat ? for_wrap_t<TexWrap::Repeat>(sampler.wrap_t, avx2)
                                           : for_wrap_t<TexWrap::ClampToEdge>(sampler.wrap_t, avx2);
}

}  // namespace pineda::raster
