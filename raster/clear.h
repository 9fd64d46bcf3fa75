// A recorded glClear, applied tile by tile when the scene executes.
#pragma once
#include <array>
#include <cstdint>

#include "raster/draw_state.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

struct ClearRecord {
  PixelRect rect;  // framebuffer ∩ scissor
  bool color = false, depth = false, stencil = false;
  uint8_t rgba[4] = {0, 0, 0, 0};
  // Per colour buffer of the framebuffer (Framebuffer::target_color(i)): its draw buffer's mask.
  std::array<std::array<bool, 4>, kMaxColorTargets> color_write{};
  uint32_t depth_value = 0;
  uint8_t stencil_value = 0;
  uint8_t stencil_write_mask = 0xff;
};

// Converts the clear to buffer values; nothing to do when the result clears nothing.
bool make_clear_record(const ClearState& clear, const Framebuffer& fb, ClearRecord& out);

void apply_clear(const ClearRecord& clear, const Framebuffer& fb, const PixelRect& tile);

}  // namespace pineda::raster
