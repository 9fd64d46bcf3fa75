// The block depth tests (raster/block_depth.h), of four adjacent quads of one primitive and of
// quads apart, each of its own: on every SIMD path, for every depth function, with and without
// depth writes, 24- and 32-bit buffers and partly covered quads, the same passing pixels and
// depth buffer as quad_ops::depth_only testing the quads one after another.
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

// Trial t's depth test: each function in turn, without depth writes every fifth trial.
DrawState trial_state(int width, int height, int trial) {
  DrawState s = test::state_for(width, height);
  s.depth_test = true;
  s.depth_func = kFuncs[trial % 8];
  s.depth_write = trial % 5 != 0;
  return s;
}

// After the quads were tested one by one into `target` (from `before`): on every SIMD path,
// test(path) from `before` passes each quad's `expected` pixels and leaves the same depths.
template <class Test>
void expect_every_path_gives(test::OwnedFramebuffer& target, const std::vector<uint32_t>& before,
                             const unsigned* expected, int trial, const Test& test) {
  const std::vector<uint32_t> expected_depth = target.depth;
  for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
    std::memcpy(target.depth.data(), before.data(), before.size() * sizeof(uint32_t));
    const unsigned got = test(path);
    for (int j = 0; j < 4; ++j)
      ASSERT_EQ((got >> (4 * j)) & 0xFu, expected[j]) << "trial " << trial << " quad " << j << " path " << static_cast<int>(path);
    ASSERT_EQ(got >> 16, 0u);
    ASSERT_EQ(target.depth, expected_depth) << "trial " << trial << " path " << static_cast<int>(path);
  }
}

TEST(BlockDepth, EveryPathTestsAndWritesAsTheQuadsOneByOne) {
  constexpr int kWidth = 24, kHeight = 6;
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int passing = 0, failing = 0, equal_passing = 0;
  for (int trial = 0; trial < 800; ++trial) {
    test::OwnedFramebuffer target(kWidth, kHeight, trial % 3 == 0 ? 32 : 24, false);
    const DrawState s = trial_state(kWidth, kHeight, trial);
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
    const unsigned quad_bits = masks[0] | masks[1] << 4 | masks[2] << 8 | masks[3] << 12;
    expect_every_path_gives(target, before, expected, trial, [&](SimdPath path) {
      return select_block_depth_test(path)(d, p, target.fb, x, y, ox, oy, quad_bits);
    });
  }
  // Both outcomes happened many times.
  EXPECT_GT(passing, 1500);
  EXPECT_GT(failing, 1500);
  EXPECT_GT(equal_passing, 20);
}

TEST(BlockDepth, QuadsApartOfTheirOwnPrimitivesTestAndWriteAsOneByOneOnEveryPath) {
  constexpr int kWidth = 24, kHeight = 6;
  std::mt19937 random(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int passing = 0, failing = 0;
  for (int trial = 0; trial < 800; ++trial) {
    test::OwnedFramebuffer target(kWidth, kHeight, trial % 3 == 0 ? 32 : 24, false);
    const DrawState s = trial_state(kWidth, kHeight, trial);
    const DrawRecord d = make_draw_record(s, target.fb);
    const int n = 2 + trial % 3;  // quads in the block; the others repeat quad 0 without bits
    PrimSetup prims[4];
    BlockQuads places;
    alignas(64) float ox[16], oy[16];
    unsigned masks[4] = {};
    for (int j = 0; j < 4; ++j) {
      PrimSetup& p = prims[j];
      p.z0 = (unit(random) * 1.4 - 0.2) * d.depth_max;
      const bool flat = (trial / 8 + j) % 2 == 0;
      p.dzdx = flat ? 0.0 : (unit(random) - 0.5) * d.depth_max * 0.1;
      p.dzdy = flat ? 0.0 : (unit(random) - 0.5) * d.depth_max * 0.1;
      p.ref_x = static_cast<float>(unit(random) * kWidth);
      p.ref_y = static_cast<float>(unit(random) * kHeight);
      bool taken = true;  // a place no earlier quad has
      while (taken) {
        places.x[j] = 2 * static_cast<int>(random() % (kWidth / 2));
        places.y[j] = 2 * static_cast<int>(random() % (kHeight / 2));
        taken = false;
        for (int k = 0; k < j; ++k) taken |= places.x[k] == places.x[j] && places.y[k] == places.y[j];
      }
      places.prim[j] = &prims[j];
      if (j < n) masks[j] = trial % 7 == 0 ? 0xFu : 1u + static_cast<unsigned>(random() % 15);
    }
    for (int j = n; j < 4; ++j) {
      places.x[j] = places.x[0];
      places.y[j] = places.y[0];
      places.prim[j] = places.prim[0];
    }
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        ox[4 * j + i] = static_cast<float>(places.x[j] + (i & 1)) + 0.5f - places.prim[j]->ref_x;
        oy[4 * j + i] = static_cast<float>(places.y[j] + (i >> 1)) + 0.5f - places.prim[j]->ref_y;
      }
    std::vector<uint32_t> before(target.depth.size());
    for (uint32_t& z : before) z = static_cast<uint32_t>(unit(random) * d.depth_max);
    std::memcpy(target.depth.data(), before.data(), before.size() * sizeof(uint32_t));
    unsigned expected[4] = {};
    for (int j = 0; j < n; ++j) {
      F4 qx, qy;
      std::memcpy(&qx, &ox[4 * j], sizeof qx);
      std::memcpy(&qy, &oy[4 * j], sizeof qy);
      expected[j] = quad_ops::depth_only(d, prims[j], target.fb, places.x[j], places.y[j], masks[j], qx, qy);
      passing += __builtin_popcount(expected[j]);
      failing += __builtin_popcount(masks[j] & ~expected[j]);
    }
    const unsigned quad_bits = masks[0] | masks[1] << 4 | masks[2] << 8 | masks[3] << 12;
    expect_every_path_gives(target, before, expected, trial, [&](SimdPath path) {
      return select_quads_depth_test(path)(d, places, target.fb, ox, oy, quad_bits);
    });
  }
  EXPECT_GT(passing, 1500);
  EXPECT_GT(failing, 1500);
}

}  // namespace
}  // namespace pineda::raster
