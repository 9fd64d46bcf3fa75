#include "raster/shader_textures.h"

#include <algorithm>
#include <cmath>

#include "raster/sampler.h"
#include "raster/sampler_bilinear8.h"
#include "raster/sampler_bilinear_block.h"
#include "raster/sampler_depth.h"
#include "raster/sampler_nearest8.h"

namespace pineda::raster {
namespace {

using shader::kLanes;
using shader::SamplerKind;

bool kind_matches(const TextureImage& image, SamplerKind kind) {
  switch (kind) {
    // A depth texture read by sampler1D/2D gives its depth as DEPTH_TEXTURE_MODE places it (GL 2.0 3.8.14).
    case SamplerKind::Tex1D: case SamplerKind::Tex2D: return image.kind == TexKind::Planar;
    case SamplerKind::Tex3D: return image.kind == TexKind::Volume;
    case SamplerKind::Cube: return image.kind == TexKind::Cube;
    case SamplerKind::Shadow1D: case SamplerKind::Shadow2D: return image.kind == TexKind::Planar && image.depth;
    case SamplerKind::Rect: return image.kind == TexKind::Rect;
    case SamplerKind::ShadowRect: return image.kind == TexKind::Rect && image.depth;
  }
  return false;
}

// GL 2.0 table 3.20: what a shader reads of each base format, for one texel (float) or four
// lanes (F4); the block samplers' apply_base_format_lanes is the same table.
template <typename V>
void apply_base_format(TexBaseFormat format, V t[4]) {
  const V zero = V{}, one = zero + 1.f;
  switch (format) {
    case TexBaseFormat::Alpha: t[0] = t[1] = t[2] = zero; break;
    case TexBaseFormat::Luminance: t[1] = t[2] = t[0]; t[3] = one; break;
    case TexBaseFormat::LuminanceAlpha: t[1] = t[2] = t[0]; break;
    case TexBaseFormat::Intensity: t[1] = t[2] = t[3] = t[0]; break;
    case TexBaseFormat::RGB: t[3] = one; break;
    case TexBaseFormat::RGBA: break;
  }
}

// The sampler reads level 0 only: it has no mipmap filter.
bool reads_level_zero(const Sampler& sampler) {
  return sampler.min_filter == TexFilter::Linear || sampler.min_filter == TexFilter::Nearest;
}

// The fast sampler's lookups of a whole block at once when its live quads read the same level
// or pair of levels, each with its own weight between the pair (the same per-quad choice, bias
// included, as the quad sampler's); false otherwise. Only for an image and sampler that
// select_bilinear8_sampler or select_nearest8_sampler takes.
bool sample_block_at_one_level(BlockSampler block, const TextureImage& image, const Sampler& sampler, const float* s,
                               const float* t, shader::LodMode mode, const float* lod, shader::LaneMask live,
                               float* const out[4]) {
  BlockLevels levels;
  // For every quad: no mipmaps (the nearest sampler's magnification and minification are alike).
  const bool level_zero = reads_level_zero(sampler);
  bool any = level_zero && live != 0;
  if (!level_zero) {
    F4 bias = splat(sampler.lod_bias);
    for (int q = 0; q < 4; ++q)
      if (mode == shader::LodMode::Bias && lod && std::isfinite(lod[4 * q])) bias[q] = sampler.lod_bias + lod[4 * q];
    const F4 lambda = bilinear8_block_lambdas(image, sampler, s, t, bias);
    const int max_level = static_cast<int>(image.levels.size()) - 1;
    for (int q = 0; q < 4; ++q) {
      if (!((live >> (4 * q)) & 0xf)) continue;
      const LevelChoice c = levels_at(sampler, lambda[q], max_level);
      if (any && (c.first != levels.first || c.two != levels.two)) return false;
      levels.first = c.first;
      levels.two = c.two;
      levels.blend[q] = c.blend;
      any = true;
    }
  }
  if (!any) return false;
  block(image, levels, s, t, out);  // with the base format applied
  // The quads without a live lane read (0, 0, 0, 1), as the general sampler gives them.
  for (int first = 0; first < kLanes; first += 4) {
    if ((live >> first) & 0xf) continue;
    for (int c = 0; c < 4; ++c) store4(&out[c][first], splat(c == 3 ? 1.f : 0.f));
  }
  return true;
}

}  // namespace

bool UnitTextureAccess::sample_2d_block(int unit, const float* s, const float* t, shader::LaneMask live,
                                        float* const out[4]) const {
  if (const FastSamplers* known = level_zero_route(unit)) {
    known->block(*known->level_zero_image, BlockLevels{}, s, t, out);
    return true;
  }
  const TextureUnit* tu = unit >= 0 && unit < kMaxTextureImageUnits ? &units_[unit] : nullptr;
  const TextureImage* image = tu && tu->image ? tu->image.get() : nullptr;
  if (!image || !kind_matches(*image, SamplerKind::Tex2D)) return false;
  const FastSamplers& f = fast_samplers(unit, *image);
  return f.block && sample_block_at_one_level(f.block, *image, tu->sampler, s, t, shader::LodMode::Implicit, nullptr,
                                              live, out);
}

bool UnitTextureAccess::sample_2d_blocks(int unit, int count, const float* const* s, const float* const* t,
                                         shader::LaneMask live, float* const (*out)[4]) const {
  if (const FastSamplers* known = level_zero_route(unit)) {
    if (known->lookups) known->lookups(*known->level_zero_image, count, s, t, out);
    else
      for (int k = 0; k < count; ++k) known->block(*known->level_zero_image, BlockLevels{}, s[k], t[k], out[k]);
    return count > 0;
  }
  return TextureAccess::sample_2d_blocks(unit, count, s, t, live, out);
}

// sample_block_at_one_level's route for one level, without its checks (the quads without a live
// lane read the level as the others), where the unit's samplers are chosen and have it.
const FastSamplers* UnitTextureAccess::level_zero_route(int unit) const {
  if (unit < 0 || unit >= kMaxTextureImageUnits) return nullptr;
  const FastSamplers* known = chosen_samplers_ ? &(*chosen_samplers_)[static_cast<size_t>(unit)]
                              : (chosen_ & (1u << unit)) ? &fast_[static_cast<size_t>(unit)] : nullptr;
  return known && known->level_zero_image ? known : nullptr;
}

const FastSamplers& UnitTextureAccess::fast_samplers(int unit, const TextureImage& image) const {
  if (chosen_samplers_) return (*chosen_samplers_)[static_cast<size_t>(unit)];
  FastSamplers& f = fast_[static_cast<size_t>(unit)];
  if (!(chosen_ & (1u << unit))) {
    static const SimdPath path = simd_path_from_environment();  // as the shader executor chooses its copy
    f = choose_fast_samplers(image, units_[static_cast<size_t>(unit)].sampler, path);
    chosen_ |= 1u << unit;
  }
  return f;
}

FastSamplers choose_fast_samplers(const TextureImage& image, const Sampler& sampler, SimdPath path) {
  FastSamplers f{};
  f.quad = select_bilinear8_sampler(image, sampler);
  // (The block samplers scale coordinates by the size: none for a rectangle.)
  const bool planar = image.kind == TexKind::Planar;
  f.block = f.quad && planar ? select_bilinear8_block_sampler(sampler, path) : nullptr;
  f.lookups = f.block ? select_bilinear8_block_lookups_sampler(sampler, path) : nullptr;
  if (!f.quad) {
    f.quad = select_nearest8_sampler(image, sampler);
    f.block = f.quad ? select_nearest8_block_sampler(sampler, path) : nullptr;
    f.lookups = f.block ? select_nearest8_block_lookups_sampler(sampler, path) : nullptr;
  }
  // Depth images: a block form only (the quad loop of `sample` takes the other lookups).
  if (!f.quad) f.block = select_depth_block_sampler(image, sampler, path);
  f.level_zero_image = f.block && reads_level_zero(sampler) && kind_matches(image, SamplerKind::Tex2D) ? &image : nullptr;
  return f;
}

void UnitTextureAccess::sample(int unit, SamplerKind kind, const float (*coords)[kLanes], shader::LodMode mode,
                               const float* lod, shader::LaneMask live, float (*out)[kLanes]) const {
  const TextureUnit* tu = unit >= 0 && unit < kMaxTextureImageUnits ? &units_[unit] : nullptr;
  const TextureImage* image = tu && tu->image ? tu->image.get() : nullptr;
  if (image && !kind_matches(*image, kind)) image = nullptr;
  const bool one_d = kind == SamplerKind::Tex1D || kind == SamplerKind::Shadow1D;
  const bool shadow = kind == SamplerKind::Shadow1D || kind == SamplerKind::Shadow2D || kind == SamplerKind::ShadowRect;
  // 2D lookups of RGBA8 images with linear filters take the fixed-function unit's fast sampler
  // (8-bit weights, as llvmpipe): one LOD per quad, as the general sampler; nearest ones the
  // general sampler's texels without its level-of-detail work (sampler_nearest8.h).
  // An explicit level of detail (texture2DLod, and every lookup of a vertex shader) chooses
  // nothing when the texture is not mipmapped: the fast samplers take both filters alike.
  const bool mipmapped = tu && !reads_level_zero(tu->sampler);
  QuadSampler fast = nullptr;
  if (image && (kind == SamplerKind::Tex2D || kind == SamplerKind::Rect) && (mode != shader::LodMode::Explicit || !mipmapped)) {
    const FastSamplers& f = fast_samplers(unit, *image);
    float* const channels[4] = {out[0], out[1], out[2], out[3]};
    if (f.block && sample_block_at_one_level(f.block, *image, tu->sampler, coords[0], coords[1], mode, lod, live, channels)) {
      return;
    }
    fast = f.quad;
  }
  for (int q = 0; q < kLanes / 4; ++q) {
    const int first = 4 * q;
    if (!((live >> first) & 0xf) || !image) {
      for (int i = first; i < first + 4; ++i) {
        out[0][i] = out[1][i] = out[2][i] = 0.f;
        out[3][i] = 1.f;
      }
      continue;
    }
    Sampler sampler = tu->sampler;
    if (shadow) sampler.compare = true;
    if (mode == shader::LodMode::Bias && lod && std::isfinite(lod[first])) sampler.lod_bias += lod[first];
    if (fast) {
      F4 lanes[4];
      fast(*image, sampler, load4(&coords[0][first]), load4(&coords[1][first]), lanes);
      apply_base_format(image->base_format, lanes);
      for (int c = 0; c < 4; ++c) store4(&out[c][first], lanes[c]);
      continue;
    }
    float texel[4][4];
    float s[4], t[4], r[4];
    for (int i = 0; i < 4; ++i) {
      s[i] = coords[0][first + i];
      t[i] = one_d ? 0.5f : coords[1][first + i];
      r[i] = shadow ? coords[2][first + i] : (kind == SamplerKind::Tex3D || kind == SamplerKind::Cube ? coords[2][first + i] : 0.f);
    }
    if (mode == shader::LodMode::Explicit) {
      // One level per lane: each lane is sampled alone at its own level of detail.
      for (int i = 0; i < 4; ++i) {
        Sampler one = sampler;
        const float l = lod && std::isfinite(lod[first + i]) ? lod[first + i] : 0.f;
        one.min_lod = one.max_lod = std::clamp(l, sampler.min_lod, sampler.max_lod);
        one.lod_bias = 0.f;
        const float si[4] = {s[i], s[i], s[i], s[i]}, ti[4] = {t[i], t[i], t[i], t[i]}, ri[4] = {r[i], r[i], r[i], r[i]};
        float lane[4][4];
        sample_quad(*image, one, si, ti, ri, lane);
        std::copy(lane[0], lane[0] + 4, texel[i]);
      }
    } else {
      sample_quad(*image, sampler, s, t, r, texel);
    }
    for (int i = 0; i < 4; ++i) {
      if (!image->depth) apply_base_format(image->base_format, texel[i]);
      for (int c = 0; c < 4; ++c) out[c][first + i] = texel[i][c];
    }
  }
}

}  // namespace pineda::raster
