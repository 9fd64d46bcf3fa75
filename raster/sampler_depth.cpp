#include "raster/sampler_depth.h"

#include <algorithm>
#include <bit>
#include <cstdint>

#include "raster/fragment_ops.h"
#include "raster/mip_selection.h"
#include "raster/sampler.h"
#include "raster/texel_addressing.h"

namespace pineda::raster {
namespace {

// What one texel contributes: its depth, or 0/1 from the comparison with `ref`. kTexels: s and
// t are in texels (a rectangle texture: texel_addressing.h).
template <bool kTexels>
struct DepthLookup {
  const Sampler& sampler;
  bool compare;
  float ref;

  float texel(const TextureLevel& level, int i, int j) const {
    const float d = i < 0 || j < 0 ? std::clamp(sampler.border_color[0], 0.f, 1.f)
                                   : std::bit_cast<float>(level.texels[static_cast<size_t>(j) * level.width + i]);
    return compare ? (raster::compare(sampler.compare_func, ref, d) ? 1.f : 0.f) : d;
  }

  float level_value(const TextureLevel& level, bool linear, float s, float t) const {
    if (!linear)
      return texel(level, nearest_index<kTexels>(sampler.wrap_s, s, level.width),
                   nearest_index<kTexels>(sampler.wrap_t, t, level.height));
    int i0, i1, j0, j1;
    float a, b;
    linear_indices<kTexels>(sampler.wrap_s, s, level.width, i0, i1, a);
    linear_indices<kTexels>(sampler.wrap_t, t, level.height, j0, j1, b);
    return (1 - a) * (1 - b) * texel(level, i0, j0) + a * (1 - b) * texel(level, i1, j0) +
           (1 - a) * b * texel(level, i0, j1) + a * b * texel(level, i1, j1);
  }
};

void expand(float v, TexBaseFormat base, float out[4]) {
  switch (base) {
    case TexBaseFormat::Intensity: out[0] = out[1] = out[2] = out[3] = v; return;
    case TexBaseFormat::Alpha: out[0] = out[1] = out[2] = 0.f; out[3] = v; return;
    default: out[0] = out[1] = out[2] = v; out[3] = 1.f; return;  // Luminance
  }
}

template <bool kTexels>
void sample_depth_quad_in(const TextureImage& image, const Sampler& sampler, const float s_in[4], const float t_in[4],
                          const float r[4], float out[4][4]) {
  float s[4], t[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = sane(s_in[i]);
    t[i] = sane(t_in[i]);
  }
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  const float lambda = kTexels ? quad_lambda(1.f, 1.f, s, t) : quad_lambda(image.levels[0], s, t);
  const LevelChoice choice = choose_levels(sampler, lambda, max_level);
  const bool compare = sampler.compare && r;
  for (int i = 0; i < 4; ++i) {
    const float ref = compare ? std::clamp(r[i], 0.f, 1.f) : 0.f;  // NaN stays NaN: every test but != fails
    const DepthLookup<kTexels> lookup{sampler, compare, ref};
    float v = lookup.level_value(image.levels[choice.first], choice.linear, s[i], t[i]);
    if (choice.two) {
      const float v1 = lookup.level_value(image.levels[choice.first + 1], choice.linear, s[i], t[i]);
      v = (1 - choice.blend) * v + choice.blend * v1;
    }
    expand(v, image.base_format, out[i]);
    if (image.depth_swizzle != kIdentitySwizzle) swizzle_rgba(image.depth_swizzle, out[i]);
  }
}

}  // namespace

void sample_depth_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                       const float r[4], float out[4][4]) {
  if (image.kind == TexKind::Rect) return sample_depth_quad_in<true>(image, sampler, s, t, r, out);
  sample_depth_quad_in<false>(image, sampler, s, t, r, out);
}

}  // namespace pineda::raster
