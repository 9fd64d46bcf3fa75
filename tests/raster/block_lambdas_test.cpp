// bilinear8_block_lambdas, the level of detail of a block's four quads in vector lanes, with
// levels_at against bilinear8_quad_levels quad by quad: the same level, pair, blend and filter
// for every quad,
// over filters, biases, LOD clamps, image sizes and coordinates from magnified to minified past
// the last level, including subnormal, zero, infinite and NaN scale factors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "raster/sampler_bilinear8.h"

namespace pineda::raster {
namespace {

TextureImage mipmapped(int width, int height) {
  TextureImage image;
  for (int w = width, h = height;; w = std::max(w / 2, 1), h = std::max(h / 2, 1)) {
    image.levels.push_back({w, h, CacheLineVector<uint32_t>(static_cast<size_t>(w) * h)});
    if (w == 1 && h == 1) break;
  }
  return image;
}

bool same(const LevelChoice& a, const LevelChoice& b) {
  return a.first == b.first && a.two == b.two && a.linear == b.linear && std::memcmp(&a.blend, &b.blend, sizeof a.blend) == 0;
}

TEST(BlockLambdas, FourQuadsAtOnceChooseAsQuadByQuad) {
  std::mt19937 random(21);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float special[] = {0.f, -0.f, 1e-30f, 1e-40f, 1e7f, -1e7f, inf, -inf, nan, 0.5f};
  const TexFilter filters[] = {TexFilter::NearestMipmapNearest, TexFilter::LinearMipmapNearest,
                               TexFilter::NearestMipmapLinear, TexFilter::LinearMipmapLinear};
  int quads = 0, pairs = 0, distinct_levels = 0;
  for (const auto& [w, h] : {std::pair{256, 256}, {64, 16}, {1, 1}, {300, 7}}) {
    const TextureImage image = mipmapped(w, h);
    for (TexFilter min : filters)
      for (TexFilter mag : {TexFilter::Nearest, TexFilter::Linear})
        for (int n = 0; n < 200; ++n) {
          Sampler sampler;
          sampler.min_filter = min;
          sampler.mag_filter = mag;
          sampler.lod_bias = n % 5 == 0 ? std::uniform_real_distribution<float>(-3.f, 3.f)(random) : 0.f;
          if (n % 7 == 0) sampler.min_lod = std::uniform_real_distribution<float>(-2.f, 4.f)(random);
          if (n % 11 == 0) sampler.max_lod = std::uniform_real_distribution<float>(0.f, 6.f)(random);
          // A block's pixels: a base coordinate and per-quad steps from about 1/64 to 64 texels.
          alignas(16) float s[16], t[16];
          for (int q = 0; q < 4; ++q) {
            const float step = std::ldexp(1.f, std::uniform_int_distribution<int>(-6, 6)(random)) / static_cast<float>(w);
            const float s0 = std::uniform_real_distribution<float>(-2.f, 3.f)(random);
            const float t0 = std::uniform_real_distribution<float>(-2.f, 3.f)(random);
            for (int i = 0; i < 4; ++i) {
              s[4 * q + i] = s0 + step * static_cast<float>(i & 1) * std::uniform_real_distribution<float>(0.5f, 1.5f)(random);
              t[4 * q + i] = t0 + step * static_cast<float>(i >> 1) * std::uniform_real_distribution<float>(0.5f, 1.5f)(random);
              if (n % 9 == 0 && random() % 3 == 0) s[4 * q + i] = special[random() % std::size(special)];
              if (n % 13 == 0 && random() % 3 == 0) t[4 * q + i] = special[random() % std::size(special)];
            }
            if (n % 17 == 0) {  // a quad without extent: rho^2 = 0
              for (int i = 1; i < 4; ++i) s[4 * q + i] = s[4 * q], t[4 * q + i] = t[4 * q];
            }
          }
          F4 bias = splat(sampler.lod_bias);
          Sampler biased[4] = {sampler, sampler, sampler, sampler};
          for (int q = 0; q < 4; ++q)
            if (n % 3 == 0) {
              const float extra = std::uniform_real_distribution<float>(-2.f, 2.f)(random);
              bias[q] = sampler.lod_bias + extra;
              biased[q].lod_bias += extra;
            }
          const F4 lambda = bilinear8_block_lambdas(image, sampler, s, t, bias);
          const int max_level = static_cast<int>(image.levels.size()) - 1;
          LevelChoice block[4];
          for (int q = 0; q < 4; ++q) block[q] = levels_at(sampler, lambda[q], max_level);
          for (int q = 0; q < 4; ++q) {
            const LevelChoice quad = bilinear8_quad_levels(image, biased[q], load4(&s[4 * q]), load4(&t[4 * q]));
            ASSERT_TRUE(same(block[q], quad)) << w << "x" << h << " quad " << q << ": block " << block[q].first << "/"
                                              << block[q].two << "/" << block[q].blend << ", quad " << quad.first << "/"
                                              << quad.two << "/" << quad.blend;
            ++quads;
            pairs += quad.two;
            distinct_levels += quad.first > 0;
          }
        }
  }
  EXPECT_EQ(quads, 4 * 4 * 2 * 200 * 4);
  // Both kinds of choice occur in numbers (the counts follow from the seed).
  EXPECT_GT(pairs, 1000);
  EXPECT_GT(distinct_levels, 1000);
}

}  // namespace
}  // namespace pineda::raster
