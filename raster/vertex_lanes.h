// Vertices in lanes: the fixed-function vertex stage works on batches of up to kVertexLanes
// vertices, one array per component, so that each step is a loop the compiler turns into
// vector instructions. Every step does per lane exactly the float operations, in the order,
// that the GLM expressions of one vertex would (so the results are the same bits).
#pragma once

namespace pineda::raster {

constexpr int kVertexLanes = 16;

using Lanes = float[kVertexLanes];

struct LaneVec3 {
  Lanes x, y, z;
};

struct LaneVec4 {
  Lanes x, y, z, w;
};

}  // namespace pineda::raster
