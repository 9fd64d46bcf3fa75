// Colour-index state (GL 1.1 sections 2.7, 4.2.2, 4.2.3). Pineda's visuals are RGBA only, so
// this state is kept, queried, listed and pushed as the spec says but never affects rendering.
#pragma once
#include <GL/gl.h>

#include "state/get_values.h"

namespace pineda {

struct ColorIndexState {
  float current_index = 1.f;  // GL_CURRENT_INDEX (CURRENT_BIT)
  float clear_index = 0.f;    // GL_INDEX_CLEAR_VALUE (COLOR_BUFFER_BIT)
  GLuint write_mask = ~0u;    // GL_INDEX_WRITEMASK (COLOR_BUFFER_BIT)
};

// glGet* of the values above (api_color_index.cpp).
bool query_color_index(Context& ctx, unsigned pname, GetValues& out);

}  // namespace pineda
