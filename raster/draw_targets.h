// Fixed-function draws and pixel rectangles into several colour buffers at once (a framebuffer
// object's glDrawBuffers): each draw buffer has a record of its own, specialized for its colour
// buffer's format, and one routine runs them one after the other on each quad row. Depth and
// stencil are restored between them, so every draw buffer sees the fragments the first one saw
// and the buffers end as after one pass. Fragment shaders write every draw buffer from one run
// instead (shade_program_target_quads). Single-target draws never reach this code: the choice
// is made once per draw.
#pragma once
#include "raster/draw_record.h"

namespace pineda::raster {

// Gives `draw` a record per draw buffer of `fb` (fb.color_targets > 1), each with its draw
// buffer's blend enable and colour mask (EXT_draw_buffers2), and the fixed-function routine
// that runs them (shader draws write the records' buffers from one run instead).
void prepare_target_draws(DrawRecord& draw, const Framebuffer& fb, SimdPath path);

}  // namespace pineda::raster
