#include "raster/sampler.h"

#include <algorithm>
#include <cmath>

#include "raster/quad_vector.h"

namespace pineda::raster {
namespace {

// Keeps coordinates where float-to-int conversions are defined; NaN becomes 0.
float sane(float v) { return v > -1e6f ? (v < 1e6f ? v : 1e6f) : (v <= -1e6f ? -1e6f : 0.f); }

// floor() for |v| < 2^31 without a libm call (the x86-64 baseline has no round instruction).
inline float floor_fast(float v) {
  const float t = static_cast<float>(static_cast<int>(v));
  return t > v ? t - 1.f : t;
}

inline int floor_int(float v) {
  const int i = static_cast<int>(v);
  return static_cast<float>(i) > v ? i - 1 : i;
}

float mirror(float s) {
  const float f = floor_fast(s);
  const float frac = s - f;
  return (static_cast<int>(f) & 1) ? 1.f - frac : frac;
}

F4 fetch(const TextureLevel& level, int i, int j) {
  const uint32_t texel = level.texels[static_cast<size_t>(j) * level.width + i];
  return from_unorm8(U4{texel, texel >> 8, texel >> 16, texel >> 24});
}

// Texel index along one axis for nearest filtering; -1 means the border colour.
int nearest_index(TexWrap wrap, float s, int size) {
  switch (wrap) {
    case TexWrap::Repeat: {
      const int i = floor_int((s - floor_fast(s)) * size);
      return std::min(i, size - 1);
    }
    case TexWrap::MirroredRepeat:
      return std::clamp(floor_int(mirror(s) * size), 0, size - 1);
    case TexWrap::ClampToBorder: {
      const int i = floor_int(std::clamp(s, -1.f, 2.f) * size);
      return i < 0 || i >= size ? -1 : i;
    }
    case TexWrap::Clamp:
    case TexWrap::ClampToEdge:
      break;
  }
  return std::clamp(floor_int(std::clamp(s, 0.f, 1.f) * size), 0, size - 1);
}

// The two texel indices and the weight of the second one for linear filtering.
void linear_indices(TexWrap wrap, float s, int size, int& i0, int& i1, float& frac) {
  float u = 0.f;
  switch (wrap) {
    case TexWrap::Repeat: u = (s - floor_fast(s)) * size - 0.5f; break;
    case TexWrap::MirroredRepeat: u = mirror(s) * size - 0.5f; break;
    case TexWrap::Clamp: u = std::clamp(s, 0.f, 1.f) * size - 0.5f; break;
    case TexWrap::ClampToEdge: u = std::clamp(s * size, 0.5f, size - 0.5f) - 0.5f; break;
    case TexWrap::ClampToBorder: u = std::clamp(s, -1.f, 2.f) * size - 0.5f; break;
  }
  const float f = floor_fast(u);
  frac = u - f;
  i0 = static_cast<int>(f);
  i1 = i0 + 1;
  switch (wrap) {
    case TexWrap::Repeat:
      // s - floor(s) lies in [0, 1] (1 when rounding a tiny negative s), so i0 >= -1 and
      // i1 <= size: one step wraps them.
      i0 = i0 < 0 ? i0 + size : i0;
      i1 = i1 >= size ? i1 - size : i1;
      break;
    case TexWrap::MirroredRepeat:
    case TexWrap::ClampToEdge:
      i0 = std::clamp(i0, 0, size - 1);
      i1 = std::clamp(i1, 0, size - 1);
      break;
    case TexWrap::Clamp:
    case TexWrap::ClampToBorder:  // out of range: the border colour
      if (i0 < 0 || i0 >= size) i0 = -1;
      if (i1 < 0 || i1 >= size) i1 = -1;
      break;
  }
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

// kRepeat: both wrap modes are REPEAT, so no index can select the border colour.
template <bool kRepeat>
[[gnu::always_inline]] inline F4 sample_level(const TextureLevel& level, const Sampler& sampler, bool linear, float s,
                                              float t) {
  if (!linear) {
    const int i = nearest_index(sampler.wrap_s, s, level.width);
    const int j = nearest_index(sampler.wrap_t, t, level.height);
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
    linear_indices(sampler.wrap_s, s, level.width, i0, i1, a);
    linear_indices(sampler.wrap_t, t, level.height, j0, j1, b);
    t00 = texel_or_border(level, sampler, i0, j0);
    t10 = texel_or_border(level, sampler, i1, j0);
    t01 = texel_or_border(level, sampler, i0, j1);
    t11 = texel_or_border(level, sampler, i1, j1);
  }
  return splat((1 - a) * (1 - b)) * t00 + splat(a * (1 - b)) * t10 + splat((1 - a) * b) * t01 + splat(a * b) * t11;
}

template <bool kRepeat>
void sample_level(const TextureLevel& level, const Sampler& sampler, bool linear, float s, float t, float out[4]) {
  store4(out, sample_level<kRepeat>(level, sampler, linear, s, t));
}

bool is_linear(TexFilter f) {
  return f == TexFilter::Linear || f == TexFilter::LinearMipmapNearest || f == TexFilter::LinearMipmapLinear;
}

}  // namespace

float quad_lambda(const TextureLevel& base, const float s[4], const float t[4]) {
  const float w = static_cast<float>(base.width), h = static_cast<float>(base.height);
  const float dudx = (s[1] - s[0]) * w, dvdx = (t[1] - t[0]) * h;
  const float dudy = (s[2] - s[0]) * w, dvdy = (t[2] - t[0]) * h;
  const float rho2 = std::max(dudx * dudx + dvdx * dvdx, dudy * dudy + dvdy * dvdy);
  // lambda = log2(rho) = log2(rho^2) / 2, with log2 taken piecewise linear between powers of
  // two (exact at them). GL allows approximating lambda; this is the approximation llvmpipe
  // uses, so that mipmap blends match it.
  if (!(rho2 > 0.f)) return rho2 == 0.f ? -INFINITY : NAN;
  int e;
  const float m = std::frexp(rho2, &e);  // rho2 = m * 2^e, m in [0.5, 1)
  return 0.5f * (static_cast<float>(e - 1) + (2.f * m - 1.f));
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

template <bool kRepeat>
void sample_quad_wrapped(const TextureImage& image, const Sampler& sampler, const float s_in[4], const float t_in[4],
                         float out[4][4]) {
  float s[4], t[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = sane(s_in[i]);
    t[i] = sane(t_in[i]);
  }
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  float lambda = quad_lambda(image.levels[0], s, t);
  if (std::isnan(lambda)) lambda = 0.f;
  lambda = std::min(std::max(lambda + sampler.lod_bias, sampler.min_lod), sampler.max_lod);
  if (!(lambda > -1e30f && lambda < 1e30f)) lambda = lambda > 0 ? 1e30f : -1e30f;

  const TexFilter min = sampler.min_filter;
  const bool mag_linear = sampler.mag_filter == TexFilter::Linear;
  const float c = mag_linear && (min == TexFilter::NearestMipmapNearest || min == TexFilter::NearestMipmapLinear)
                      ? 0.5f
                      : 0.f;
  if (lambda <= c || min == TexFilter::Nearest || min == TexFilter::Linear) {
    const bool linear = lambda <= c ? mag_linear : min == TexFilter::Linear;
    for (int i = 0; i < 4; ++i) sample_level<kRepeat>(image.levels[0], sampler, linear, s[i], t[i], out[i]);
    return;
  }
  const bool linear = is_linear(min);
  if (min == TexFilter::NearestMipmapNearest || min == TexFilter::LinearMipmapNearest) {
    const int d = lambda <= 0.5f ? 0 : std::min(static_cast<int>(std::ceil(std::min(lambda, 1e6f) + 0.5f)) - 1, max_level);
    for (int i = 0; i < 4; ++i) sample_level<kRepeat>(image.levels[d], sampler, linear, s[i], t[i], out[i]);
    return;
  }
  if (lambda >= static_cast<float>(max_level)) {
    for (int i = 0; i < 4; ++i) sample_level<kRepeat>(image.levels[max_level], sampler, linear, s[i], t[i], out[i]);
    return;
  }
  const int d1 = static_cast<int>(std::floor(lambda));
  const float f = lambda - static_cast<float>(d1);
  if (kRepeat && linear) {
    F4 a[4], b[4];
    bilinear_repeat_quad(image.levels[d1], load4(s), load4(t), a);
    bilinear_repeat_quad(image.levels[d1 + 1], load4(s), load4(t), b);
    for (int i = 0; i < 4; ++i) store4(out[i], splat(1 - f) * a[i] + splat(f) * b[i]);
    return;
  }
  for (int i = 0; i < 4; ++i) {
    const F4 a = sample_level<kRepeat>(image.levels[d1], sampler, linear, s[i], t[i]);
    const F4 b = sample_level<kRepeat>(image.levels[d1 + 1], sampler, linear, s[i], t[i]);
    store4(out[i], splat(1 - f) * a + splat(f) * b);
  }
}

}  // namespace

void sample_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                 float out[4][4]) {
  if (sampler.wrap_s == TexWrap::Repeat && sampler.wrap_t == TexWrap::Repeat)
    sample_quad_wrapped<true>(image, sampler, s, t, out);
  else
    sample_quad_wrapped<false>(image, sampler, s, t, out);
}

}  // namespace pineda::raster
