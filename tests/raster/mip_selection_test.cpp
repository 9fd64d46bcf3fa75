// The level of detail from rho^2: log2 piecewise linear between powers of two, as llvmpipe
// takes it, from the float's exponent and mantissa (also for subnormal and infinite rho^2);
// the four-lane forms the fill routines take give each lane the scalar functions' values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "raster/mip_selection.h"

namespace pineda::raster {
namespace {

TEST(MipSelection, LambdaIsHalfThePiecewiseLinearLog2OfRho2) {
  EXPECT_EQ(lambda_from_rho2(1.f), 0.f);
  EXPECT_EQ(lambda_from_rho2(4.f), 1.f);
  EXPECT_EQ(lambda_from_rho2(0.25f), -1.f);
  EXPECT_EQ(lambda_from_rho2(3.f), 0.75f);     // log2 taken as 1.5 between 2 and 4
  EXPECT_EQ(lambda_from_rho2(1.5f), 0.25f);
  EXPECT_EQ(lambda_from_rho2(0x1p-149f), -74.5f);  // the smallest subnormal: 2^-149
  EXPECT_EQ(lambda_from_rho2(0x1.8p-140f), -69.75f);  // a subnormal with a mantissa
  EXPECT_EQ(lambda_from_rho2(std::numeric_limits<float>::max()), 0.5f * (127.f + (2.f * (1.f - 0x1p-24f) - 1.f)));
  EXPECT_EQ(lambda_from_rho2(std::numeric_limits<float>::infinity()), std::numeric_limits<float>::infinity());
  EXPECT_EQ(lambda_from_rho2(0.f), -std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(lambda_from_rho2(-1.f)));
  EXPECT_TRUE(std::isnan(lambda_from_rho2(std::numeric_limits<float>::quiet_NaN())));
}

TEST(MipSelection, LanesGiveTheScalarLevels) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> rho2s = {0.f,    -0.f,  -1.f,  nan,          inf,          0x1p-149f, 0x1.8p-140f, 0x1p-126f,
                                    0.25f,  0.9f,  1.f,   1.5f,         3.f,          4.f,       4.5f,        17.f,
                                    250.f,  1e6f,  3e9f,  1e30f,        std::numeric_limits<float>::max(), 2.f, 8.f, 63.f};
  struct Limits {
    float bias, min_lod, max_lod;
  };
  const Limits limits[] = {{0.f, -1000.f, 1000.f}, {0.7f, -1000.f, 1000.f}, {-2.5f, 0.5f, 3.25f}, {1e30f, -1e30f, inf}};
  int lanes_checked = 0;
  for (const TexFilter min : {TexFilter::LinearMipmapLinear, TexFilter::NearestMipmapLinear})
    for (const TexFilter mag : {TexFilter::Linear, TexFilter::Nearest})
      for (const Limits& l : limits)
        for (size_t i = 0; i < rho2s.size(); i += 4) {
          Sampler sampler;
          sampler.min_filter = min;
          sampler.mag_filter = mag;
          sampler.lod_bias = l.bias;
          sampler.min_lod = l.min_lod;
          sampler.max_lod = l.max_lod;
          const F4 rho2 = {rho2s[i], rho2s[i + 1], rho2s[i + 2], rho2s[i + 3]};
          const F4 lambda = clamped_lambda_lanes(sampler, rho2);
          I4 first, two, blend256;
          blended_levels_lanes(sampler, lambda, 5, first, two, blend256);
          for (int k = 0; k < 4; ++k) {
            const float expected_lambda = clamped_lambda(sampler, lambda_from_rho2(rho2[k]));
            EXPECT_EQ(lambda[k], expected_lambda) << "rho2 " << rho2[k];
            const LevelChoice choice = levels_at(sampler, expected_lambda, 5);
            EXPECT_EQ(first[k], choice.first) << "rho2 " << rho2[k] << " bias " << l.bias;
            EXPECT_EQ(two[k] != 0, choice.two) << "rho2 " << rho2[k] << " bias " << l.bias;
            if (choice.two) {
              EXPECT_EQ(blend256[k], static_cast<int>(choice.blend * 256.f)) << "rho2 " << rho2[k];
            }
            ++lanes_checked;
          }
        }
  EXPECT_EQ(lanes_checked, 2 * 2 * 4 * 24);
}

}  // namespace
}  // namespace pineda::raster
