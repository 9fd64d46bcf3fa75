// OES_compressed_paletted_texture (core in OpenGL ES 1.1): glCompressedTexImage2D with one of the
// ten PALETTE{4,8}_* formats takes a palette followed by the indices of every mipmap level.
#pragma once
#include <GL/gl.h>

namespace pineda {

class Context;

// Whether `format` is one of the ten paletted formats.
bool paletted_format(GLenum format);

// The formats listed by GL_COMPRESSED_TEXTURE_FORMATS in an OpenGL ES 1.1 context.
inline constexpr int kPalettedFormatCount = 10;
GLenum paletted_format_at(int i);

// glCompressedTexImage2D of a paletted format: `level` is 0 or minus the last mipmap level that
// `data` holds. Each level is stored decoded, as Mesa does: RGB or RGBA of the palette's type.
void paletted_tex_image(Context& ctx, GLenum target, GLint level, GLenum format, GLsizei width, GLsizei height,
                        GLint border, GLsizei image_size, const void* data);

}  // namespace pineda
