#include "raster/cleared_tiles.h"

#include <cstring>

namespace pineda::raster {
namespace {

// One buffer: its clear left out where the tile already holds `value`; otherwise what the tile
// holds after it (`value` everywhere when `uniform_after`, not known otherwise).
template <typename T>
void skip_or_note(bool& clears, bool& known, T& known_value, T value, bool uniform_after) {
  if (!clears) return;
  if (known && known_value == value) {
    clears = false;
    return;
  }
  known = uniform_after;
  known_value = value;
}

}  // namespace

void skip_cleared_buffers(ClearRecord& clear, const PixelRect& tile, ClearedTile& known) {
  // A tile the clear covers wholly, with every bit of a buffer written, holds one value after it.
  const bool whole = clear.rect.x0 <= tile.x0 && clear.rect.y0 <= tile.y0 && clear.rect.x1 >= tile.x1 &&
                     clear.rect.y1 >= tile.y1;
  const auto& mask = clear.color_write[0];
  uint32_t rgba = 0;
  std::memcpy(&rgba, clear.rgba, sizeof rgba);
  skip_or_note(clear.color, known.color, known.rgba, rgba, whole && mask[0] && mask[1] && mask[2] && mask[3]);
  skip_or_note(clear.depth, known.depth, known.depth_value, clear.depth_value, whole);
  skip_or_note(clear.stencil, known.stencil, known.stencil_value, clear.stencil_value,
               whole && clear.stencil_write_mask == 0xff);
}

}  // namespace pineda::raster
