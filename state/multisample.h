// GL 1.3 multisample state (ARB_multisample). Pineda's framebuffers are single-sampled
// (SAMPLE_BUFFERS is 0), so by GL 1.5 section 3.2.1 multisample rasterization is never on and
// this state changes no fragment: it is kept for glGet, glIsEnabled and the attribute stack.
#pragma once
#include <GL/gl.h>

#include "state/get_values.h"

namespace pineda {

struct AttribFrame;

struct MultisampleState {
  bool multisample = true;  // GL_MULTISAMPLE
  bool alpha_to_coverage = false, alpha_to_one = false, sample_coverage = false;
  float coverage_value = 1.f;
  bool coverage_invert = false;
};

// The enable flag of `cap`, or null when it is not a multisample capability.
bool* multisample_capability(Context& ctx, GLenum cap);
bool query_multisample(Context& ctx, unsigned pname, GetValues& out);
// glPopAttrib: MULTISAMPLE_BIT restores all of it, ENABLE_BIT the four enables.
void restore_multisample(Context& ctx, const AttribFrame& frame);

}  // namespace pineda
