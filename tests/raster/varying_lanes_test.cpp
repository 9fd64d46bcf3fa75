// The shader block's varying interpolation: every SIMD path gives, lane by lane, what
// eval_plane gives a quad (and the perspective division by the 1/w plane).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "raster/fragment_extras.h"
#include "raster/varying_lanes.h"

namespace pineda::raster {
namespace {

TEST(VaryingLanes, EveryPathGivesTheQuadValues) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> value(-100.f, 100.f), step(-2.f, 2.f), offset(-40.f, 40.f);
  for (int trial = 0; trial < 100; ++trial) {
    Plane planes[8];
    for (Plane& plane : planes) plane = {value(random), step(random), step(random)};
    const Plane inv_w{1.f + 0.01f * value(random), 0.001f * step(random), 0.001f * step(random)};
    alignas(64) float ox[kVaryingLanes], oy[kVaryingLanes];
    for (int l = 0; l < kVaryingLanes; ++l) ox[l] = offset(random), oy[l] = offset(random);
    const bool perspective = trial % 2 == 0;
    for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
      alignas(64) float out[8][kVaryingLanes], w[kVaryingLanes];
      select_varying_interpolator(path)(planes, 8, inv_w, perspective, ox, oy, out, w);
      for (int q = 0; q < 4; ++q) {
        const F4 qx = load4(&ox[4 * q]), qy = load4(&oy[4 * q]);
        const F4 quad_w = eval_plane(inv_w, qx, qy);
        const F4 inv = 1.f / quad_w;
        float expected_w[4];
        store4(expected_w, quad_w);
        ASSERT_EQ(std::memcmp(&w[4 * q], expected_w, sizeof expected_w), 0);
        for (int v = 0; v < 8; ++v) {
          F4 value = eval_plane(planes[v], qx, qy);
          if (perspective) value *= inv;
          float expected[4];
          store4(expected, value);
          ASSERT_EQ(std::memcmp(&out[v][4 * q], expected, sizeof expected), 0) << trial << " " << v << " " << q;
        }
      }
    }
  }
}

// Four quads of four primitives, some with perspective and some without: each quad's lanes get
// the values its own primitive's planes give it.
TEST(VaryingLanes, EveryPathGivesEachQuadItsOwnPrimitivesValues) {
  std::mt19937 random(13);
  std::uniform_real_distribution<float> value(-100.f, 100.f), step(-2.f, 2.f), offset(-40.f, 40.f);
  for (int trial = 0; trial < 100; ++trial) {
    const int count = 1 + trial % 9;
    Plane planes[4][10];  // one past the count: the primitives' planes are followed by more
    Plane inv_w[4];
    QuadPlanes quads;
    for (int j = 0; j < 4; ++j) {
      for (Plane& plane : planes[j]) plane = {value(random), step(random), step(random)};
      inv_w[j] = {1.f + 0.01f * value(random), 0.001f * step(random), 0.001f * step(random)};
      quads.planes[j] = planes[j];
      quads.inv_w[j] = &inv_w[j];
      quads.perspective[j] = (trial + j) % 3 != 0;
    }
    alignas(64) float ox[kVaryingLanes], oy[kVaryingLanes];
    for (int l = 0; l < kVaryingLanes; ++l) ox[l] = offset(random), oy[l] = offset(random);
    for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
      alignas(64) float out[10][kVaryingLanes], w[kVaryingLanes];
      select_quad_varying_interpolator(path)(quads, count, ox, oy, out, w);
      for (int q = 0; q < 4; ++q) {
        const F4 qx = load4(&ox[4 * q]), qy = load4(&oy[4 * q]);
        const F4 quad_w = eval_plane(inv_w[q], qx, qy);
        const F4 inv = 1.f / quad_w;
        float expected_w[4];
        store4(expected_w, quad_w);
        ASSERT_EQ(std::memcmp(&w[4 * q], expected_w, sizeof expected_w), 0) << trial << " " << q;
        for (int v = 0; v < count; ++v) {
          F4 f = eval_plane(planes[q][v], qx, qy);
          if (quads.perspective[q]) f *= inv;
          float expected[4];
          store4(expected, f);
          ASSERT_EQ(std::memcmp(&out[v][4 * q], expected, sizeof expected), 0)
              << trial << " " << v << " " << q << " path " << static_cast<int>(path);
        }
      }
    }
  }
}

}  // namespace
}  // namespace pineda::raster
