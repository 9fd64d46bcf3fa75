// The conversions between a depth texture's float texels and the integers the depth test
// compares while the texture is rendered into (state/framebuffers/depth_copy.h).
#include "state/framebuffers/depth_copy.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace pineda {
namespace {

std::vector<uint32_t> all_values(int bits) {
  std::vector<uint32_t> v(size_t{1} << bits);
  for (size_t i = 0; i < v.size(); ++i) v[i] = uint32_t(i);
  return v;
}

// Every 16- and 24-bit value gives the float its quotient rounds to (the division itself).
TEST(DepthCopy, EveryValueBecomesItsCorrectlyRoundedQuotient) {
  for (const int bits : {16, 24}) {
    const std::vector<uint32_t> in = all_values(bits);
    std::vector<uint32_t> out(in.size());
    depth_floats_from_integers(in.data(), out.data(), in.size(), bits);
    const double max = std::ldexp(1.0, bits) - 1.0;
    size_t wrong = 0;
    for (size_t i = 0; i < in.size(); ++i) wrong += out[i] != std::bit_cast<uint32_t>(static_cast<float>(in[i] / max));
    EXPECT_EQ(wrong, 0u) << bits << " bits";
    EXPECT_EQ(std::bit_cast<float>(out.back()), 1.0f);
  }
  // A count past the vector steps (8, then 5 one at a time).
  const uint32_t some[13] = {0, 1, 2, 77, 1000, 4095, 65534, 65535, 3, 5, 9, 30000, 65533};
  uint32_t some_out[13];
  depth_floats_from_integers(some, some_out, 13, 16);
  for (int i = 0; i < 13; ++i)
    EXPECT_EQ(some_out[i], std::bit_cast<uint32_t>(static_cast<float>(some[i] / 65535.0))) << some[i];
  const uint32_t in[3] = {0u, 0x80000000u, 0xffffffffu};
  uint32_t out[3];
  depth_floats_from_integers(in, out, 3, 32);
  EXPECT_EQ(std::bit_cast<float>(out[0]), 0.0f);
  EXPECT_EQ(std::bit_cast<float>(out[1]), static_cast<float>(2147483648.0 / 4294967295.0));
  EXPECT_EQ(std::bit_cast<float>(out[2]), 1.0f);
}

// Every 16- and 24-bit value comes back from its float; the rest round to the nearest, ties to
// even, clamped to [0, 1], NaN as 0.
TEST(DepthCopy, FloatsRoundToTheNearestIntegerAndValuesComeBack) {
  for (const int bits : {16, 24}) {
    const std::vector<uint32_t> in = all_values(bits);
    std::vector<uint32_t> texels(in.size()), back(in.size());
    depth_floats_from_integers(in.data(), texels.data(), in.size(), bits);
    depth_integers_from_floats(texels.data(), back.data(), in.size(), bits);
    EXPECT_EQ(back, in) << bits << " bits";
  }
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float z[6] = {-0.5f, 2.0f, nan, inf, 0.5f, 1.0f};
  uint32_t texels[6], out[6];
  for (int i = 0; i < 6; ++i) texels[i] = std::bit_cast<uint32_t>(z[i]);
  depth_integers_from_floats(texels, out, 6, 16);
  const uint32_t expected[6] = {0, 65535, 0, 65535, 32768, 65535};  // 0.5: 32767.5, to even
  for (int i = 0; i < 6; ++i) EXPECT_EQ(out[i], expected[i]) << i;
  depth_integers_from_floats(texels + 4, out, 1, 1);  // 0.5 to even: 0
  EXPECT_EQ(out[0], 0u);
  depth_integers_from_floats(texels + 4, out, 1, 2);  // 1.5 to even: 2
  EXPECT_EQ(out[0], 2u);
  depth_integers_from_floats(texels + 5, out, 1, 32);
  EXPECT_EQ(out[0], 0xffffffffu);
}

}  // namespace
}  // namespace pineda
