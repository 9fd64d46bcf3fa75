// The block sampler where a lane's two texels along s are not neighbours in memory (the clamped
// right edge, the repeat wrap, levels 1 texel wide) and where they end the texel array: the quad
// sampler's texels exactly, on every path.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <random>
#include <utility>

#include "raster/sampler_bilinear8.h"
#include "raster/sampler_bilinear_block.h"

namespace pineda::raster {
namespace {

// Coordinates along one axis of `size` texels: random ones (mode 0), ones between the first and
// the last texel centre, where no lane wraps (1), and ones at and past the edges (2).
float coordinate(std::mt19937& random, int size, int mode) {
  const float n = static_cast<float>(size);
  if (mode == 0) return static_cast<float>(std::uniform_int_distribution<int>(-1024, 2048)(random)) / 1024.f;
  if (mode == 1) return std::uniform_real_distribution<float>(0.5f / n, (n - 0.5f) / n)(random);
  const float edges[] = {0.f, -0.01f, 0.25f / n, 0.5f / n, (n - 0.5f) / n, (n - 0.25f) / n, 1.f, 1.01f, 1.5f, 3.f};
  return edges[std::uniform_int_distribution<int>(0, 9)(random)];
}

// The block sampler's lanes equal four calls of the quad sampler, bit for bit.
void expect_quad_samplers_texels(const TextureImage& image, const Sampler& sampler, SimdPath path, const float* s,
                                 const float* t) {
  const TextureLevel& level = image.levels[0];
  alignas(64) float block[4][kBlockLanes];
  float* const channels[4] = {block[0], block[1], block[2], block[3]};
  select_bilinear8_block_sampler(sampler, path)(image, BlockLevels{}, s, t, channels);
  for (int q = 0; q < 4; ++q) {
    F4 quad[4];
    select_bilinear8_sampler(image, sampler, path)(image, sampler, load4(s + 4 * q), load4(t + 4 * q), quad);
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(block[c][4 * q + i], quad[c][i])
            << level.width << "x" << level.height << " s " << s[4 * q + i] << " t " << t[4 * q + i] << " channel " << c;
  }
}

// Levels of each size with random texels, sampled with either wrap on every path, 200 blocks
// each, whose coordinates `fill(w, h, trial, s, t)` writes; counts the quads compared.
template <class Fill>
void expect_blocks_of_levels(std::mt19937& random, std::initializer_list<std::pair<int, int>> sizes, int& quads,
                             const Fill& fill) {
  for (auto [w, h] : sizes) {
    TextureImage image;
    std::vector<uint32_t> texels(static_cast<size_t>(w * h));
    for (uint32_t& t : texels) t = static_cast<uint32_t>(random());
    image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
    for (TexWrap wrap : {TexWrap::Repeat, TexWrap::ClampToEdge})
      for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline})
        for (int trial = 0; trial < 200; ++trial) {
          Sampler sampler;
          sampler.min_filter = sampler.mag_filter = TexFilter::Linear;
          sampler.wrap_s = sampler.wrap_t = wrap;
          alignas(64) float s[kBlockLanes], t[kBlockLanes];
          fill(w, h, trial, s, t);
          ASSERT_NO_FATAL_FAILURE(expect_quad_samplers_texels(image, sampler, path, s, t));
          quads += 4;
        }
  }
}

TEST(Bilinear8BlockSampler, EdgesGiveTheQuadSamplersTexelsOnEveryPath) {
  std::mt19937 random(12);
  int quads = 0;
  for (int w : {1, 2, 3, 5, 16})
    for (int h : {1, 2, 3}) {
      // One level: its texel array ends with the bottom right texel, which clamped lanes read.
      TextureImage image;
      std::vector<uint32_t> texels(static_cast<size_t>(w * h));
      for (uint32_t& t : texels) t = static_cast<uint32_t>(random());
      image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
      for (TexWrap ws : {TexWrap::Repeat, TexWrap::ClampToEdge})
        for (TexWrap wt : {TexWrap::Repeat, TexWrap::ClampToEdge})
          for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline})
            for (int trial = 0; trial < 60; ++trial) {
              Sampler sampler;
              sampler.min_filter = sampler.mag_filter = TexFilter::Linear;
              sampler.wrap_s = ws;
              sampler.wrap_t = wt;
              alignas(64) float s[kBlockLanes], t[kBlockLanes];
              for (int i = 0; i < kBlockLanes; ++i) {
                s[i] = coordinate(random, w, trial % 3);
                t[i] = coordinate(random, h, (trial / 3) % 3);
              }
              ASSERT_NO_FATAL_FAILURE(expect_quad_samplers_texels(image, sampler, path, s, t));
              quads += 4;
            }
    }
  EXPECT_EQ(quads, 5 * 3 * 2 * 2 * 3 * 60 * 4);
}

// Blocks whose texels lie within 8 columns by 4 or 8 rows (magnified or slightly minified: the
// AVX-512 copy reads them as rows and permutes them to the lanes) anywhere in levels of several
// shapes, against the edges and the end of the texel array too, and some a little too wide or too
// tall for that window: the quad sampler's texels exactly, on every path.
TEST(Bilinear8BlockSampler, CompactBlocksGiveTheQuadSamplersTexelsOnEveryPath) {
  std::mt19937 random(31);
  int quads = 0;
  ASSERT_NO_FATAL_FAILURE(expect_blocks_of_levels(random, {{37, 29}, {8, 8}, {9, 5}, {300, 3}, {7, 40}, {64, 64}}, quads,
                                                  [&](int w, int h, int trial, float* s, float* t) {
    // The block's corner anywhere from a texel before the level to one past it; steps of up
    // to 2.2 texels per pixel (3 steps: up to 6.6 texels across, 7.6 with the second tap).
    const float s0 = std::uniform_real_distribution<float>(-1.f, w + 1.f)(random) / w;
    const float t0 = std::uniform_real_distribution<float>(-1.f, h + 1.f)(random) / h;
    const float ds = std::uniform_real_distribution<float>(-2.2f, 2.2f)(random) / w;
    const float dt = std::uniform_real_distribution<float>(trial % 2 ? -2.2f : -0.9f, trial % 2 ? 2.2f : 0.9f)(random) / h;
    for (int i = 0; i < kBlockLanes; ++i) {
      const int x = (i & 1) | ((i >> 1) & 2), y = ((i >> 1) & 1) | ((i >> 2) & 2);  // quads of 2x2
      s[i] = s0 + ds * x;
      t[i] = t0 + dt * y;
    }
  }));
  EXPECT_EQ(quads, 6 * 2 * 3 * 200 * 4);
}

// Blocks as the rasterizer fills them, four quads side by side (8 pixels by 2), at up to 1.9
// texels a pixel along each axis: the AVX-512 copy's 8x8 window and its gathers.
TEST(Bilinear8BlockSampler, RowsOfFourQuadsGiveTheQuadSamplersTexelsOnEveryPath) {
  std::mt19937 random(47);
  int quads = 0;
  ASSERT_NO_FATAL_FAILURE(expect_blocks_of_levels(random, {{37, 29}, {16, 4}, {17, 2}, {9, 5}, {300, 3}, {15, 40}, {64, 64}},
                                                  quads, [&](int w, int h, int, float* s, float* t) {
    const float s0 = std::uniform_real_distribution<float>(-1.f, w + 1.f)(random) / w;
    const float t0 = std::uniform_real_distribution<float>(-1.f, h + 1.f)(random) / h;
    const float ds = std::uniform_real_distribution<float>(-1.9f, 1.9f)(random) / w;
    const float dt = std::uniform_real_distribution<float>(-1.9f, 1.9f)(random) / h;
    for (int i = 0; i < kBlockLanes; ++i) {
      const int x = (i & 1) + 2 * (i >> 2), y = (i >> 1) & 1;
      s[i] = s0 + ds * x;
      t[i] = t0 + dt * y;
    }
  }));
  EXPECT_EQ(quads, 7 * 2 * 3 * 200 * 4);
}

// Coordinates the sampler must make sane or that sit on its roundings' edges (NaN, infinities,
// values past +-1e6, zeros of either sign, subnormals, the float just below 1), mixed with
// ordinary ones in blocks whose other lanes lie close together, so that the AVX-512 copy's window
// and its gathers both see them: the quad sampler's texels exactly, on every path.
TEST(Bilinear8BlockSampler, UnusualCoordinatesGiveTheQuadSamplersTexelsOnEveryPath) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const float unusual[] = {std::numeric_limits<float>::quiet_NaN(), kInf, -kInf, 1e6f, -1e6f, 1.5e6f, -3e7f, 3e38f,
                           -0.f, 0.f, 1e-40f, -1e-40f, std::nextafter(1.f, 0.f), std::nextafter(0.f, 1.f), -1.f, 1.f, 2.f};
  constexpr int kUnusual = sizeof unusual / sizeof unusual[0];
  std::mt19937 random(53);
  int blocks = 0;
  for (auto [w, h] : {std::pair{1, 1}, {3, 2}, {8, 8}, {37, 29}, {512, 256}}) {
    TextureImage image;
    std::vector<uint32_t> texels(static_cast<size_t>(w * h));
    for (uint32_t& t : texels) t = static_cast<uint32_t>(random());
    image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
    for (TexWrap ws : {TexWrap::Repeat, TexWrap::ClampToEdge})
      for (TexWrap wt : {TexWrap::Repeat, TexWrap::ClampToEdge})
        for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline})
          for (int trial = 0; trial < 40; ++trial) {
            Sampler sampler;
            sampler.min_filter = sampler.mag_filter = TexFilter::Linear;
            sampler.wrap_s = ws;
            sampler.wrap_t = wt;
            const float s0 = std::uniform_real_distribution<float>(-0.1f, 1.1f)(random);
            const float t0 = std::uniform_real_distribution<float>(-0.1f, 1.1f)(random);
            alignas(64) float s[kBlockLanes], t[kBlockLanes];
            for (int i = 0; i < kBlockLanes; ++i) {
              s[i] = s0 + static_cast<float>(i & 3) * 0.5f / w;
              t[i] = t0 + static_cast<float>(i >> 2) * 0.5f / h;
            }
            // One to four unusual lanes, or (trial 0) all of them.
            const int count = trial == 0 ? kBlockLanes : 1 + trial % 4;
            for (int k = 0; k < count; ++k) {
              const int lane = trial == 0 ? k : std::uniform_int_distribution<int>(0, kBlockLanes - 1)(random);
              (k % 2 ? t : s)[lane] = unusual[std::uniform_int_distribution<int>(0, kUnusual - 1)(random)];
              if (trial % 3 == 0) (k % 2 ? s : t)[lane] = unusual[(trial + k) % kUnusual];
            }
            ASSERT_NO_FATAL_FAILURE(expect_quad_samplers_texels(image, sampler, path, s, t));
            ++blocks;
          }
  }
  EXPECT_EQ(blocks, 5 * 2 * 2 * 3 * 40);
}

}  // namespace
}  // namespace pineda::raster
