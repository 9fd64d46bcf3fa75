// The block colour writes (adjacent quads, and quads anywhere): on every SIMD path, each live
// pixel gets what write_quad's conversion (to_unorm8) and blend8.h's blends (each equal to the
// float blend: blend8_test.cpp) give it, and every other pixel keeps what it had.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/blend8.h"
#include "raster/block_write.h"
#include "raster/quad_ops.h"

namespace pineda::raster {
namespace {

using quad_ops::ChannelShift;
using quad_ops::kBgraShift;
using quad_ops::kRgbaShift;

// What write_quad gives lane `lane`'s pixel over `before`.
constexpr Blend8 kBlends[] = {Blend8::Other, Blend8::Over, Blend8::AddScaled, Blend8::Add, Blend8::OverKeepAlpha};

uint32_t expected_pixel(const float (*color)[16], int lane, const ChannelShift& shift, Blend8 blend, uint32_t before) {
  U4 packed = {0, 0, 0, 0};
  for (int c = 0; c < 4; ++c) packed |= to_unorm8(splat(color[c][lane])) << shift.at[c];
  if (blend == Blend8::Over) packed = blend_over8(packed, U4{} + before);
  if (blend == Blend8::AddScaled) packed = blend_add_scaled8(packed, U4{} + before);
  if (blend == Blend8::Add) packed = blend_add8(packed, U4{} + before);
  if (blend == Blend8::OverKeepAlpha) packed = keep_alpha8(blend_over8(packed, U4{} + before), U4{} + before);
  return packed[0];
}

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
    const Blend8 blend = kBlends[trial % 5];
    // Every lane, then partial masks: each row alone, single lanes, random.
    const uint16_t live = trial < 100 ? 0xFFFF
                          : trial < 110 ? (trial % 2 ? 0x3333 : 0xCCCC)
                          : trial < 130 ? static_cast<uint16_t>(1u << (trial % 16))
                                        : static_cast<uint16_t>(pixel(random));
    const ChannelShift& shift = trial % 10 < 5 ? kRgbaShift : kBgraShift;
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
        ASSERT_EQ(rows[y][x], expected_pixel(color, lane, shift, blend, before[y][x])) << "trial " << trial << " lane " << lane;
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
    for (Blend8 blend : kBlends) {
      std::vector<uint32_t> pixels(2, 0xff00ff00u);
      uint8_t* row = reinterpret_cast<uint8_t*>(pixels.data());
      select_block_writer(path)(color, kRgbaShift.at, blend, row, row, 0x0003);
      // Red, opaque: over green, replaces it or adds to it.
      const uint32_t want = blend == Blend8::AddScaled || blend == Blend8::Add ? 0xff00ffffu : 0xff0000ffu;
      EXPECT_EQ(pixels[0], want);
      EXPECT_EQ(pixels[1], want);
    }
  }
}

// Four quads anywhere in a 16x16 buffer, no two at one place, with random live lanes: each live
// pixel gets what write_quad gives it, every other pixel of the buffer keeps what it had.
TEST(QuadsWrite, EveryPathWritesWhatTheQuadWriterWould) {
  std::mt19937 random(9);
  std::uniform_real_distribution<float> value(-0.25f, 1.25f);
  std::uniform_int_distribution<uint32_t> pixel;
  std::uniform_int_distribution<int> place(0, 7);
  int written = 0;
  for (int trial = 0; trial < 300; ++trial) {
    alignas(64) float color[4][16];
    for (auto& channel : color)
      for (float& v : channel) v = value(random);
    const Blend8 blend = kBlends[trial % 5];
    const ChannelShift& shift = trial % 10 < 5 ? kRgbaShift : kBgraShift;
    const uint16_t live = trial < 50 ? 0xFFFF : static_cast<uint16_t>(pixel(random));
    int qx[4], qy[4];
    for (int j = 0; j < 4; ++j) {
      bool taken = true;
      while (taken) {
        qx[j] = 2 * place(random);
        qy[j] = 2 * place(random);
        taken = false;
        for (int i = 0; i < j; ++i) taken |= qx[i] == qx[j] && qy[i] == qy[j];
      }
    }
    uint32_t before[16][16];
    for (auto& row : before)
      for (uint32_t& p : row) p = pixel(random);
    for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
      uint32_t image[16][16];
      std::memcpy(image, before, sizeof image);
      uint32_t spare[2] = {0x12345678u, 0x9abcdef0u};
      uint8_t* rows[8];
      for (int j = 0; j < 4; ++j)
        for (int r = 0; r < 2; ++r)
          rows[2 * j + r] = (live >> (4 * j + 2 * r)) & 3u ? reinterpret_cast<uint8_t*>(&image[qy[j] + r][qx[j]])
                                                            : reinterpret_cast<uint8_t*>(spare);
      select_quads_writer(path)(color, shift.at, blend, rows, live);
      EXPECT_EQ(spare[0], 0x12345678u);
      EXPECT_EQ(spare[1], 0x9abcdef0u);
      uint32_t expected[16][16];
      std::memcpy(expected, before, sizeof expected);
      for (int lane = 0; lane < 16; ++lane) {
        if (!((live >> lane) & 1)) continue;
        const int j = lane / 4, x = qx[j] + (lane & 1), y = qy[j] + ((lane >> 1) & 1);
        expected[y][x] = expected_pixel(color, lane, shift, blend, before[y][x]);
        ++written;
      }
      for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) ASSERT_EQ(image[y][x], expected[y][x]) << "trial " << trial << " at " << x << "," << y;
    }
  }
  EXPECT_GT(written, 300 * 3 * 6);
}

// A quad whose right pixel lies past the buffer: only the live one is read and written (the
// sanitizer build catches any other byte).
TEST(QuadsWrite, TouchesOnlyTheLivePixels) {
  alignas(64) float color[4][16] = {};
  for (int lane = 0; lane < 16; ++lane) color[1][lane] = color[3][lane] = 1.f;
  for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
    for (Blend8 blend : kBlends) {
      std::vector<uint32_t> pixels(1, 0xff0000ffu);
      uint32_t spare[2] = {};
      uint8_t* rows[8];
      std::fill_n(rows, 8, reinterpret_cast<uint8_t*>(spare));
      rows[4] = reinterpret_cast<uint8_t*>(pixels.data());  // quad 2's first row, its left pixel alone
      select_quads_writer(path)(color, kRgbaShift.at, blend, rows, 0x0100);
      EXPECT_EQ(pixels[0], blend == Blend8::AddScaled || blend == Blend8::Add ? 0xff00ffffu : 0xff00ff00u);
    }
  }
}

}  // namespace
}  // namespace pineda::raster
