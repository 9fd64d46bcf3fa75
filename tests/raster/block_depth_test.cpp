// The block depth test (raster/block_depth.h): on every SIMD path, for every depth function, with
// and without depth writes, 24- and 32-bit buffers and partly covered quads, the same passing
// pixels and depth buffer as quad_ops::depth_only testing the four quads one after another.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "raster/block_depth.h"
#include "raster/draw_record.h"
#include "raster/quad_ops.h"
#include "tests/raster/test_support.h"

namespace pineda::raster {
namespace {

constexpr CompareFunc kFuncs[] = {CompareFunc::Never,   CompareFunc::Less,     CompareFunc::Equal,
                                  CompareFunc::LessEqual, CompareFunc::Greater, CompareFunc::NotEqual,
                                  CompareFunc::GreaterEqual, CompareFunc::Always};

TEST(BlockDepth, EveryPathTestsAndWritesAsTheQuadsOneByOne) {
  constexpr int kWidth = 24, kHeight = 6;
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int passing = 0, failing = 0, equal_passing = 0;
  for (int trial = 0; trial < 800; ++trial) {
    const int bits = trial % 3 == 0 ? 32 : 24;
    test::OwnedFramebuffer target(kWidth, kHeight, bits, false);
    DrawState s = test::state_for(kWidth, kHeight);
    s.depth_test = true;
    s.depth_func = kFuncs[trial % 8];
    s.depth_write = trial % 5 != 0;
    const DrawRecord d = make_draw_record(s, target.fb);
    PrimSetup p;
    // Depths that reach past both ends (clamped), and planes flat enough for equal values.
    p.z0 = (unit(random) * 1.4 - 0.2) * d.depth_max;
    const bool flat = (trial / 8) % 2 == 0;
    p.dzdx = flat ? 0.0 : (unit(random) - 0.5) * d.depth_max * 0.1;
    p.dzdy = flat ? 0.0 : (unit(random) - 0.5) * d.depth_max * 0.1;
    p.ref_x = static_cast<float>(unit(random) * kWidth);
    p.ref_y = static_cast<float>(unit(random) * kHeight);
    const int x = 2 * static_cast<int>(unit(random) * 8), y = 2 * static_cast<int>(unit(random) * 2);
    std::vector<uint32_t> before(target.depth.size());
    // Half the flat planes' trials store the plane's depth where it is in range (Equal passes).
    const bool stored_equal = flat && (trial / 16) % 2 == 0 && p.z0 >= 0.0 && p.z0 <= d.depth_max;
    for (uint32_t& z : before)
      z = stored_equal && random() % 2 ? static_cast<uint32_t>(p.z0 + 0.5) : static_cast<uint32_t>(unit(random) * d.depth_max);
    alignas(64) float ox[16], oy[16];
    unsigned masks[4];
    for (int j = 0; j < 4; ++j) {
      masks[j] = trial % 7 == 0 ? 0xFu : static_cast<unsigned>(random() % 16);
      for (int i = 0; i < 4; ++i) {
        ox[4 * j + i] = static_cast<float>(x + 2 * j + (i & 1)) + 0.5f - p.ref_x;
        oy[4 * j + i] = static_cast<float>(y + (i >> 1)) + 0.5f - p.ref_y;
      }
    }
    // The quads one by one.
    std::memcpy(target.depth.data(), before.data(), before.size() * sizeof(uint32_t));
    unsigned expected[4];
    for (int j = 0; j < 4; ++j) {
      F4 qx, qy;
      std::memcpy(&qx, &ox[4 * j], sizeof qx);
      std::memcpy(&qy, &oy[4 * j], sizeof qy);
      expected[j] = quad_ops::depth_only(d, p, target.fb, x + 2 * j, y, masks[j], qx, qy);
      passing += __builtin_popcount(expected[j]);
      if (s.depth_func == CompareFunc::Equal) equal_passing += __builtin_popcount(expected[j]);
      failing += __builtin_popcount(masks[j] & ~expected[j]);
    }
    const std::vector<uint32_t> expected_depth = target.depth;
    for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
      std::memcpy(target.depth.data(), before.data(), before.size() * sizeof(uint32_t));
      const unsigned quad_bits = masks[0] | masks[1] << 4 | masks[2] << 8 | masks[3] << 12;
      const unsigned got = select_block_depth_test(path)(d, p, target.fb, x, y, ox, oy, quad_bits);
      for (int j = 0; j < 4; ++j)
        ASSERT_EQ((got >> (4 * j)) & 0xFu, expected[j])
            << "trial " << trial << " quad " << j << " path " << static_cast<int>(path);
      ASSERT_EQ(got >> 16, 0u);
      ASSERT_EQ(target.depth, expected_depth) << "trial " << trial << " path " << static_cast<int>(path);
    }
  }
  // Both outcomes happened many times.
  EXPECT_GT(passing, 1500);
  EXPECT_GT(failing, 1500);
  EXPECT_GT(equal_passing, 20);
}

}  // namespace
}  // namespace pineda::raster
