// The shader block's lane helpers (varying_lanes.h, block_depth.h, block_write.h,
// sampler_bilinear_block.h, the block samplers of sampler_nearest8.h and sampler_depth.h) in
// three copies: baseline x86-64 (4-lane vectors), AVX2 (8, gather instructions) and AVX-512
// (16), the same operations per lane in each, so the same values.
#include <immintrin.h>

#include <cstring>

#include "raster/block_depth.h"
#include "raster/block_write.h"
#include "raster/sampler_bilinear_block.h"
#include "raster/sampler_depth.h"
#include "raster/sampler_nearest8.h"
#include "raster/varying_lanes.h"

// The copies pass vectors wider than the baseline's registers but only within one function.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace pineda::raster::block_lanes_sse2 {
using VF = float __attribute__((vector_size(16)));
constexpr int kGatherBytes = 0;
#include "raster/block_lanes_types.inc"
#include "raster/block_write_body.inc"
#include "raster/sampler_bilinear_block_body.inc"
#include "raster/sampler_nearest_block_body.inc"
#include "raster/sampler_depth_block_body.inc"
#include "raster/varying_lanes_body.inc"
#include "raster/block_depth_body.inc"
}  // namespace pineda::raster::block_lanes_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace pineda::raster::block_lanes_avx2 {
using VF = float __attribute__((vector_size(32)));
constexpr int kGatherBytes = kCopiesHaveTheirTargets ? 32 : 0;
#include "raster/block_lanes_types.inc"
#include "raster/block_write_body.inc"
#include "raster/sampler_bilinear_block_body.inc"
#include "raster/sampler_nearest_block_body.inc"
#include "raster/sampler_depth_block_body.inc"
#include "raster/varying_lanes_body.inc"
#include "raster/block_depth_body.inc"
}  // namespace pineda::raster::block_lanes_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512vl,avx512dq")
namespace pineda::raster::block_lanes_avx512 {
using VF = float __attribute__((vector_size(64)));
constexpr int kGatherBytes = kCopiesHaveTheirTargets ? 64 : 0;
#include "raster/block_lanes_types.inc"
#include "raster/block_write_body.inc"
#include "raster/sampler_bilinear_block_body.inc"
#include "raster/sampler_nearest_block_body.inc"
#include "raster/sampler_depth_block_body.inc"
#include "raster/varying_lanes_body.inc"
#include "raster/block_depth_body.inc"
}  // namespace pineda::raster::block_lanes_avx512
#pragma GCC pop_options

namespace pineda::raster {
namespace {

template <TexWrap kWrapS, TexWrap kWrapT>
BlockSampler block_sampler_for_path(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::sample_block<kWrapS, kWrapT>;
  if (uses_avx2(path)) return &block_lanes_avx2::sample_block<kWrapS, kWrapT>;
  return &block_lanes_sse2::sample_block<kWrapS, kWrapT>;
}

template <TexWrap kWrapS>
BlockSampler block_sampler_for_wrap_t(TexWrap t, SimdPath path) {
  return t == TexWrap::Repeat ? block_sampler_for_path<kWrapS, TexWrap::Repeat>(path)
                              : block_sampler_for_path<kWrapS, TexWrap::ClampToEdge>(path);
}

// pick.operator()<kWrapS, kWrapT>() for s and t each REPEAT or CLAMP_TO_EDGE; null for others.
template <class Pick>
auto for_wrap_pair(TexWrap s, TexWrap t, const Pick& pick)
    -> decltype(pick.template operator()<TexWrap::Repeat, TexWrap::Repeat>()) {
  constexpr TexWrap kRepeat = TexWrap::Repeat, kEdge = TexWrap::ClampToEdge;
  if (s == kRepeat && t == kRepeat) return pick.template operator()<kRepeat, kRepeat>();
  if (s == kRepeat && t == kEdge) return pick.template operator()<kRepeat, kEdge>();
  if (s == kEdge && t == kRepeat) return pick.template operator()<kEdge, kRepeat>();
  if (s == kEdge && t == kEdge) return pick.template operator()<kEdge, kEdge>();
  return nullptr;
}

// for_wrap_pair for the nearest samplers: CLAMP picks the texels CLAMP_TO_EDGE does
// (nearest_index); MIRRORED_REPEAT keeps the quad sampler.
template <class Pick>
auto for_nearest_wrap_pair(const Sampler& sampler, const Pick& pick) {
  const auto edge = [](TexWrap w) { return w == TexWrap::Clamp ? TexWrap::ClampToEdge : w; };
  return for_wrap_pair(edge(sampler.wrap_s), edge(sampler.wrap_t), pick);
}

}  // namespace

BlockSampler select_bilinear8_block_sampler(const Sampler& sampler, SimdPath path) {
  return sampler.wrap_s == TexWrap::Repeat ? block_sampler_for_wrap_t<TexWrap::Repeat>(sampler.wrap_t, path)
                                           : block_sampler_for_wrap_t<TexWrap::ClampToEdge>(sampler.wrap_t, path);
}

BlockLookupsSampler select_bilinear8_block_lookups_sampler(const Sampler& sampler, SimdPath path) {
  const auto for_path = [path]<TexWrap kWrapS, TexWrap kWrapT>() -> BlockLookupsSampler {
    if (uses_avx512(path)) return &block_lanes_avx512::sample_block_lookups<kWrapS, kWrapT>;
    if (uses_avx2(path)) return &block_lanes_avx2::sample_block_lookups<kWrapS, kWrapT>;
    return &block_lanes_sse2::sample_block_lookups<kWrapS, kWrapT>;
  };
  return for_wrap_pair(sampler.wrap_s, sampler.wrap_t, for_path);
}

BlockSampler select_nearest8_block_sampler(const Sampler& sampler, SimdPath path) {
  const auto for_path = [path]<TexWrap kWrapS, TexWrap kWrapT>() -> BlockSampler {
    if (uses_avx512(path)) return &block_lanes_avx512::sample_nearest_block<kWrapS, kWrapT>;
    if (uses_avx2(path)) return &block_lanes_avx2::sample_nearest_block<kWrapS, kWrapT>;
    return &block_lanes_sse2::sample_nearest_block<kWrapS, kWrapT>;
  };
  return for_nearest_wrap_pair(sampler, for_path);
}

BlockLookupsSampler select_nearest8_block_lookups_sampler(const Sampler& sampler, SimdPath path) {
  const auto for_path = [path]<TexWrap kWrapS, TexWrap kWrapT>() -> BlockLookupsSampler {
    if (uses_avx512(path)) return &block_lanes_avx512::sample_nearest_block_lookups<kWrapS, kWrapT>;
    if (uses_avx2(path)) return &block_lanes_avx2::sample_nearest_block_lookups<kWrapS, kWrapT>;
    return &block_lanes_sse2::sample_nearest_block_lookups<kWrapS, kWrapT>;
  };
  return for_nearest_wrap_pair(sampler, for_path);
}

BlockSampler select_depth_block_sampler(const TextureImage& image, const Sampler& sampler, SimdPath path) {
  if (!image.depth || image.kind != TexKind::Planar || image.depth_swizzle != kIdentitySwizzle || image.levels.empty())
    return nullptr;
  const TextureLevel& level = image.levels[0];
  if (level.width <= 0 || level.height <= 0 || level.texels.size() < static_cast<size_t>(level.width) * level.height)
    return nullptr;
  const TexFilter filter = sampler.mag_filter;
  if (sampler.compare || sampler.min_filter != filter) return nullptr;
  const auto for_path = [path]<TexWrap kWrapS, TexWrap kWrapT, bool kLinear>() -> BlockSampler {
    if (uses_avx512(path)) return &block_lanes_avx512::sample_depth_block<kWrapS, kWrapT, kLinear>;
    if (uses_avx2(path)) return &block_lanes_avx2::sample_depth_block<kWrapS, kWrapT, kLinear>;
    return &block_lanes_sse2::sample_depth_block<kWrapS, kWrapT, kLinear>;
  };
  const auto for_filter = [&]<TexWrap kWrapS, TexWrap kWrapT>() -> BlockSampler {
    return filter == TexFilter::Linear ? for_path.template operator()<kWrapS, kWrapT, true>()
                                       : for_path.template operator()<kWrapS, kWrapT, false>();
  };
  // A nearest filter reads CLAMP as CLAMP_TO_EDGE (nearest_index); a linear one reads the border there.
  const bool nearest = filter == TexFilter::Nearest;
  if (!nearest && filter != TexFilter::Linear) return nullptr;
  const auto edge = [nearest](TexWrap w) { return nearest && w == TexWrap::Clamp ? TexWrap::ClampToEdge : w; };
  const TexWrap s = edge(sampler.wrap_s), t = edge(sampler.wrap_t);
  return for_wrap_pair(s, t, for_filter);
}

VaryingInterpolator select_varying_interpolator(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::interpolate;
  return uses_avx2(path) ? &block_lanes_avx2::interpolate : &block_lanes_sse2::interpolate;
}

QuadVaryingInterpolator select_quad_varying_interpolator(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::interpolate_quads;
  return uses_avx2(path) ? &block_lanes_avx2::interpolate_quads : &block_lanes_sse2::interpolate_quads;
}

BlockDepthTest select_block_depth_test(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::depth_test_block;
  return uses_avx2(path) ? &block_lanes_avx2::depth_test_block : &block_lanes_sse2::depth_test_block;
}

QuadsDepthTest select_quads_depth_test(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::depth_test_quads;
  return uses_avx2(path) ? &block_lanes_avx2::depth_test_quads : &block_lanes_sse2::depth_test_quads;
}

BlockWriter select_block_writer(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::write_block;
  return uses_avx2(path) ? &block_lanes_avx2::write_block : &block_lanes_sse2::write_block;
}

QuadsWriter select_quads_writer(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::write_quads;
  return uses_avx2(path) ? &block_lanes_avx2::write_quads : &block_lanes_sse2::write_quads;
}

}  // namespace pineda::raster
