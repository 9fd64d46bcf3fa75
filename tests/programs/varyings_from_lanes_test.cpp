// varyings_from_lanes and positions_from_lanes (state/programs/varyings_from_lanes.h): every
// vertex count of a batch (and varying counts around the 4x4 steps) give each vertex its own
// values, and nothing past the vertices or beside their positions is written.
#include "state/programs/varyings_from_lanes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace pineda {
namespace {

TEST(VaryingsFromLanes, EachVertexGetsItsOwnVaryings) {
  constexpr int kLanes = shader::kLanes;
  for (int nv = 0; nv <= 13; ++nv) {
    std::vector<float> lanes(static_cast<size_t>(nv) * kLanes);
    for (int k = 0; k < nv; ++k)
      for (int i = 0; i < kLanes; ++i) lanes[size_t(k) * kLanes + size_t(i)] = float(1000 * k + i);
    for (int vertices = 0; vertices <= kLanes; ++vertices) {
      std::vector<float> out(size_t(kLanes) * size_t(nv) + 1, -1.f);
      varyings_from_lanes(lanes.data(), vertices, nv, out.data());
      for (int i = 0; i < kLanes; ++i)
        for (int k = 0; k < nv; ++k)
          ASSERT_EQ(out[size_t(i) * size_t(nv) + size_t(k)], i < vertices ? float(1000 * k + i) : -1.f)
              << "nv " << nv << " vertices " << vertices << " vertex " << i << " varying " << k;
      ASSERT_EQ(out.back(), -1.f);
    }
  }
}

TEST(PositionsFromLanes, EachVertexGetsItsOwnPositionAndNothingElseChanges) {
  constexpr int kLanes = shader::kLanes;
  std::vector<float> lanes(4 * kLanes);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < kLanes; ++i) lanes[size_t(k) * kLanes + size_t(i)] = float(1000 * k + i);
  for (int vertices = 0; vertices <= kLanes; ++vertices) {
    std::vector<raster::ClipVertex> out(kLanes + 1);
    for (raster::ClipVertex& v : out) {
      std::fill(std::begin(v.clip), std::end(v.clip), -1.f);
      v.fog = -2.f;
    }
    positions_from_lanes(lanes.data(), vertices, out.data());
    for (int i = 0; i <= kLanes; ++i) {
      for (int k = 0; k < 4; ++k)
        ASSERT_EQ(out[size_t(i)].clip[k], i < vertices ? float(1000 * k + i) : -1.f)
            << "vertices " << vertices << " vertex " << i << " component " << k;
      ASSERT_EQ(out[size_t(i)].fog, -2.f);
    }
  }
}

}  // namespace
}  // namespace pineda
