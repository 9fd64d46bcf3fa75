#include "raster/sampler_volume.h"

#include <algorithm>

#include "raster/mip_selection.h"
#include "raster/quad_vector.h"
#include "raster/srgb.h"
#include "raster/texel_addressing.h"

namespace pineda::raster {
namespace {

// i, j, k: texel indices, any of them -1 for the border colour.
F4 texel_or_border(const TextureLevel& level, const Sampler& sampler, int i, int j, int k) {
  if (i < 0 || j < 0 || k < 0) {
    const F4 c = load4(sampler.border_color), zero = splat(0.f), one = splat(1.f);
    return c < zero ? zero : (one < c ? one : c);
  }
  return texel_to_rgba(level, level.texels[(static_cast<size_t>(k) * level.height + j) * level.width + i]);
}

float volume_lambda(const TextureLevel& base, const float s[4], const float t[4], const float r[4]) {
  const float w = static_cast<float>(base.width), h = static_cast<float>(base.height);
  const float d = static_cast<float>(base.depth);
  const float dudx = (s[1] - s[0]) * w, dvdx = (t[1] - t[0]) * h, dwdx = (r[1] - r[0]) * d;
  const float dudy = (s[2] - s[0]) * w, dvdy = (t[2] - t[0]) * h, dwdy = (r[2] - r[0]) * d;
  return lambda_from_rho2(
      std::max(dudx * dudx + dvdx * dvdx + dwdx * dwdx, dudy * dudy + dvdy * dvdy + dwdy * dwdy));
}

// Filtering within one level.
F4 sample_level(const TextureLevel& level, const Sampler& sampler, bool linear, float s, float t, float r, int slice) {
  if (!linear) {
    const int i = nearest_index(sampler.wrap_s, s, level.width);
    const int j = nearest_index(sampler.wrap_t, t, level.height);
    const int k = slice >= 0 ? slice : nearest_index(sampler.wrap_r, r, level.depth);
    return texel_or_border(level, sampler, i, j, k);
  }
  int i0, i1, j0, j1, k0 = slice, k1 = slice;
  float a, b, c = 0.f;
  linear_indices(sampler.wrap_s, s, level.width, i0, i1, a);
  linear_indices(sampler.wrap_t, t, level.height, j0, j1, b);
  if (slice < 0) linear_indices(sampler.wrap_r, r, level.depth, k0, k1, c);
  auto plane = [&](int k) {
    return splat((1 - a) * (1 - b)) * texel_or_border(level, sampler, i0, j0, k) +
           splat(a * (1 - b)) * texel_or_border(level, sampler, i1, j0, k) +
           splat((1 - a) * b) * texel_or_border(level, sampler, i0, j1, k) +
           splat(a * b) * texel_or_border(level, sampler, i1, j1, k);
  };
  if (slice >= 0) return plane(slice);
  return splat(1 - c) * plane(k0) + splat(c) * plane(k1);
}

}  // namespace

void sample_slices(const TextureImage& image, const Sampler& sampler, const LevelChoice& choice, float s, float t,
                   float r, int slice, float out[4]) {
  const F4 first = sample_level(image.levels[choice.first], sampler, choice.linear, s, t, r, slice);
  if (!choice.two) return store4(out, first);
  const F4 second = sample_level(image.levels[choice.first + 1], sampler, choice.linear, s, t, r, slice);
  store4(out, splat(1 - choice.blend) * first + splat(choice.blend) * second);
}

void sample_volume_quad(const TextureImage& image, const Sampler& sampler, const float s_in[4], const float t_in[4],
                        const float r_in[4], float out[4][4]) {
  float s[4], t[4], r[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = sane(s_in[i]);
    t[i] = sane(t_in[i]);
    r[i] = sane(r_in[i]);
  }
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  const LevelChoice choice = choose_levels(sampler, volume_lambda(image.levels[0], s, t, r), max_level);
  for (int i = 0; i < 4; ++i) sample_slices(image, sampler, choice, s[i], t[i], r[i], -1, out[i]);
}

}  // namespace pineda::raster
