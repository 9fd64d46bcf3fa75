// The rules OpenGL ES 1.1 adds to glTexImage2D (ES 1.1 3.7.1): internalformat one of the five
// base formats (else GL_INVALID_VALUE), equal to format, a format/type pair of table 3.4, no
// border; what Mesa's ES 1.1 context records (checked side by side with llvmpipe).
#pragma once
#include <GL/gl.h>

namespace pineda {

class Context;

// False, with the error recorded, when the call breaks one of them.
bool es1_tex_image_allowed(Context& ctx, GLint internalformat, GLint border, GLenum format, GLenum type);

}  // namespace pineda
