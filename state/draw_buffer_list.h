// GL 2.0 / ARB_draw_buffers: the colour buffer each fragment colour output is written to.
// DRAW_BUFFER0 is Context::draw_buffer (glDrawBuffer's); the others are Context::
// extra_draw_buffers, GL_NONE unless glDrawBuffers set them.
#pragma once
#include <GL/gl.h>

#include <array>

#include "shader/program.h"
#include "state/get_values.h"

namespace pineda {

using shader::kMaxDrawBuffers;  // the fragment colour outputs a shader writes

using ExtraDrawBuffers = std::array<GLenum, kMaxDrawBuffers - 1>;  // DRAW_BUFFER1..

// MAX_DRAW_BUFFERS and DRAW_BUFFERi.
bool query_draw_buffers(Context& ctx, unsigned pname, GetValues& out);

// Selects n (validated) draw buffers, the others NONE, and points the renderer at them.
void set_draw_buffers(Context& ctx, int n, const GLenum* bufs);

}  // namespace pineda
