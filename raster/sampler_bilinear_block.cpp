#include "raster/sampler_bilinear_block.h"

#include <immintrin.h>

#include <cstring>

#include "raster/sampler_bilinear8.h"

// The helpers pass vectors wider than the baseline's registers but are always inlined.
#pragma GCC diagnostic ignored "-Wpsabi"

// Three copies: baseline (4 lanes at a time), AVX2 (8, gather instructions), AVX-512 (16); the
// lanes' arithmetic is integers and lane-wise float operations, so every copy gives the same texels.

namespace pineda::raster::block_sse2 {
namespace {
using VF = float __attribute__((vector_size(16)));
using VI = int32_t __attribute__((vector_size(16)));
constexpr int kGatherBytes = 0;
#include "raster/sampler_bilinear_block_body.inc"
}  // namespace
}  // namespace pineda::raster::block_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace pineda::raster::block_avx2 {
namespace {
using VF = float __attribute__((vector_size(32)));
using VI = int32_t __attribute__((vector_size(32)));
constexpr int kGatherBytes = kCopiesHaveTheirTargets ? 32 : 0;
#include "raster/sampler_bilinear_block_body.inc"
}  // namespace
}  // namespace pineda::raster::block_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512vl,avx512dq")
namespace pineda::raster::block_avx512 {
namespace {
using VF = float __attribute__((vector_size(64)));
using VI = int32_t __attribute__((vector_size(64)));
constexpr int kGatherBytes = kCopiesHaveTheirTargets ? 64 : 0;
#include "raster/sampler_bilinear_block_body.inc"
}  // namespace
}  // namespace pineda::raster::block_avx512
#pragma GCC pop_options

namespace pineda::raster {
namespace {

template <TexWrap kWrapS, TexWrap kWrapT>
BlockSampler for_path(SimdPath path) {
  if (uses_avx512(path)) return &block_avx512::sample_block<kWrapS, kWrapT>;
  if (uses_avx2(path)) return &block_avx2::sample_block<kWrapS, kWrapT>;
  return &block_sse2::sample_block<kWrapS, kWrapT>;
}

template <TexWrap kWrapS>
BlockSampler for_wrap_t(TexWrap t, SimdPath path) {
  return t == TexWrap::Repeat ? for_path<kWrapS, TexWrap::Repeat>(path) : for_path<kWrapS, TexWrap::ClampToEdge>(path);
}

}  // namespace

BlockSampler select_bilinear8_block_sampler(const Sampler& sampler, SimdPath path) {
  return sampler.wrap_s == TexWrap::Repeat ? for_wrap_t<TexWrap::Repeat>(sampler.wrap_t, path)
                                           : for_wrap_t<TexWrap::ClampToEdge>(sampler.wrap_t, path);
}

}  // namespace pineda::raster
