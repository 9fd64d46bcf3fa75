#pragma once
#include "state/get_values.h"

namespace pineda {

// FRAMEBUFFER_BINDING, READ_FRAMEBUFFER_BINDING, RENDERBUFFER_BINDING, MAX_RENDERBUFFER_SIZE,
// MAX_COLOR_ATTACHMENTS, MAX_SAMPLES.
bool query_framebuffers(Context& ctx, unsigned pname, GetValues& out);

}  // namespace pineda
