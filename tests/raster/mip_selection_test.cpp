// The level of detail from rho^2: log2 piecewise linear between powers of two, as llvmpipe
// takes it, from the float's exponent and mantissa (also for subnormal and infinite rho^2).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

}  // namespace
}  // namespace pineda::raster
