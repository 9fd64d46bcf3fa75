#include "raster/sampler.h"

#include <algorithm>
#include <cmath>

namespace pineda::raster {
namespace {

// Keeps coordinates where float-to-int conversions are defined; NaN becomes 0.
float sane(float v) { return v > -1e6f ? (v < 1e6f ? v : 1e6f) : (v <= -1e6f ? -1e6f : 0.f); }

int floor_int(float v) { return static_cast<int>(std::floor(v)); }

float mirror(float s) {
  const float f = std::floor(s);
  const float frac = s - f;
  return (static_cast<int>(f) & 1) ? 1.f - frac : frac;
}

void fetch(const TextureLevel& level, int i, int j, float out[4]) {
  const uint32_t texel = level.texels[static_cast<size_t>(j) * level.width + i];
  for (int c = 0; c < 4; ++c) out[c] = static_cast<float>((texel >> (8 * c)) & 0xff) * (1.f / 255.f);
}

// Texel index along one axis for nearest filtering; -1 means the border colour.
int nearest_index(TexWrap wrap, float s, int size) {
  switch (wrap) {
    case TexWrap::Repeat: {
      const int i = floor_int((s - std::floor(s)) * size);
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
    case TexWrap::Repeat: u = (s - std::floor(s)) * size - 0.5f; break;
    case TexWrap::MirroredRepeat: u = mirror(s) * size - 0.5f; break;
    case TexWrap::Clamp: u = std::clamp(s, 0.f, 1.f) * size - 0.5f; break;
    case TexWrap::ClampToEdge: u = std::clamp(s * size, 0.5f, size - 0.5f) - 0.5f; break;
    case TexWrap::ClampToBorder: u = std::clamp(s, -1.f, 2.f) * size - 0.5f; break;
  }
  const float f = std::floor(u);
  frac = u - f;
  i0 = static_cast<int>(f);
  i1 = i0 + 1;
  switch (wrap) {
    case TexWrap::Repeat:
      i0 = ((i0 % size) + size) % size;
      i1 = ((i1 % size) + size) % size;
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

void texel_or_border(const TextureLevel& level, const Sampler& sampler, int i, int j, float out[4]) {
  if (i < 0 || j < 0) {
    for (int c = 0; c < 4; ++c) out[c] = std::clamp(sampler.border_color[c], 0.f, 1.f);
    return;
  }
  fetch(level, i, j, out);
}

void sample_level(const TextureLevel& level, const Sampler& sampler, bool linear, float s, float t, float out[4]) {
  if (!linear) {
    const int i = nearest_index(sampler.wrap_s, s, level.width);
    const int j = nearest_index(sampler.wrap_t, t, level.height);
    texel_or_border(level, sampler, i, j, out);
    return;
  }
  int i0, i1, j0, j1;
  float a, b;
  linear_indices(sampler.wrap_s, s, level.width, i0, i1, a);
  linear_indices(sampler.wrap_t, t, level.height, j0, j1, b);
  float t00[4], t10[4], t01[4], t11[4];
  texel_or_border(level, sampler, i0, j0, t00);
  texel_or_border(level, sampler, i1, j0, t10);
  texel_or_border(level, sampler, i0, j1, t01);
  texel_or_border(level, sampler, i1, j1, t11);
  for (int c = 0; c < 4; ++c)
    out[c] = (1 - a) * (1 - b) * t00[c] + a * (1 - b) * t10[c] + (1 - a) * b * t01[c] + a * b * t11[c];
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

void sample_quad(const TextureImage& image, const Sampler& sampler, const float s_in[4], const float t_in[4],
                 float out[4][4]) {
  float s[4], t[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = sane(s_in[i]);
    t[i] = sane(t_in[i]);
  }
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  float lambda = quad_lambda(image.levels[0], s, t);
  if (std::isnan(lambda)) lambda = 0.f;
  lambda = std::min(std::max(lambda, sampler.min_lod), sampler.max_lod);
  if (!(lambda > -1e30f && lambda < 1e30f)) lambda = lambda > 0 ? 1e30f : -1e30f;

  const TexFilter min = sampler.min_filter;
  const bool mag_linear = sampler.mag_filter == TexFilter::Linear;
  const float c = mag_linear && (min == TexFilter::NearestMipmapNearest || min == TexFilter::NearestMipmapLinear)
                      ? 0.5f
                      : 0.f;
  if (lambda <= c || min == TexFilter::Nearest || min == TexFilter::Linear) {
    const bool linear = lambda <= c ? mag_linear : min == TexFilter::Linear;
    for (int i = 0; i < 4; ++i) sample_level(image.levels[0], sampler, linear, s[i], t[i], out[i]);
    return;
  }
  const bool linear = is_linear(min);
  if (min == TexFilter::NearestMipmapNearest || min == TexFilter::LinearMipmapNearest) {
    const int d = lambda <= 0.5f ? 0 : std::min(static_cast<int>(std::ceil(std::min(lambda, 1e6f) + 0.5f)) - 1, max_level);
    for (int i = 0; i < 4; ++i) sample_level(image.levels[d], sampler, linear, s[i], t[i], out[i]);
    return;
  }
  if (lambda >= static_cast<float>(max_level)) {
    for (int i = 0; i < 4; ++i) sample_level(image.levels[max_level], sampler, linear, s[i], t[i], out[i]);
    return;
  }
  const int d1 = static_cast<int>(std::floor(lambda));
  const float f = lambda - static_cast<float>(d1);
  for (int i = 0; i < 4; ++i) {
    float a[4], b[4];
    sample_level(image.levels[d1], sampler, linear, s[i], t[i], a);
    sample_level(image.levels[d1 + 1], sampler, linear, s[i], t[i], b);
    for (int k = 0; k < 4; ++k) out[i][k] = (1 - f) * a[k] + f * b[k];
  }
}

}  // namespace pineda::raster
