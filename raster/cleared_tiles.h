// Which tiles of a window's buffers still hold, uniformly, the value a clear wrote there: a
// clear of the same value skips them (a frame's glClear then touches only the tiles the last
// frame drew into). Only for buffers that nothing but the renderer writes (a window's back
// buffer, depth and stencil; never an application's OSMesa memory, a front buffer X may
// change, or a framebuffer object's storage, which texture uploads write): every other writer
// flushes first, and Renderer::flush forgets what is known.
#pragma once
#include <cstdint>
#include <vector>

#include "raster/clear.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

// What one tile's buffers hold: for each buffer, whether all its pixels hold the value.
struct ClearedTile {
  bool color = false, depth = false, stencil = false;
  uint32_t rgba = 0;  // ClearRecord::rgba's four bytes
  uint32_t depth_value = 0;
  uint8_t stencil_value = 0;
};

class ClearedTiles {
 public:
  // Sized for `tiles` tiles; a new size knows nothing. Called before the tiles run.
  void prepare(size_t tiles) {
    if (tiles_.size() != tiles) tiles_.assign(tiles, {});
  }
  void forget() { tiles_.assign(tiles_.size(), {}); }
  ClearedTile& tile(size_t i) { return tiles_[i]; }

 private:
  std::vector<ClearedTile> tiles_;  // each tile's entry is touched only by the thread running it
};

// Takes the buffers whose part of `tile` already holds the clear's value out of `clear`, and
// records what the tile holds after the clear.
void skip_cleared_buffers(ClearRecord& clear, const PixelRect& tile, ClearedTile& known);

}  // namespace pineda::raster
