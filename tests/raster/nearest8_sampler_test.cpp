// The RGBA8 nearest quad sampler: which samplers it takes, and the general sampler's texels
// (sample_quad) for any coordinates, wrap modes and level sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "raster/quad_vector.h"
#include "raster/sampler.h"
#include "raster/sampler_nearest8.h"

namespace pineda::raster {
namespace {

TextureImage random_level(int w, int h, std::mt19937& rng) {
  TextureImage image;
  std::vector<uint32_t> texels(static_cast<size_t>(w) * h);
  for (uint32_t& t : texels) t = rng();
  image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
  return image;
}

Sampler nearest(TexWrap s, TexWrap t) {
  Sampler out;
  out.min_filter = out.mag_filter = TexFilter::Nearest;
  out.wrap_s = s;
  out.wrap_t = t;
  return out;
}

TEST(Nearest8Sampler, TakesOnlyNearestPlanarColourImagesWithoutTheBorder) {
  std::mt19937 rng(1);
  const TextureImage image = random_level(3, 2, rng);
  for (TexWrap w : {TexWrap::Repeat, TexWrap::Clamp, TexWrap::ClampToEdge, TexWrap::MirroredRepeat})
    EXPECT_NE(select_nearest8_sampler(image, nearest(w, TexWrap::Repeat)), nullptr);
  EXPECT_EQ(select_nearest8_sampler(image, nearest(TexWrap::ClampToBorder, TexWrap::Repeat)), nullptr);
  EXPECT_EQ(select_nearest8_sampler(image, nearest(TexWrap::Repeat, TexWrap::ClampToBorder)), nullptr);
  Sampler mipmapped = nearest(TexWrap::Repeat, TexWrap::Repeat);
  mipmapped.min_filter = TexFilter::NearestMipmapNearest;
  EXPECT_EQ(select_nearest8_sampler(image, mipmapped), nullptr);
  Sampler linear_mag = nearest(TexWrap::Repeat, TexWrap::Repeat);
  linear_mag.mag_filter = TexFilter::Linear;
  EXPECT_EQ(select_nearest8_sampler(image, linear_mag), nullptr);
  TextureImage srgb = image;
  srgb.levels[0].srgb = true;
  EXPECT_EQ(select_nearest8_sampler(srgb, nearest(TexWrap::Repeat, TexWrap::Repeat)), nullptr);
  TextureImage depth = image;
  depth.depth = true;
  EXPECT_EQ(select_nearest8_sampler(depth, nearest(TexWrap::Repeat, TexWrap::Repeat)), nullptr);
}

// Coordinates inside, outside, on texel edges, huge, infinite and NaN, in every wrap pair.
TEST(Nearest8Sampler, GivesTheGeneralSamplersTexels) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> near(-2.5f, 3.5f);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float special[] = {0.f, 1.f, -1.f, 0.5f, 1e7f, -1e7f, inf, -inf, nan, 1.f / 3.f, 2.f / 3.f, -0.f};
  const TexWrap wraps[] = {TexWrap::Repeat, TexWrap::Clamp, TexWrap::ClampToEdge, TexWrap::MirroredRepeat};
  int compared = 0;
  for (const auto& [w, h] : {std::pair{1, 1}, {3, 5}, {16, 16}, {97, 2}, {1, 64}})
    for (TexWrap ws : wraps)
      for (TexWrap wt : wraps) {
        const TextureImage image = random_level(w, h, rng);
        const Sampler sampler = nearest(ws, wt);
        const QuadSampler sample = select_nearest8_sampler(image, sampler);
        ASSERT_NE(sample, nullptr);
        for (int n = 0; n < 200; ++n) {
          float s[4], t[4];
          for (int i = 0; i < 4; ++i) {
            s[i] = n % 4 == 0 ? special[rng() % std::size(special)] : near(rng);
            t[i] = n % 5 == 0 ? special[rng() % std::size(special)] : near(rng);
            if (n % 3 == 0) s[i] = std::floor(s[i] * w) / w;  // on texel edges
          }
          float expected[4][4];
          sample_quad(image, sampler, s, t, expected);
          F4 out[4];
          sample(image, sampler, F4{s[0], s[1], s[2], s[3]}, F4{t[0], t[1], t[2], t[3]}, out);
          for (int i = 0; i < 4; ++i)
            for (int c = 0; c < 4; ++c) {
              ASSERT_EQ(out[c][i], expected[i][c]) << w << "x" << h << " wrap " << int(ws) << "/" << int(wt) << " s " << s[i]
                                                    << " t " << t[i];
              ++compared;
            }
        }
      }
  EXPECT_EQ(compared, 5 * 16 * 200 * 16);
}

// One block of coordinates through the 16-lane sampler on every instruction-set path, each
// lane against the quad sampler's texel; counts the blocks compared.
void compare_block_with_quad_sampler(const TextureImage& image, const Sampler& sampler, const float* s, const float* t,
                                     int& compared) {
  const QuadSampler quad = select_nearest8_sampler(image, sampler);
  for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
    const BlockSampler block = select_nearest8_block_sampler(sampler, path);
    ASSERT_NE(block, nullptr);
    alignas(64) float out[4][16];
    float* const channels[4] = {out[0], out[1], out[2], out[3]};
    block(image, BlockLevels{}, s, t, channels);
    for (int q = 0; q < 4; ++q) {
      F4 expected[4];
      quad(image, sampler, load4(&s[4 * q]), load4(&t[4 * q]), expected);
      for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 4; ++i)
          ASSERT_EQ(out[c][4 * q + i], expected[c][i]) << "path " << int(path) << " lane " << 4 * q + i;
    }
    ++compared;
  }
}

// The 16-lane form on every instruction-set path: the quad sampler's texels.
TEST(Nearest8Sampler, BlocksGiveTheQuadSamplersTexelsOnEveryPath) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> near(-2.5f, 3.5f);
  const float special[] = {0.f, 1.f, -1.f, 1e7f, -1e7f, std::numeric_limits<float>::infinity(),
                           std::numeric_limits<float>::quiet_NaN(), 1.f / 3.f, -0.f, -std::numeric_limits<float>::infinity(),
                           std::nextafter(1.f, 0.f), std::nextafter(0.f, -1.f), -std::numeric_limits<float>::quiet_NaN()};
  const TexWrap wraps[] = {TexWrap::Repeat, TexWrap::Clamp, TexWrap::ClampToEdge};
  int blocks = 0;
  for (const auto& [w, h] : {std::pair{1, 1}, {5, 3}, {64, 64}, {300, 7}})
    for (TexWrap ws : wraps)
      for (TexWrap wt : wraps) {
        const TextureImage image = random_level(w, h, rng);
        const Sampler sampler = nearest(ws, wt);
        for (int n = 0; n < 50; ++n) {
          alignas(64) float s[16], t[16];
          for (int i = 0; i < 16; ++i) {
            s[i] = n % 4 == 0 ? special[rng() % std::size(special)] : near(rng);
            t[i] = n % 3 == 0 ? special[rng() % std::size(special)] : near(rng);
          }
          compare_block_with_quad_sampler(image, sampler, s, t, blocks);
          if (::testing::Test::HasFatalFailure()) return;
        }
      }
  EXPECT_EQ(blocks, 4 * 9 * 50 * 3);
  EXPECT_EQ(select_nearest8_block_sampler(nearest(TexWrap::MirroredRepeat, TexWrap::Repeat)), nullptr);
}

// Blocks as a magnified or mildly minified draw gives them (a pixel's neighbours a fraction of
// a texel to two texels apart, near every edge): the quad sampler's texels on every path.
TEST(Nearest8Sampler, NearbyBlocksGiveTheQuadSamplersTexels) {
  std::mt19937 rng(5);
  const TexWrap wraps[] = {TexWrap::Repeat, TexWrap::ClampToEdge};
  int blocks = 0;
  for (const auto& [w, h] : {std::pair{16, 4}, {17, 5}, {64, 64}, {300, 7}, {15, 40}})
    for (TexWrap ws : wraps)
      for (TexWrap wt : wraps) {
        const TextureImage image = random_level(w, h, rng);
        const Sampler sampler = nearest(ws, wt);
        for (int n = 0; n < 200; ++n) {
          // Texels per pixel: 0.3 to 2.2, so that some blocks span more than the window.
          const float scale = 0.3f + 1.9f * static_cast<float>(rng() % 1000) / 1000.f;
          const float s0 = -0.1f + 1.2f * static_cast<float>(rng() % 1000) / 1000.f;
          const float t0 = -0.1f + 1.2f * static_cast<float>(rng() % 1000) / 1000.f;
          alignas(64) float s[16], t[16];
          for (int q = 0; q < 4; ++q)  // a block: four quads along a row (8x2 pixels)
            for (int i = 0; i < 4; ++i) {
              s[4 * q + i] = s0 + scale * static_cast<float>(2 * q + (i & 1)) / static_cast<float>(w);
              t[4 * q + i] = t0 + scale * static_cast<float>(i >> 1) / static_cast<float>(h);
            }
          compare_block_with_quad_sampler(image, sampler, s, t, blocks);
          if (::testing::Test::HasFatalFailure()) return;
        }
      }
  EXPECT_EQ(blocks, 5 * 4 * 200 * 3);
}

}  // namespace
}  // namespace pineda::raster
