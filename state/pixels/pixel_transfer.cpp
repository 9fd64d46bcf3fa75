#include "state/pixels/pixel_transfer.h"

#include <algorithm>
#include <cmath>

namespace pineda {
namespace {

float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }

// GL: a colour c in [0, 1] looks up entry round(c * (size - 1)).
float lookup_color(const std::vector<float>& table, float c) {
  const int last = static_cast<int>(table.size()) - 1;
  const int i = static_cast<int>(std::lround(clamp01(c) * static_cast<float>(last)));
  return table[std::clamp(i, 0, last)];
}

// GL: an index looks up entry (index & (size - 1)); index maps have power-of-two sizes.
float lookup_index(const std::vector<float>& table, int64_t index) {
  return table[static_cast<size_t>(index) & (table.size() - 1)];
}

// In 64-bit two's complement arithmetic: an index shifted far left wraps (GL leaves what
// overflow gives unspecified) instead of overflowing a signed integer.
int64_t shift_and_offset(const PixelMode& mode, int64_t index) {
  const int shift = std::clamp(mode.index_shift, -62, 62);
  const uint64_t shifted = shift >= 0 ? uint64_t(index) << shift : uint64_t(index >> -shift);
  return int64_t(shifted + uint64_t(int64_t{mode.index_offset}));
}

}  // namespace

void transfer_color(const PixelMode& mode, const PixelMaps& maps, float rgba[4]) {
  for (int c = 0; c < 4; ++c) rgba[c] = rgba[c] * mode.scale[c] + mode.bias[c];
  if (mode.map_color)
    for (int c = 0; c < 4; ++c) rgba[c] = lookup_color(maps[GLenum(GL_PIXEL_MAP_R_TO_R + c)], rgba[c]);
  for (int c = 0; c < 4; ++c) rgba[c] = clamp01(rgba[c]);
}

bool color_transfer_is_identity(const PixelMode& mode) {
  if (mode.map_color) return false;
  for (int c = 0; c < 4; ++c)
    if (mode.scale[c] != 1.f || mode.bias[c] != 0.f) return false;
  return true;
}

double transfer_depth(const PixelMode& mode, double depth) {
  const double z = depth * mode.depth_scale + mode.depth_bias;
  return z > 0.0 ? (z < 1.0 ? z : 1.0) : 0.0;
}

int64_t transfer_stencil(const PixelMode& mode, const PixelMaps& maps, int64_t index) {
  index = shift_and_offset(mode, index);
  if (mode.map_stencil) index = static_cast<int64_t>(lookup_index(maps[GL_PIXEL_MAP_S_TO_S], index));
  return index;
}

void index_to_rgba(const PixelMode& mode, const PixelMaps& maps, int64_t index, float rgba[4]) {
  index = shift_and_offset(mode, index);
  for (int c = 0; c < 4; ++c) rgba[c] = clamp01(lookup_index(maps[GLenum(GL_PIXEL_MAP_I_TO_R + c)], index));
}

}  // namespace pineda
