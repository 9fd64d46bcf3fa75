// The block colour write: on every SIMD path, each live pixel gets what write_quad's
// conversion (to_unorm8) and SRC_ALPHA / ONE_MINUS_SRC_ALPHA blend (blend_over8) give it, and
// every other pixel keeps what it had.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/blend_over.h"
#include "raster/block_write.h"
#include "raster/quad_ops.h"

namespace pineda::raster {
namespace {

using quad_ops::ChannelShift;
using quad_ops::kBgraShift;
using quad_ops::kRgbaShift;

TEST(BlockWrite, EveryPathWritesWhatTheQuadWriterWould) {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> value(-0.25f, 1.25f);
  std::uniform_int_distribution<uint32_t> pixel;
  int pixels = 0;
  for (int trial = 0; trial < 200; ++trial) {
    alignas(64) float color[4][16];
    for (auto& channel : color)
      for (float& v : channel) v = value(random);
    // Exact halves round to even; NaN and infinities clamp.
    color[0][0] = 0.5f / 255.f;
    color[1][1] = 2.5f / 255.f;
    color[2][2] = std::numeric_limits<float>::quiet_NaN();
    color[3][3] = std::numeric_limits<float>::infinity();
    const bool blend = trial % 2 == 1;
    // Every lane, then partial masks: each row alone, single lanes, random.
    const uint16_t live = trial < 100 ? 0xFFFF
                          : trial < 110 ? (trial % 2 ? 0x3333 : 0xCCCC)
                          : trial < 130 ? static_cast<uint16_t>(1u << (trial % 16))
                                        : static_cast<uint16_t>(pixel(random));
    const ChannelShift& shift = trial % 4 < 2 ? kRgbaShift : kBgraShift;
    uint32_t before[2][8];
    for (auto& row : before)
      for (uint32_t& p : row) p = pixel(random);
    for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
      uint32_t rows[2][8];
      std::memcpy(rows, before, sizeof rows);
      select_block_writer(path)(color, shift.at, blend, reinterpret_cast<uint8_t*>(rows[0]),
                                reinterpret_cast<uint8_t*>(rows[1]), live);
      for (int lane = 0; lane < 16; ++lane) {
        const int quad = lane / 4, i = lane % 4, x = 2 * quad + (i & 1), y = i >> 1;
        if (!((live >> lane) & 1)) {
          ASSERT_EQ(rows[y][x], before[y][x]) << "trial " << trial << " lane " << lane << " is not live";
          ++pixels;
          continue;
        }
        U4 packed = {0, 0, 0, 0};
        for (int c = 0; c < 4; ++c) packed |= to_unorm8(splat(color[c][lane])) << shift.at[c];
        if (blend) packed = blend_over8(packed, U4{} + before[y][x]);
        ASSERT_EQ(rows[y][x], packed[0]) << "trial " << trial << " lane " << lane;
        ++pixels;
      }
    }
  }
  EXPECT_EQ(pixels, 200 * 3 * 16);
}

// A block at the right and bottom edge of a buffer: only its two live pixels exist (the
// sanitizer build catches any other byte read or written).
TEST(BlockWrite, TouchesOnlyTheLivePixels) {
  alignas(64) float color[4][16] = {};
  for (int lane = 0; lane < 16; ++lane) color[0][lane] = color[3][lane] = 1.f;
  for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
    for (bool blend : {false, true}) {
      std::vector<uint32_t> pixels(2, 0xff00ff00u);
      uint8_t* row = reinterpret_cast<uint8_t*>(pixels.data());
      select_block_writer(path)(color, kRgbaShift.at, blend, row, row, 0x0003);
      EXPECT_EQ(pixels[0], 0xff0000ffu);
      EXPECT_EQ(pixels[1], 0xff0000ffu);
    }
  }
}

}  // namespace
}  // namespace pineda::raster
