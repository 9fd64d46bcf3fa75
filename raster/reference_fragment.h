// The reference mode's fragment stage (PINEDA_REFERENCE=1): one 2x2 quad at a time, scalar,
// every value computed per pixel from exact (double) attributes; no specialised routines.
// It applies the same operations as the fast pipeline (fragment_ops.h, the sampler, the
// texture environment; colour sum and fog in double) in GL's order, and blends in double
// precision without first rounding the source to the colour buffer's precision.
#pragma once
#include <cstdint>

#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

// Pixel i of the quad is (x + (i & 1), y + (i >> 1)); pixels outside `mask` are helpers
// (their attributes still feed the texture level of detail).
struct ReferenceQuad {
  int x = 0, y = 0;
  unsigned mask = 0;
  double z[4] = {};                  // window depth in depth-buffer units, before clamping
  double attr[kMaxPlanes][4] = {};   // r, g, b, a, then the texture planes (DrawRecord::tex_plane)
  double coverage[4] = {1, 1, 1, 1};  // of an antialiased point or line, multiplied into alpha
};

// Returns the pixels that passed every test up to depth.
uint32_t reference_shade_quad(const DrawRecord& d, bool back_facing, const float flat_color[4], const Framebuffer& fb,
                              const ReferenceQuad& quad);

}  // namespace pineda::raster
