// WindowTransform::prepare_many, which takes vertices to the window in vector lanes, against
// prepare(), one vertex at a time: the same usable flags and, for usable vertices, the same
// positions bit for bit, on every instruction-set path, for any count (the lanes' remainder).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/window_transform.h"

namespace pineda::raster {
namespace {

// Clip coordinates around the clip volume, past the guard band, on sub-pixel ties, and special
// values.
float coordinate(std::mt19937& random) {
  const float special[] = {0.f, -0.f, 1.f, -1.f, 1e-30f, 1e30f, -1e30f, std::numeric_limits<float>::infinity(),
                           -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                           std::numeric_limits<float>::denorm_min()};
  const int kind = std::uniform_int_distribution<int>(0, 9)(random);
  if (kind == 0) return special[std::uniform_int_distribution<size_t>(0, std::size(special) - 1)(random)];
  if (kind == 1) return std::uniform_real_distribution<float>(-5000.f, 5000.f)(random);
  // Multiples of 2^-18: with w = 1 in a 1024-pixel viewport, often half a sub-pixel (a tie to round).
  if (kind == 2) return std::ldexp(static_cast<float>(std::uniform_int_distribution<int>(-1 << 18, 1 << 18)(random)), -18);
  return std::uniform_real_distribution<float>(-1.5f, 1.5f)(random);
}

TEST(WindowLanes, PrepareManyGivesPreparesWindowsOnEveryPath) {
  std::mt19937 random(5);
  const Viewport viewports[] = {{0, 0, 1024, 768, 0.0, 1.0}, {-30, 17, 301, 99, 0.25, 0.75}, {5, 5, 1, 1, 1.0, 0.0}};
  int usable = 0, unusable = 0;
  for (const Viewport& viewport : viewports)
    for (uint32_t planes : {0u, 0b101u, 0b111111u}) {
      const WindowTransform transform(viewport, planes, 16777215.0);
      for (size_t count : {size_t{1}, size_t{7}, size_t{8}, size_t{9}, size_t{64}, size_t{203}}) {
        std::vector<ClipVertex> vertices(count);
        for (ClipVertex& v : vertices) {
          for (float& c : v.clip) c = coordinate(random);
          const int w_kind = static_cast<int>(random() % 4);  // mostly visible
          if (w_kind == 1) v.clip[3] = std::uniform_real_distribution<float>(0.5f, 2.f)(random);
          if (w_kind == 2) v.clip[3] = 1.f;
          for (float& d : v.clip_distance) d = random() % 4 ? std::fabs(coordinate(random)) : coordinate(random);
        }
        const std::vector<float> varying_store(count * 3);
        const float* varyings = varying_store.data();
        std::vector<PreparedWindow> expected(count);
        for (size_t i = 0; i < count; ++i) transform.prepare(vertices[i], varyings + i * 3, expected[i]);
        for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
          std::vector<PreparedWindow> got(count);
          transform.prepare_many(vertices.data(), varyings, 3, count, got.data(), path);
          for (size_t i = 0; i < count; ++i) {
            ASSERT_EQ(got[i].usable, expected[i].usable) << "vertex " << i << " path " << int(path);
            if (!expected[i].usable) continue;
            const WinPosition &a = got[i].position, &b = expected[i].position;
            EXPECT_EQ(a.x, b.x);
            EXPECT_EQ(a.y, b.y);
            EXPECT_EQ(std::memcmp(&a.fx, &b.fx, sizeof a.fx), 0) << a.fx << " " << b.fx;
            EXPECT_EQ(std::memcmp(&a.fy, &b.fy, sizeof a.fy), 0) << a.fy << " " << b.fy;
            EXPECT_EQ(std::memcmp(&a.z, &b.z, sizeof a.z), 0) << a.z << " " << b.z;
            EXPECT_EQ(std::memcmp(&a.inv_w, &b.inv_w, sizeof a.inv_w), 0);
            EXPECT_EQ(a.varyings, varyings + i * 3);
          }
        }
        for (const PreparedWindow& w : expected) (w.usable ? usable : unusable) += 1;
      }
    }
  // Both kinds of vertex occur in numbers (the counts follow from the seed).
  EXPECT_GT(usable, 500);
  EXPECT_GT(unusable, 500);
}

}  // namespace
}  // namespace pineda::raster
