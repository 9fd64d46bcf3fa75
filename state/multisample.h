// GL 1.3 multisample state (ARB_multisample). It lives in the draw snapshot
// (raster::MultisampleState, Context::multisample refers to it) and changes fragments only in
// multisampled framebuffers (SAMPLE_BUFFERS 1), as GL 1.5 section 3.2.1 says.
#pragma once
#include <GL/gl.h>

#include "raster/draw_state.h"
#include "state/get_values.h"

namespace pineda {

struct AttribFrame;

using MultisampleState = raster::MultisampleState;

// The enable flag of `cap`, or null when it is not a multisample capability.
bool* multisample_capability(Context& ctx, GLenum cap);
bool query_multisample(Context& ctx, unsigned pname, GetValues& out);
// glPopAttrib: MULTISAMPLE_BIT restores all of it, ENABLE_BIT the four enables.
void restore_multisample(Context& ctx, const AttribFrame& frame);

}  // namespace pineda
