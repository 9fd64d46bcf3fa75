// The 16-lane depth sampler of shader lookups (select_depth_block_sampler): which images and
// samplers it takes, and bit for bit the quad sampler's values (sample_depth_quad) on every
// instruction-set path, for any coordinates, filter, wrap mode, size and depth texture mode.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "raster/sampler_depth.h"

namespace pineda::raster {
namespace {

TextureImage depth_image(int w, int h, TexBaseFormat mode, std::mt19937& rng) {
  TextureImage image;
  image.depth = true;
  image.base_format = mode;
  std::uniform_real_distribution<float> depth(0.f, 1.f);
  std::vector<uint32_t> texels(static_cast<size_t>(w) * h);
  for (uint32_t& t : texels) t = std::bit_cast<uint32_t>(depth(rng));
  image.levels.push_back({w, h, CacheLineVector<uint32_t>(texels.begin(), texels.end())});
  return image;
}

Sampler filtered(TexFilter filter, TexWrap s, TexWrap t) {
  Sampler out;
  out.min_filter = out.mag_filter = filter;
  out.wrap_s = s;
  out.wrap_t = t;
  return out;
}

TEST(DepthBlockSampler, TakesLevelZeroOfPlanarDepthImagesWithOneFilterAndNoComparison) {
  std::mt19937 rng(1);
  const TextureImage image = depth_image(4, 3, TexBaseFormat::Luminance, rng);
  for (TexFilter f : {TexFilter::Nearest, TexFilter::Linear})
    for (TexWrap w : {TexWrap::Repeat, TexWrap::ClampToEdge}) {
      EXPECT_NE(select_depth_block_sampler(image, filtered(f, w, TexWrap::Repeat)), nullptr);
      EXPECT_NE(select_depth_block_sampler(image, filtered(f, TexWrap::ClampToEdge, w)), nullptr);
    }
  // GL_CLAMP picks CLAMP_TO_EDGE's texel when nearest; linear, it blends in the border.
  EXPECT_NE(select_depth_block_sampler(image, filtered(TexFilter::Nearest, TexWrap::Clamp, TexWrap::Clamp)), nullptr);
  EXPECT_EQ(select_depth_block_sampler(image, filtered(TexFilter::Linear, TexWrap::Clamp, TexWrap::Repeat)), nullptr);
  for (TexWrap w : {TexWrap::ClampToBorder, TexWrap::MirroredRepeat}) {
    EXPECT_EQ(select_depth_block_sampler(image, filtered(TexFilter::Nearest, w, TexWrap::Repeat)), nullptr);
    EXPECT_EQ(select_depth_block_sampler(image, filtered(TexFilter::Linear, TexWrap::Repeat, w)), nullptr);
  }
  Sampler minified_other_way = filtered(TexFilter::Linear, TexWrap::Repeat, TexWrap::Repeat);
  minified_other_way.min_filter = TexFilter::Nearest;  // the level of detail picks the filter
  EXPECT_EQ(select_depth_block_sampler(image, minified_other_way), nullptr);
  Sampler mipmapped = filtered(TexFilter::Linear, TexWrap::Repeat, TexWrap::Repeat);
  mipmapped.min_filter = TexFilter::LinearMipmapNearest;
  EXPECT_EQ(select_depth_block_sampler(image, mipmapped), nullptr);
  Sampler compared = filtered(TexFilter::Nearest, TexWrap::Repeat, TexWrap::Repeat);
  compared.compare = true;
  EXPECT_EQ(select_depth_block_sampler(image, compared), nullptr);
  const Sampler plain = filtered(TexFilter::Nearest, TexWrap::Repeat, TexWrap::Repeat);
  TextureImage colour = image;
  colour.depth = false;
  EXPECT_EQ(select_depth_block_sampler(colour, plain), nullptr);
  TextureImage rectangle = image;
  rectangle.kind = TexKind::Rect;
  EXPECT_EQ(select_depth_block_sampler(rectangle, plain), nullptr);
  TextureImage swizzled = image;
  swizzled.depth_swizzle[0] = 3;
  EXPECT_EQ(select_depth_block_sampler(swizzled, plain), nullptr);
  TextureImage short_level = image;
  short_level.levels[0].texels.edit().pop_back();
  EXPECT_EQ(select_depth_block_sampler(short_level, plain), nullptr);
}

// Coordinates inside, outside, on texel edges and centres, huge, infinite and NaN.
TEST(DepthBlockSampler, BlocksGiveTheQuadSamplersValuesOnEveryPath) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> near(-2.5f, 3.5f);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float special[] = {0.f, 1.f, -1.f, 0.5f, 1e7f, -1e7f, inf, -inf, nan, 1.f / 3.f, -0.f,
                           std::nextafter(1.f, 0.f), std::nextafter(0.f, -1.f), -nan};
  const TexWrap wraps[] = {TexWrap::Repeat, TexWrap::Clamp, TexWrap::ClampToEdge};
  const TexBaseFormat modes[] = {TexBaseFormat::Luminance, TexBaseFormat::Intensity, TexBaseFormat::Alpha};
  int blocks = 0, images = 0;
  for (const auto& [w, h] : {std::pair{1, 1}, {5, 3}, {64, 64}, {300, 7}})
    for (TexFilter filter : {TexFilter::Nearest, TexFilter::Linear})
      for (TexWrap ws : wraps)
        for (TexWrap wt : wraps) {
          const Sampler sampler = filtered(filter, ws, wt);
          const TextureImage image = depth_image(w, h, modes[images++ % 3], rng);
          if (filter == TexFilter::Linear && (ws == TexWrap::Clamp || wt == TexWrap::Clamp)) {
            EXPECT_EQ(select_depth_block_sampler(image, sampler), nullptr);
            continue;
          }
          for (int n = 0; n < 40; ++n) {
            alignas(64) float s[16], t[16];
            for (int i = 0; i < 16; ++i) {
              s[i] = n % 4 == 0 ? special[rng() % std::size(special)] : near(rng);
              t[i] = n % 3 == 0 ? special[rng() % std::size(special)] : near(rng);
              if (n % 5 == 1) s[i] = std::floor(s[i] * w) / w;                // texel edges
              if (n % 5 == 2) t[i] = (std::floor(t[i] * h) + 0.5f) / h;       // texel centres
            }
            for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
              const BlockSampler block = select_depth_block_sampler(image, sampler, path);
              ASSERT_NE(block, nullptr);
              alignas(64) float out[4][16];
              float* const channels[4] = {out[0], out[1], out[2], out[3]};
              block(image, BlockLevels{}, s, t, channels);
              for (int q = 0; q < 4; ++q) {
                float expected[4][4];
                sample_depth_quad(image, sampler, &s[4 * q], &t[4 * q], nullptr, expected);
                for (int i = 0; i < 4; ++i)
                  for (int c = 0; c < 4; ++c)
                    ASSERT_EQ(std::bit_cast<uint32_t>(out[c][4 * q + i]), std::bit_cast<uint32_t>(expected[i][c]))
                        << w << "x" << h << " filter " << int(filter) << " wrap " << int(ws) << "/" << int(wt)
                        << " path " << int(path) << " s " << s[4 * q + i] << " t " << t[4 * q + i] << " channel " << c;
              }
              ++blocks;
            }
          }
        }
  // Per size: 9 nearest wrap pairs and the 4 linear ones without GL_CLAMP, 40 blocks, 3 paths.
  EXPECT_EQ(blocks, 4 * (9 + 4) * 40 * 3);
}

}  // namespace
}  // namespace pineda::raster
