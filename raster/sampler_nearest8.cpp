#include "raster/sampler_nearest8.h"

#include "raster/quad_vector.h"
#include "raster/texel_addressing.h"

namespace pineda::raster {
namespace {

// floor_int() and nearest_index() of texel_addressing.h for four lanes (with its sane4): the
// same operations in each lane, so the same indices.
inline I4 floor_int4(F4 v) {
  const I4 i = __builtin_convertvector(v, I4);
  return i + (__builtin_convertvector(i, F4) > v);  // a true comparison is -1
}

template <TexWrap kWrap>
inline I4 nearest_index4(F4 s, int size) {
  const I4 last = I4{} + (size - 1);
  if constexpr (kWrap == TexWrap::Repeat) {
    const I4 i = floor_int4((s - __builtin_convertvector(floor_int4(s), F4)) * static_cast<float>(size));
    return last < i ? last : i;
  } else if constexpr (kWrap == TexWrap::ClampToEdge) {
    const F4 zero = F4{}, one = splat(1.f);
    const F4 clamped = s < zero ? zero : (one < s ? one : s);
    const I4 i = floor_int4(clamped * static_cast<float>(size));
    return i < I4{} ? I4{} : (last < i ? last : i);
  } else {
    I4 out;
    for (int k = 0; k < 4; ++k) out[k] = nearest_index(kWrap, s[k], size);
    return out;
  }
}

template <TexWrap kWrapS, TexWrap kWrapT>
void sample_nearest8(const TextureImage& image, const Sampler&, F4 s, F4 t, F4 out[4]) {
  const TextureLevel& level = image.levels[0];
  const I4 x = nearest_index4<kWrapS>(sane4(s), level.width), y = nearest_index4<kWrapT>(sane4(t), level.height);
  const I4 at = y * level.width + x;  // below the texel count: the indices lie inside the level
  const U4 texels = {level.texels[static_cast<size_t>(at[0])], level.texels[static_cast<size_t>(at[1])],
                     level.texels[static_cast<size_t>(at[2])], level.texels[static_cast<size_t>(at[3])]};
  for (int c = 0; c < 4; ++c) out[c] = from_unorm8(texels >> static_cast<unsigned>(8 * c));
}

template <TexWrap kWrapS>
QuadSampler for_wrap_t(TexWrap t) {
  switch (t) {
    case TexWrap::Repeat: return &sample_nearest8<kWrapS, TexWrap::Repeat>;
    case TexWrap::MirroredRepeat: return &sample_nearest8<kWrapS, TexWrap::MirroredRepeat>;
    case TexWrap::Clamp: case TexWrap::ClampToEdge: return &sample_nearest8<kWrapS, TexWrap::ClampToEdge>;
    case TexWrap::ClampToBorder: break;
  }
  return nullptr;
}

}  // namespace

QuadSampler select_nearest8_sampler(const TextureImage& image, const Sampler& sampler) {
  if (image.depth || image.kind != TexKind::Planar || image.levels.empty() || image.levels[0].srgb) return nullptr;
  if (sampler.mag_filter != TexFilter::Nearest || sampler.min_filter != TexFilter::Nearest) return nullptr;
  const TextureLevel& level = image.levels[0];
  if (level.width <= 0 || level.height <= 0 || level.texels.size() < static_cast<size_t>(level.width) * level.height)
    return nullptr;
  switch (sampler.wrap_s) {
    case TexWrap::Repeat: return for_wrap_t<TexWrap::Repeat>(sampler.wrap_t);
    case TexWrap::MirroredRepeat: return for_wrap_t<TexWrap::MirroredRepeat>(sampler.wrap_t);
    case TexWrap::Clamp: case TexWrap::ClampToEdge: return for_wrap_t<TexWrap::ClampToEdge>(sampler.wrap_t);
    case TexWrap::ClampToBorder: break;
  }
  return nullptr;
}

}  // namespace pineda::raster
