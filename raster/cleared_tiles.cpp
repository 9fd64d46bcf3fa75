#include "raster/cleared_tiles.h"

#include <cstring>

namespace pineda::raster {

void skip_cleared_buffers(ClearRecord& clear, const PixelRect& tile, ClearedTile& known) {
  // A tile the clear covers wholly, with every bit of a buffer written, holds one value after it.
  const bool whole = clear.rect.x0 <= tile.x0 && clear.rect.y0 <= tile.y0 && clear.rect.x1 >= tile.x1 &&
                     clear.rect.y1 >= tile.y1;
  if (clear.color) {
    if (known.color && std::memcmp(known.rgba, clear.rgba, sizeof known.rgba) == 0) {
      clear.color = false;
    } else {
      const auto& mask = clear.color_write[0];
      known.color = whole && mask[0] && mask[1] && mask[2] && mask[3];
      std::memcpy(known.rgba, clear.rgba, sizeof known.rgba);
    }
  }
  if (clear.depth) {
    if (known.depth && known.depth_value == clear.depth_value) {
      clear.depth = false;
    } else {
      known.depth = whole;
      known.depth_value = clear.depth_value;
    }
  }
  if (clear.stencil) {
    if (known.stencil && known.stencil_value == clear.stencil_value) {
      clear.stencil = false;
    } else {
      known.stencil = whole && clear.stencil_write_mask == 0xff;
      known.stencil_value = clear.stencil_value;
    }
  }
}

}  // namespace pineda::raster
