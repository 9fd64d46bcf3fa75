// The RGBA8 lane sampler: which samplers it takes, 8-bit weights, exact texels at their
// centres, and the mipmap blend.
#include <gtest/gtest.h>

#include <memory>
#include <limits>
#include <random>

#include "raster/sampler_bilinear8.h"
#include "raster/sampler_bilinear_block.h"

namespace pineda::raster {
namespace {

TextureImage one_level(int w, int h, std::vector<uint32_t> texels) {
  TextureImage image;
  image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
  return image;
}

Sampler linear(TexWrap wrap, TexFilter min = TexFilter::Linear) {
  Sampler s;
  s.min_filter = min;
  s.mag_filter = TexFilter::Linear;
  s.wrap_s = s.wrap_t = wrap;
  return s;
}

TEST(Bilinear8Sampler, TakesOnlyLinearPlanarColourImagesWithRepeatOrClampToEdge) {
  const TextureImage image = one_level(1, 1, {0});
  EXPECT_NE(select_bilinear8_sampler(image, linear(TexWrap::Repeat)), nullptr);
  EXPECT_NE(select_bilinear8_sampler(image, linear(TexWrap::ClampToEdge, TexFilter::LinearMipmapLinear)), nullptr);
  EXPECT_NE(select_bilinear8_sampler(image, linear(TexWrap::Repeat, TexFilter::LinearMipmapNearest)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::MirroredRepeat)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::ClampToBorder)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::Clamp)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::Repeat, TexFilter::NearestMipmapLinear)), nullptr);
  Sampler nearest_mag = linear(TexWrap::Repeat);
  nearest_mag.mag_filter = TexFilter::Nearest;
  EXPECT_EQ(select_bilinear8_sampler(image, nearest_mag), nullptr);
  TextureImage depth = image;
  depth.depth = true;
  EXPECT_EQ(select_bilinear8_sampler(depth, linear(TexWrap::Repeat)), nullptr);
  TextureImage cube = image;
  cube.kind = TexKind::Cube;
  EXPECT_EQ(select_bilinear8_sampler(cube, linear(TexWrap::Repeat)), nullptr);
}

TEST(Bilinear8Sampler, TexelCentresGiveTheTexelExactly) {
  const TextureImage image = one_level(2, 2, {0x04030201u, 0x80ff7f00u, 0x10203040u, 0xfffefdfcu});
  const Sampler sampler = linear(TexWrap::Repeat);
  F4 out[4];
  // Pixels at the four texel centres; the quad spans one texel per pixel (lambda 0).
  select_bilinear8_sampler(image, sampler)(image, sampler, F4{0.25f, 0.75f, 0.25f, 0.75f},
                                           F4{0.25f, 0.25f, 0.75f, 0.75f}, out);
  const uint32_t texels[4] = {0x04030201u, 0x80ff7f00u, 0x10203040u, 0xfffefdfcu};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(out[c][i], static_cast<float>((texels[i] >> (8 * c)) & 0xff) * (1.f / 255.f)) << i << " " << c;
}

TEST(Bilinear8Sampler, WeightsRoundToTheNearestOne256th) {
  // Texels 0 and 255 along s; u = 2s - 0.5 = 0.3 weighs the second by round(0.3 * 256) / 256
  // (76.8: 77), as llvmpipe; u = 0.2 by round(51.2) / 256 = 51 / 256.
  const TextureImage image = one_level(2, 1, {0u, 0xffffffffu});
  const Sampler sampler = linear(TexWrap::ClampToEdge);
  F4 out[4];
  select_bilinear8_sampler(image, sampler)(image, sampler, F4{0.4f, 0.35f, 0.4f, 0.35f}, F4{0.5f, 0.5f, 0.5f, 0.5f}, out);
  for (int c = 0; c < 4; ++c) {
    EXPECT_FLOAT_EQ(out[c][0], 77.f / 256.f);
    EXPECT_FLOAT_EQ(out[c][1], 51.f / 256.f);
  }
}

TEST(Bilinear8Sampler, MipmapBlendUsesLambdaInOne256th) {
  TextureImage image = one_level(2, 2, {0u, 0u, 0u, 0u});
  image.levels.push_back({1, 1, {0xffffffffu}});
  const Sampler sampler = linear(TexWrap::Repeat, TexFilter::LinearMipmapLinear);
  F4 out[4];
  // One texel per half pixel along x and y: rho^2 = 2, lambda = 0.5.
  select_bilinear8_sampler(image, sampler)(image, sampler, F4{0.f, 0.5f, 0.f, 0.5f}, F4{0.f, 0.5f, 0.f, 0.5f}, out);
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(out[c][i], 0.5f) << i << " " << c;
}

}  // namespace

// Bit q set when quad q of the block sampler's lanes holds what the quad sampler gives it.
unsigned quads_matching(const TextureImage& image, const Sampler& sampler, SimdPath path, const BlockLevels& levels,
                        const float* s, const float* t) {
  alignas(64) float block[4][kBlockLanes];
  float* const channels[4] = {block[0], block[1], block[2], block[3]};
  select_bilinear8_block_sampler(sampler, path)(image, levels, s, t, channels);
  unsigned matching = 0;
  for (int q = 0; q < 4; ++q) {
    F4 quad[4];
    select_bilinear8_sampler(image, sampler, path)(image, sampler, load4(s + 4 * q), load4(t + 4 * q), quad);
    bool same = true;
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 4; ++c) same &= block[c][4 * q + i] == quad[c][i];
    matching |= same ? 1u << q : 0u;
  }
  return matching;
}

TEST(Bilinear8BlockSampler, SixteenLanesGiveTheQuadSamplersTexelsOnEveryPath) {
  // A 16x8 image with three more levels; coordinates from a few texels to many per pixel, and
  // ones the sampler must make sane (NaN, huge).
  TextureImage image;
  std::mt19937 random(7);
  for (int w = 16, h = 8; w >= 2; w /= 2, h /= 2) {
    std::vector<uint32_t> texels(static_cast<size_t>(w * h));
    for (uint32_t& t : texels) t = static_cast<uint32_t>(random());
    image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
  }
  image.levels.push_back({1, 1, {0x80402010u}});
  // Steps and corners in 1/256ths: s0 + ds - s0 is exactly ds in every quad.
  std::uniform_int_distribution<int> coord(-768, 768), step(0, 100);
  int blocks = 0, quads_compared = 0;
  for (TexWrap ws : {TexWrap::Repeat, TexWrap::ClampToEdge})
    for (TexWrap wt : {TexWrap::Repeat, TexWrap::ClampToEdge})
      for (TexFilter min : {TexFilter::Linear, TexFilter::LinearMipmapNearest, TexFilter::LinearMipmapLinear})
        for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline})
          for (int trial = 0; trial < 200; ++trial) {
            Sampler sampler = linear(ws, min);
            sampler.wrap_t = wt;
            // Every quad spans the same steps, so that every quad reads the same levels.
            const float ds = static_cast<float>(step(random)) / 256.f, dt = static_cast<float>(step(random)) / 256.f;
            alignas(64) float s[kBlockLanes], t[kBlockLanes];
            for (int q = 0; q < 4; ++q) {
              const float s0 = static_cast<float>(coord(random)) / 256.f, t0 = static_cast<float>(coord(random)) / 256.f;
              for (int i = 0; i < 4; ++i) {
                s[4 * q + i] = s0 + ((i & 1) ? ds : 0.f);
                t[4 * q + i] = t0 + ((i & 2) ? dt : 0.f);
              }
            }
            if (trial == 0) s[5] = std::numeric_limits<float>::quiet_NaN(), t[9] = 1e30f;
            const LevelChoice choice = bilinear8_quad_levels(image, sampler, load4(s), load4(t));
            BlockLevels levels{choice.first, choice.two, {}};
            for (int q = 0; q < 4; ++q) levels.blend[q] = bilinear8_quad_levels(image, sampler, load4(s + 4 * q), load4(t + 4 * q)).blend;
            const unsigned matching = quads_matching(image, sampler, path, levels, s, t);
            for (int q = 0; q < 4; ++q) {
              const LevelChoice own = bilinear8_quad_levels(image, sampler, load4(s + 4 * q), load4(t + 4 * q));
              if (own.first != choice.first || own.two != choice.two) continue;  // each quad's own weight
              ASSERT_TRUE((matching >> q) & 1u) << "quad " << q;
              ++quads_compared;
            }
            ++blocks;
          }
  EXPECT_EQ(blocks, 2 * 2 * 3 * 3 * 200);
  // Only a quad with a NaN or huge coordinate (trial 0) may read other levels than quad 0.
  EXPECT_GE(quads_compared, 4 * blocks - 2 * 2 * 3 * 3 * 2);
}

// Quads between the same two levels at different levels of detail: each keeps its own weight
// between them, as the quad sampler gives it.
TEST(Bilinear8BlockSampler, QuadsBetweenTheSameLevelsKeepTheirOwnWeights) {
  TextureImage image;
  std::mt19937 random(5);
  for (int w = 16; w >= 1; w /= 2) {
    std::vector<uint32_t> texels(static_cast<size_t>(w * w));
    for (uint32_t& t : texels) t = static_cast<uint32_t>(random());
    image.levels.push_back({w, w, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
  }
  std::uniform_real_distribution<float> corner(-1.f, 2.f), texels_per_pixel(2.1f, 3.9f);  // lambda in (1, 2)
  int blocks = 0, weights_differ = 0;
  for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline})
    for (int trial = 0; trial < 100; ++trial) {
      const Sampler sampler = linear(trial % 2 ? TexWrap::Repeat : TexWrap::ClampToEdge, TexFilter::LinearMipmapLinear);
      alignas(64) float s[kBlockLanes], t[kBlockLanes];
      BlockLevels levels;
      for (int q = 0; q < 4; ++q) {
        const float s0 = corner(random), t0 = corner(random), ds = texels_per_pixel(random) / 16.f;
        for (int i = 0; i < 4; ++i) {
          s[4 * q + i] = s0 + ((i & 1) ? ds : 0.f);
          t[4 * q + i] = t0 + ((i & 2) ? ds / 4.f : 0.f);
        }
        const LevelChoice own = bilinear8_quad_levels(image, sampler, load4(s + 4 * q), load4(t + 4 * q));
        ASSERT_TRUE(own.two);
        ASSERT_EQ(own.first, 1);
        levels.first = own.first;
        levels.two = own.two;
        levels.blend[q] = own.blend;
      }
      weights_differ += levels.blend[0] != levels.blend[1];
      ASSERT_EQ(quads_matching(image, sampler, path, levels, s, t), 0xFu) << "path " << int(path);
      ++blocks;
    }
  EXPECT_EQ(blocks, 3 * 100);
  EXPECT_GT(weights_differ, 250);
}

}  // namespace pineda::raster
