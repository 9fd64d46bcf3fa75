// The rules OpenGL ES 2.0 adds to calls it shares with desktop GL: which capabilities exist,
// which texture and renderbuffer formats are taken (ES 2.0 3.7.1, 4.4.3, and the extensions
// of glapi/es2_extensions.txt).
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "state/gl_error.h"

namespace pineda {

class Context;

// glEnable/glDisable/glIsEnabled: ES 2.0 table 6.11's nine capabilities.
bool es2_capability(GLenum cap);

// glTexImage2D: false (error recorded) unless `internalformat` equals `format` (else
// INVALID_OPERATION, as Mesa, also for sized formats) and the pair
// format/type is one ES 2.0 lists (table 3.4, OES_depth_texture, OES_packed_depth_stencil,
// EXT_texture_format_BGRA8888); border must be 0. OpenGL ES 1.1 has the same rules, over the
// enums its context takes (es1_tex_image_allowed).
bool es2_tex_image_allowed(Context& ctx, GLint internalformat, GLint border, GLenum format, GLenum type);

// glTexSubImage2D: the same format/type pairs.
bool es2_tex_sub_image_allowed(Context& ctx, GLenum format, GLenum type);

// The desktop internal format that stores an ES 2.0 one (BGRA_EXT is kept as RGBA8).
GLint es2_storage_format(GLint internalformat);

// glTexParameter: ES 2.0 has REPEAT, CLAMP_TO_EDGE and MIRRORED_REPEAT only.
bool es2_tex_parameter_allowed(GLenum pname, GLenum value);

// glRenderbufferStorage: ES 2.0 4.4.3 (RGBA4, RGB5_A1, RGB565, DEPTH_COMPONENT16, STENCIL_INDEX8)
// plus OES_rgb8_rgba8, OES_depth24 and OES_packed_depth_stencil.
bool es2_renderbuffer_format(GLenum internalformat);

// glReadPixels (ES 2.0 4.3.1): RGBA/UNSIGNED_BYTE and the IMPLEMENTATION_COLOR_READ pair,
// which is the same one here; other pairs of table 3.4 INVALID_OPERATION, others INVALID_ENUM.
GlError es2_read_pixels_error(GLenum format, GLenum type);

// glCopyTexImage2D: the five base formats.
bool es2_copy_tex_image_format(GLenum internalformat);

// RGBA8 pixels reduced to the components of base format `format` (RGBA, RGB, LUMINANCE_ALPHA,
// LUMINANCE: R, ALPHA), one byte each.
std::vector<uint8_t> es2_base_format_pixels(const uint8_t* rgba, size_t pixels, GLenum format);

}  // namespace pineda
