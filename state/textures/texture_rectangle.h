// ARB_texture_rectangle's rules for its target: one level, no repeating wrap modes, no mipmap
// filters, and the initial parameters that follow from them.
#pragma once
#include <GL/gl.h>

#include "state/gl_error.h"
#include "state/textures/texture_object.h"

namespace pineda {

// A new texture object's parameters for its first target: a rectangle's wrap modes are
// CLAMP_TO_EDGE and its minification filter LINEAR; the other targets start alike.
TexParams default_tex_params(TexTarget kind);

// The error glTexParameter gives for a rectangle texture's value that other targets accept:
// INVALID_ENUM for REPEAT and MIRRORED_REPEAT and for mipmap filters, INVALID_OPERATION for a
// positive base level (as Mesa; a negative one is the generic INVALID_VALUE). GL_NO_ERROR when
// the generic checks decide.
GlError rectangle_parameter_error(GLenum pname, GLfloat value);

}  // namespace pineda
