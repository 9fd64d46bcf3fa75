// The block sampler for several lookups (select_bilinear8_block_lookups_sampler): filter
// kernels' taps around blocks as the rasterizer fills them, whose texels mostly share one window
// of eight by eight (the AVX-512 copy reads it once) and sometimes do not, give the block
// sampler's values for each lookup exactly, on every path.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "raster/sampler_bilinear_block.h"

namespace pineda::raster {
namespace {

struct Lookups {
  alignas(64) float s[kMaxBlockLookups][kBlockLanes];
  alignas(64) float t[kMaxBlockLookups][kBlockLanes];
};

// Each lookup by the lookups sampler equals the block sampler's, bit for bit. When `own_output`,
// each lookup writes its red and green over its own s and t (which the sampler allows).
void expect_block_samplers_values(const TextureImage& image, const Sampler& sampler, SimdPath path, const Lookups& in,
                                  int count, bool own_output) {
  alignas(64) float expected[kMaxBlockLookups][4][kBlockLanes];
  for (int k = 0; k < count; ++k) {
    float* const channels[4] = {expected[k][0], expected[k][1], expected[k][2], expected[k][3]};
    select_bilinear8_block_sampler(sampler, path)(image, BlockLevels{}, in.s[k], in.t[k], channels);
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
  select_bilinear8_block_lookups_sampler(sampler, path)(image, count, s, t, out);
  for (int k = 0; k < count; ++k)
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < kBlockLanes; ++l)
        ASSERT_EQ(out[k][c][l], expected[k][c][l])
            << image.levels[0].width << "x" << image.levels[0].height << " lookup " << k << " of " << count << " channel "
            << c << " lane " << l << " s " << in.s[k][l] << " t " << in.t[k][l];
}

TEST(Bilinear8BlockLookups, KernelTapsGiveTheBlockSamplersValuesOnEveryPath) {
  std::mt19937 random(71);
  int lookups = 0;
  for (auto [w, h] : {std::pair{8, 8}, {9, 8}, {37, 29}, {64, 64}, {7, 40}, {300, 3}, {512, 512}}) {
    TextureImage image;
    std::vector<uint32_t> texels(static_cast<size_t>(w * h));
    for (uint32_t& texel : texels) texel = static_cast<uint32_t>(random());
    image.levels.push_back({w, h, std::move(texels)});
    for (TexWrap wrap : {TexWrap::Repeat, TexWrap::ClampToEdge})
      for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline})
        for (int trial = 0; trial < 100; ++trial) {
          Sampler sampler;
          sampler.min_filter = sampler.mag_filter = TexFilter::Linear;
          sampler.wrap_s = sampler.wrap_t = wrap;
          // A block of four quads side by side (8 pixels by 2) at up to 1.2 texels a pixel
          // anywhere from a texel before the level to one past it, and taps up to 1.5 texels
          // away (most share a window), or (every fourth trial) up to 6.
          const float s0 = std::uniform_real_distribution<float>(-1.f, w + 1.f)(random) / w;
          const float t0 = std::uniform_real_distribution<float>(-1.f, h + 1.f)(random) / h;
          const float ds = std::uniform_real_distribution<float>(-1.2f, 1.2f)(random) / w;
          const float dt = std::uniform_real_distribution<float>(-1.2f, 1.2f)(random) / h;
          const float reach = trial % 4 == 3 ? 6.f : 1.5f;
          const int count = 1 + trial % kMaxBlockLookups;
          Lookups in;
          for (int k = 0; k < count; ++k) {
            const float os = std::uniform_real_distribution<float>(-reach, reach)(random) / w;
            const float ot = std::uniform_real_distribution<float>(-reach, reach)(random) / h;
            for (int i = 0; i < kBlockLanes; ++i) {
              const int x = (i & 1) + 2 * (i >> 2), y = (i >> 1) & 1;
              in.s[k][i] = s0 + os + ds * x;
              in.t[k][i] = t0 + ot + dt * y;
            }
          }
          ASSERT_NO_FATAL_FAILURE(expect_block_samplers_values(image, sampler, path, in, count, trial % 2 == 1));
          lookups += count;
        }
  }
  // 100 trials take counts 1 to 8 in turn: 12 rounds of 36 and 1 + 2 + 3 + 4.
  EXPECT_EQ(lookups, 7 * 2 * 3 * (12 * 36 + 10));
}

}  // namespace
}  // namespace pineda::raster
