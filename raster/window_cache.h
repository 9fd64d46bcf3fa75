// The post-transform cache of fixed-function draws (GeometryStage::cached_window): the
// front-colour window vertex of a draw's vertex `index` in slot index & mask, usable when the
// vertex lies inside the clip volume (shared vertices of a mesh are taken to the window once,
// not once per triangle or line). One per renderer, kept from draw to draw: a slot belongs to
// the draw whose number it holds, so a new draw starts with no slot of its own and nothing to
// clear (per draw, clearing the slots of a 65-vertex line strip cost more than its lines). The
// slots lie in zeroed pages (a zero slot belongs to no draw), first touched only when used: a
// program's first draws of a few vertices touch a few of them, not all 1024 (176 KiB).
#pragma once
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "raster/setup.h"
#include "raster/zeroed_store.h"

namespace pineda::raster {

struct WindowSlot {
  uint64_t draw = 0;  // the draw the slot belongs to (0: none)
  size_t index = SIZE_MAX;
  bool usable = false;
  int8_t in_view = -1;  // inside the view volume (which lines are clipped to); -1: not known yet
  WinVert window;
};

class WindowCache {
 public:
  // A new draw of `vertex_count` vertices: up to kSlots slots, none of them its own yet.
  void begin_draw(size_t vertex_count) {
    ++draw_;
    mask_ = std::min(kSlots, std::bit_ceil(std::max<size_t>(vertex_count, 1))) - 1;
  }
  // Whether vertices i and j, different, take the same slot: the later one's window would
  // replace the earlier one's under a pointer still held to it.
  bool share_slot(size_t i, size_t j) const { return i != j && ((i ^ j) & mask_) == 0; }
  // The slot of vertex `index`; `fresh` when it held another vertex or draw (then it is the
  // caller's to fill: `index` and the draw are recorded, usable and in_view reset).
  WindowSlot& slot(size_t index, bool& fresh) {
    WindowSlot& s = slots_.grow(kSlots)[index & mask_];
    fresh = s.draw != draw_ || s.index != index;
    if (fresh) {
      s.draw = draw_;
      s.index = index;
      s.usable = false;
      s.in_view = -1;
    }
    return s;
  }

 private:
  static constexpr size_t kSlots = 1024;
  ZeroedStore<WindowSlot> slots_;
  uint64_t draw_ = 0;
  size_t mask_ = 0;
};

}  // namespace pineda::raster
