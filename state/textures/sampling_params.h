// The sampling parameters: the part of a texture's parameters that a sampler object
// (GL_ARB_sampler_objects) holds too, set and read by glTexParameter and glSamplerParameter
// alike: filters, wrap modes, border colour, level-of-detail range and bias, depth comparison,
// sRGB decoding (EXT_texture_sRGB_decode).
#pragma once
#include <GL/gl.h>

#include "state/gl_error.h"
#include "state/textures/texture_object.h"

namespace pineda {

bool is_sampling_param(GLenum pname);

// Sets sampling parameter `pname` (is_sampling_param) of `p` from v (v[0], or four values for
// the border colour); returns the error the spec names for a bad value.
GlError set_sampling_param(TexParams& p, GLenum pname, const GLfloat* v);

// The values of sampling parameter `pname`; `colour` tells whether integer queries map them
// as colours. False for any other pname.
bool get_sampling_param(const TexParams& p, GLenum pname, float out[4], int& count, bool& colour);

// `texture`'s parameters with the sampling ones of `sampler`.
TexParams with_sampling_params(const TexParams& texture, const TexParams& sampler);

}  // namespace pineda
