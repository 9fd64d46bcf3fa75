// The implementation limits Pineda reports through glGet.
#pragma once

namespace pineda {

constexpr int kMaxViewportDim = 16384;
constexpr int kMaxTextureSize = 8192;
constexpr int kMax3DTextureSize = 256;
constexpr int kMaxCubeMapTextureSize = 4096;
constexpr int kMaxRectangleTextureSize = 8192;
constexpr int kMaxModelviewStackDepth = 32;
constexpr int kMaxProjectionStackDepth = 10;
constexpr int kMaxTextureStackDepth = 10;
constexpr float kPointSizeRange[2] = {1.f, 255.f};
constexpr float kLineWidthRange[2] = {1.f, 255.f};
constexpr float kSmoothSizeGranularity = 1.f / 256.f;  // raster::kSubpixelOne
constexpr int kSubpixelBits = 8;
// glDrawRangeElements' recommended maximums (GL 1.2): Pineda has no limit; Mesa's values.
constexpr int kMaxElementsVertices = 3000;
constexpr int kMaxElementsIndices = 3000;

}  // namespace pineda
