// The block samplers for several lookups (select_bilinear8_block_lookups_sampler,
// select_nearest8_block_lookups_sampler): filter kernels' taps around blocks as the rasterizer
// fills them, whose texels mostly share one window (the AVX-512 copies read it once) and
// sometimes do not, give the block sampler's values for each lookup exactly, on every path.
#include <gtest/gtest.h>

#include <initializer_list>
#include <random>
#include <utility>
#include <vector>

#include "raster/sampler_bilinear_block.h"
#include "raster/sampler_nearest8.h"

namespace pineda::raster {
namespace {

struct Lookups {
  alignas(64) float s[kMaxBlockLookups][kBlockLanes];
  alignas(64) float t[kMaxBlockLookups][kBlockLanes];
};

// Each lookup by the lookups sampler equals the block sampler's, bit for bit. When `own_output`,
// each lookup writes its red and green over its own s and t (which the sampler allows).
void expect_block_samplers_values(const TextureImage& image, BlockSampler block, BlockLookupsSampler lookups,
                                  const Lookups& in, int count, bool own_output) {
  alignas(64) float expected[kMaxBlockLookups][4][kBlockLanes];
  for (int k = 0; k < count; ++k) {
    float* const channels[4] = {expected[k][0], expected[k][1], expected[k][2], expected[k][3]};
    block(image, BlockLevels{}, in.s[k], in.t[k], channels);
  }
  Lookups coords = in;
  alignas(64) float blue_alpha[kMaxBlockLookups][2][kBlockLanes];
  alignas(64) float red_green[kMaxBlockLookups][2][kBlockLanes];
  const float* s[kMaxBlockLookups];
  const float* t[kMaxBlockLookups];
  float* out[kMaxBlockLookups][4];
  for (int k = 0; k < count; ++k) {
    s[k] = coords.s[k];
    t[k] = coords.t[k];
    out[k][0] = own_output ? coords.s[k] : red_green[k][0];
    out[k][1] = own_output ? coords.t[k] : red_green[k][1];
    out[k][2] = blue_alpha[k][0];
    out[k][3] = blue_alpha[k][1];
  }
  lookups(image, count, s, t, out);
  for (int k = 0; k < count; ++k)
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < kBlockLanes; ++l)
        ASSERT_EQ(out[k][c][l], expected[k][c][l])
            << image.levels[0].width << "x" << image.levels[0].height << " lookup " << k << " of " << count << " channel "
            << c << " lane " << l << " s " << in.s[k][l] << " t " << in.t[k][l];
}

// Kernels of 1 to kMaxBlockLookups taps (counts in turn over the trials) around a block of four quads side by
// side (8 pixels by 2) at up to `scale` texels a pixel anywhere from a texel before each level
// to one past it, the taps up to `reach` texels away or, every fourth trial, `far`; each lookup
// compared by `compare(image, sampler, in, count, own_output)`. Returns the lookups compared.
template <class Compare>
int expect_kernels(std::initializer_list<std::pair<int, int>> sizes, std::initializer_list<TexWrap> wraps, TexFilter filter,
                   float scale, float reach, float far, const Compare& compare) {
  std::mt19937 random(71);
  int lookups = 0;
  for (auto [w, h] : sizes) {
    TextureImage image;
    std::vector<uint32_t> texels(static_cast<size_t>(w * h));
    for (uint32_t& texel : texels) texel = static_cast<uint32_t>(random());
    image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
    for (TexWrap wrap : wraps)
      for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline})
        for (int trial = 0; trial < 100; ++trial) {
          Sampler sampler;
          sampler.min_filter = sampler.mag_filter = filter;
          sampler.wrap_s = sampler.wrap_t = wrap;
          const float s0 = std::uniform_real_distribution<float>(-1.f, w + 1.f)(random) / w;
          const float t0 = std::uniform_real_distribution<float>(-1.f, h + 1.f)(random) / h;
          const float ds = std::uniform_real_distribution<float>(-scale, scale)(random) / w;
          const float dt = std::uniform_real_distribution<float>(-scale, scale)(random) / h;
          const float taps_reach = trial % 4 == 3 ? far : reach;
          const int count = 1 + trial % kMaxBlockLookups;
          Lookups in;
          for (int k = 0; k < count; ++k) {
            const float os = std::uniform_real_distribution<float>(-taps_reach, taps_reach)(random) / w;
            const float ot = std::uniform_real_distribution<float>(-taps_reach, taps_reach)(random) / h;
            for (int i = 0; i < kBlockLanes; ++i) {
              const int x = (i & 1) + 2 * (i >> 2), y = (i >> 1) & 1;
              in.s[k][i] = s0 + os + ds * x;
              in.t[k][i] = t0 + ot + dt * y;
            }
          }
          compare(image, sampler, path, in, count, trial % 2 == 1);
          if (::testing::Test::HasFatalFailure()) return lookups;
          lookups += count;
        }
  }
  return lookups;
}

// 100 trials take counts 1 to kMaxBlockLookups in turn.
constexpr int kLookupsPer100Trials = [] {
  int lookups = 0;
  for (int trial = 0; trial < 100; ++trial) lookups += 1 + trial % kMaxBlockLookups;
  return lookups;
}();

// Bilinear taps most of which share an 8x8 window.
TEST(BlockLookups, BilinearKernelTapsGiveTheBlockSamplersValuesOnEveryPath) {
  const int lookups = expect_kernels({{8, 8}, {9, 8}, {37, 29}, {64, 64}, {7, 40}, {300, 3}, {512, 512}},
                                     {TexWrap::Repeat, TexWrap::ClampToEdge}, TexFilter::Linear, 1.2f, 1.5f, 6.f,
                                     [](const TextureImage& image, const Sampler& sampler, SimdPath path, const Lookups& in,
                                        int count, bool own_output) {
    ASSERT_NO_FATAL_FAILURE(expect_block_samplers_values(image, select_bilinear8_block_sampler(sampler, path),
                                                         select_bilinear8_block_lookups_sampler(sampler, path), in, count,
                                                         own_output));
  });
  EXPECT_EQ(lookups, 7 * 2 * 3 * kLookupsPer100Trials);
}

// Nearest taps about a texel a pixel, most of which share a window of 16 columns by 8 rows; CLAMP
// reads as CLAMP_TO_EDGE.
TEST(BlockLookups, NearestKernelTapsGiveTheBlockSamplersValuesOnEveryPath) {
  const int lookups = expect_kernels({{16, 8}, {17, 9}, {37, 29}, {64, 64}, {15, 40}, {300, 7}, {800, 600}},
                                     {TexWrap::Repeat, TexWrap::ClampToEdge, TexWrap::Clamp}, TexFilter::Nearest, 1.1f,
                                     3.f, 8.f,
                                     [](const TextureImage& image, const Sampler& sampler, SimdPath path, const Lookups& in,
                                        int count, bool own_output) {
    ASSERT_NO_FATAL_FAILURE(expect_block_samplers_values(image, select_nearest8_block_sampler(sampler, path),
                                                         select_nearest8_block_lookups_sampler(sampler, path), in, count,
                                                         own_output));
  });
  EXPECT_EQ(lookups, 7 * 3 * 3 * kLookupsPer100Trials);
}

}  // namespace
}  // namespace pineda::raster
