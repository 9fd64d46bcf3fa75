#include "raster/sampler_bilinear8.h"

#include <immintrin.h>

#include "raster/mip_selection.h"
#include "raster/sampler.h"

namespace pineda::raster {
namespace {

constexpr int kGatherBytes = 0;  // quads: four scalar loads
#include "raster/bilinear8_lanes.inc"

template <TexWrap kWrapS, TexWrap kWrapT>
[[gnu::always_inline]] inline void sample_body(const TextureImage& image, const Sampler& sampler, F4 s_in, F4 t_in,
                                               F4 out[4]) {
  const F4 s = sane_lanes(s_in), t = sane_lanes(t_in);
  const LevelChoice choice = bilinear8_quad_levels(image, sampler, s_in, t_in);
  I4 v[4];
  bilinear_lanes<kWrapS, kWrapT>(image.levels[choice.first], s, t, v);
  if (choice.two) {
    I4 w[4];
    bilinear_lanes<kWrapS, kWrapT>(image.levels[choice.first + 1], s, t, w);
    const int f = static_cast<int>(choice.blend * 256.f);  // blend < 1: f <= 255
    for (int c = 0; c < 4; ++c) v[c] = ((v[c] + 128) >> 8) * (256 - f) + ((w[c] + 128) >> 8) * f;
  }
  for (int c = 0; c < 4; ++c) out[c] = unorm_lanes<F4>(v[c]);
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
  const bool rect = image.kind == TexKind::Rect;  // clamped to the edge only (axis_lanes)
  if (image.depth || !(image.kind == TexKind::Planar || rect) || image.levels.empty() || image.levels[0].srgb)
    return nullptr;
  if (rect && (sampler.wrap_s != TexWrap::ClampToEdge || sampler.wrap_t != TexWrap::ClampToEdge)) return nullptr;
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
