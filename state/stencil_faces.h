// GL 2.0 separate stencil state. The front face's GL values are Context::stencil_func,
// stencil_value_mask... (GL 1.x names); the back face's are these. Both faces' raster form is
// DrawState::stencil_front and stencil_back, which the rasterizer picks by facing.
#pragma once
#include <GL/gl.h>

#include "state/get_values.h"

namespace pineda {

// The back face's stencil state as the application set it (enums and full-width masks), for
// glGet and glPushAttrib.
struct StencilBackValues {
  GLenum func = GL_ALWAYS, fail = GL_KEEP, zfail = GL_KEEP, zpass = GL_KEEP;
  GLuint value_mask = ~0u, write_mask = ~0u;
};

// STENCIL_BACK_FUNC, _REF, _VALUE_MASK, _WRITEMASK, _FAIL, _PASS_DEPTH_FAIL, _PASS_DEPTH_PASS.
bool query_stencil_back(Context& ctx, unsigned pname, GetValues& out);

}  // namespace pineda
