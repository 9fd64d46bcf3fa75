// The argument checks of glTexImage*D and glTexSubImage*D that depend on no state, shared by
// the calls and by their display-list compilation, which copies client pixels only for a call
// that can read them.
#pragma once
#include <GL/gl.h>

#include "state/gl_error.h"
#include "state/textures/texture_format.h"
#include "state/textures/texture_target.h"

namespace pineda {

// The error of a glTexImage*D whose images have `dims` dimensions (height and depth are 1
// where the target has no such dimension), in the calls' order; GL_NO_ERROR when the image is
// defined (for a proxy target: when the proxy level is set, fitting or not).
GlError tex_image_error(GLenum target, int dims, GLint level, GLint internal_format, GLsizei width, GLsizei height,
                       GLsizei depth, GLint border, GLenum format, GLenum type);

// GL 3.3 3.8.3: depth or depth-stencil data (DEPTH_COMPONENT, DEPTH_STENCIL) only for depth or
// depth-stencil formats and the other way round, either for either (a depth format takes the
// depth of DEPTH_STENCIL data; a DEPTH_STENCIL format takes DEPTH_COMPONENT data into its depth,
// as Mesa's texture_formats_agree); depth formats on 1D, 2D and rectangle textures only (Mesa's
// INVALID_OPERATION for both).
bool depth_use_allowed(const TextureFormat& storage, TexTarget kind, GLenum format);

// False when a glTexSubImage*D with these arguments fails whatever texture is bound: then it
// reads no pixels. True does not mean it succeeds.
bool tex_sub_image_may_read(GLenum target, int dims, GLint level, GLsizei width, GLsizei height, GLsizei depth,
                            GLenum format, GLenum type);

}  // namespace pineda
