#include "raster/sampler.h"

#include <algorithm>
#include <cmath>

#include "raster/mip_selection.h"
#include "raster/quad_vector.h"
#include "raster/sampler_depth.h"
#include "raster/sampler_volume.h"
#include "raster/srgb.h"
#include "raster/texel_addressing.h"

namespace pineda::raster {
namespace {

F4 fetch(const TextureLevel& level, int i, int j) {
  return texel_to_rgba(level, level.texels[static_cast<size_t>(j) * level.width + i]);
}

F4 texel_or_border(const TextureLevel& level, const Sampler& sampler, int i, int j) {
  if (i < 0 || j < 0) {
    const F4 c = load4(sampler.border_color), zero = splat(0.f), one = splat(1.f);
    return c < zero ? zero : (one < c ? one : c);  // std::clamp's order: NaN stays NaN
  }
  return fetch(level, i, j);
}

// linear_indices for REPEAT, with nothing left to choose at run time.
[[gnu::always_inline]] inline void repeat_indices(float s, int size, int& i0, int& i1, float& frac) {
  const float u = (s - floor_fast(s)) * size - 0.5f;
  const float f = floor_fast(u);
  frac = u - f;
  i0 = static_cast<int>(f);
  i1 = i0 + 1;
  i0 = i0 < 0 ? i0 + size : i0;
  i1 = i1 >= size ? i1 - size : i1;
}

// kRepeat: both wrap modes are REPEAT, so no index can select the border colour. kTexels: s and t
// are in texels (a rectangle texture: texel_addressing.h).
template <bool kRepeat, bool kTexels = false>
[[gnu::always_inline]] inline F4 sample_level(const TextureLevel& level, const Sampler& sampler, bool linear, float s,
                                              float t) {
  if (!linear) {
    const int i = nearest_index<kTexels>(sampler.wrap_s, s, level.width);
    const int j = nearest_index<kTexels>(sampler.wrap_t, t, level.height);
    return texel_or_border(level, sampler, i, j);
  }
  int i0, i1, j0, j1;
  float a, b;
  F4 t00, t10, t01, t11;
  if constexpr (kRepeat) {
    repeat_indices(s, level.width, i0, i1, a);
    repeat_indices(t, level.height, j0, j1, b);
    const uint32_t* row0 = level.texels.data() + static_cast<size_t>(j0) * level.width;
    const uint32_t* row1 = level.texels.data() + static_cast<size_t>(j1) * level.width;
    auto unpack = [](uint32_t texel) { return from_unorm8(U4{texel, texel >> 8, texel >> 16, texel >> 24}); };
    t00 = unpack(row0[i0]);
    t10 = unpack(row0[i1]);
    t01 = unpack(row1[i0]);
    t11 = unpack(row1[i1]);
  } else {
    linear_indices<kTexels>(sampler.wrap_s, s, level.width, i0, i1, a);
    linear_indices<kTexels>(sampler.wrap_t, t, level.height, j0, j1, b);
    t00 = texel_or_border(level, sampler, i0, j0);
    t10 = texel_or_border(level, sampler, i1, j0);
    t01 = texel_or_border(level, sampler, i0, j1);
    t11 = texel_or_border(level, sampler, i1, j1);
  }
  return splat((1 - a) * (1 - b)) * t00 + splat(a * (1 - b)) * t10 + splat((1 - a) * b) * t01 + splat(a * b) * t11;
}

template <bool kRepeat, bool kTexels>
void sample_level(const TextureLevel& level, const Sampler& sampler, bool linear, float s, float t, float out[4]) {
  store4(out, sample_level<kRepeat, kTexels>(level, sampler, linear, s, t));
}

}  // namespace

float quad_lambda(const TextureLevel& base, const float s[4], const float t[4]) {
  return quad_lambda(static_cast<float>(base.width), static_cast<float>(base.height), s, t);
}

float quad_lambda(float w, float h, const float s[4], const float t[4]) {
  const float dudx = (s[1] - s[0]) * w, dvdx = (t[1] - t[0]) * h;
  const float dudy = (s[2] - s[0]) * w, dvdy = (t[2] - t[0]) * h;
  return lambda_from_rho2(std::max(dudx * dudx + dvdx * dvdx, dudy * dudy + dvdy * dvdy));
}

namespace {

inline F4 floor_fast4(F4 v) {
  const F4 t = __builtin_convertvector(__builtin_convertvector(v, I4), F4);
  return t > v ? t - 1.f : t;
}

// repeat_indices for the four pixels at once (the same operations per lane).
inline void repeat_indices4(F4 s, int size, I4& i0, I4& i1, F4& frac) {
  const F4 u = (s - floor_fast4(s)) * static_cast<float>(size) - 0.5f;
  const F4 f = floor_fast4(u);
  frac = u - f;
  i0 = __builtin_convertvector(f, I4);
  i1 = i0 + 1;
  i0 = i0 < 0 ? i0 + size : i0;
  i1 = i1 >= size ? i1 - size : i1;
}

// Bilinear REPEAT/REPEAT samples of one level for the four pixels.
void bilinear_repeat_quad(const TextureLevel& level, F4 s, F4 t, F4 out[4]) {
  I4 i0, i1, j0, j1;
  F4 fa, fb;
  repeat_indices4(s, level.width, i0, i1, fa);
  repeat_indices4(t, level.height, j0, j1, fb);
  auto unpack = [](uint32_t texel) { return from_unorm8(U4{texel, texel >> 8, texel >> 16, texel >> 24}); };
  for (int i = 0; i < 4; ++i) {
    const uint32_t* row0 = level.texels.data() + static_cast<size_t>(j0[i]) * level.width;
    const uint32_t* row1 = level.texels.data() + static_cast<size_t>(j1[i]) * level.width;
    const float a = fa[i], b = fb[i];
    out[i] = splat((1 - a) * (1 - b)) * unpack(row0[i0[i]]) + splat(a * (1 - b)) * unpack(row0[i1[i]]) +
             splat((1 - a) * b) * unpack(row1[i0[i]]) + splat(a * b) * unpack(row1[i1[i]]);
  }
}

template <bool kRepeat, bool kTexels = false>
void sample_quad_wrapped(const TextureImage& image, const Sampler& sampler, const float s_in[4], const float t_in[4],
                         float out[4][4]) {
  float s[4], t[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = sane(s_in[i]);
    t[i] = sane(t_in[i]);
  }
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  const float lambda = kTexels ? quad_lambda(1.f, 1.f, s, t) : quad_lambda(image.levels[0], s, t);
  const LevelChoice choice = choose_levels(sampler, lambda, max_level);
  const bool linear = choice.linear;
  if (!choice.two) {
    for (int i = 0; i < 4; ++i)
      sample_level<kRepeat, kTexels>(image.levels[choice.first], sampler, linear, s[i], t[i], out[i]);
    return;
  }
  const int d1 = choice.first;
  const float f = choice.blend;
  if (kRepeat && linear) {
    F4 a[4], b[4];
    bilinear_repeat_quad(image.levels[d1], load4(s), load4(t), a);
    bilinear_repeat_quad(image.levels[d1 + 1], load4(s), load4(t), b);
    for (int i = 0; i < 4; ++i) store4(out[i], splat(1 - f) * a[i] + splat(f) * b[i]);
    return;
  }
  for (int i = 0; i < 4; ++i) {
    const F4 a = sample_level<kRepeat, kTexels>(image.levels[d1], sampler, linear, s[i], t[i]);
    const F4 b = sample_level<kRepeat, kTexels>(image.levels[d1 + 1], sampler, linear, s[i], t[i]);
    store4(out[i], splat(1 - f) * a + splat(f) * b);
  }
}

}  // namespace

void sample_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                 float out[4][4]) {
  if (image.depth) return sample_depth_quad(image, sampler, s, t, nullptr, out);
  if (image.kind == TexKind::Rect) return sample_quad_wrapped<false, true>(image, sampler, s, t, out);
  // sRGB images take the general path, whose one texel fetch decodes them.
  if (sampler.wrap_s == TexWrap::Repeat && sampler.wrap_t == TexWrap::Repeat && !image.levels[0].srgb)
    sample_quad_wrapped<true>(image, sampler, s, t, out);
  else
    sample_quad_wrapped<false>(image, sampler, s, t, out);
}

void sample_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                 const float r[4], float out[4][4]) {
  switch (image.kind) {
    case TexKind::Planar:
    case TexKind::Rect:
      return image.depth ? sample_depth_quad(image, sampler, s, t, r, out) : sample_quad(image, sampler, s, t, out);
    case TexKind::Volume: return sample_volume_quad(image, sampler, s, t, r, out);
    case TexKind::Cube: return sample_cube_quad(image, sampler, s, t, r, out);
  }
}

}  // namespace pineda::raster
