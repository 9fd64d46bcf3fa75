#include "state/es2/es2_rules.h"

#include "state/context.h"

namespace pineda {
namespace {

bool known_format(GLenum format) {
  switch (format) {
    case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_RGB: case GL_RGBA:
    case GL_BGRA: case GL_DEPTH_COMPONENT: case GL_DEPTH_STENCIL:
      return true;
    default: return false;
  }
}

bool known_type(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT: case GL_UNSIGNED_INT:
    case GL_UNSIGNED_INT_24_8:
      return true;
    default: return false;
  }
}

bool valid_pair(GLenum format, GLenum type) {
  switch (format) {
    case GL_RGBA:
      return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT_4_4_4_4 || type == GL_UNSIGNED_SHORT_5_5_5_1;
    case GL_RGB: return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT_5_6_5;
    case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_BGRA: return type == GL_UNSIGNED_BYTE;
    case GL_DEPTH_COMPONENT: return type == GL_UNSIGNED_SHORT || type == GL_UNSIGNED_INT;
    case GL_DEPTH_STENCIL: return type == GL_UNSIGNED_INT_24_8;
    default: return false;
  }
}

}  // namespace

bool es2_capability(GLenum cap) {
  switch (cap) {
    case GL_BLEND: case GL_CULL_FACE: case GL_DEPTH_TEST: case GL_DITHER: case GL_POLYGON_OFFSET_FILL:
    case GL_SAMPLE_ALPHA_TO_COVERAGE: case GL_SAMPLE_COVERAGE: case GL_SCISSOR_TEST: case GL_STENCIL_TEST:
    case GL_DEBUG_OUTPUT: case GL_DEBUG_OUTPUT_SYNCHRONOUS:  // GL_KHR_debug
      return true;
    default: return false;
  }
}

bool es2_tex_sub_image_allowed(Context& ctx, GLenum format, GLenum type) {
  if (!known_format(format) || !known_type(type)) {
    ctx.record_error(GL_INVALID_ENUM, "format or type is not one OpenGL ES takes");
    return false;
  }
  if (!valid_pair(format, type)) {
    ctx.record_error(GL_INVALID_OPERATION, "format and type are not a combination of OpenGL ES table 3.4");
    return false;
  }
  return true;
}

bool es2_tex_image_allowed(Context& ctx, GLint internalformat, GLint border, GLenum format, GLenum type) {
  if (!known_format(format) || !known_type(type)) {
    ctx.record_error(GL_INVALID_ENUM, "format or type is not one OpenGL ES takes");
    return false;
  }
  if (border != 0) {
    ctx.record_error(GL_INVALID_VALUE, "border is not 0");
    return false;
  }
  // Also for the sized formats of later versions (Mesa's order; piglit's
  // oes_packed_depth_stencil-depth-stencil-texture_gles2 expects it for DEPTH24_STENCIL8).
  if (GLenum(internalformat) != format) {
    ctx.record_error(GL_INVALID_OPERATION, "internalformat differs from format (OpenGL ES 1.1 and 2.0 3.7.1)");
    return false;
  }
  if (!valid_pair(format, type)) {
    ctx.record_error(GL_INVALID_OPERATION, "format and type are not a combination of OpenGL ES table 3.4");
    return false;
  }
  return true;
}

GlError es2_read_pixels_error(GLenum format, GLenum type) {
  switch (format) {
    case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_RGB: case GL_RGBA: case GL_BGRA: break;
    default: return {GL_INVALID_ENUM, "format is not a pixel format of OpenGL ES 2.0"};
  }
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_5_5_5_1: break;
    default: return {GL_INVALID_ENUM, "type is not a pixel type of OpenGL ES 2.0"};
  }
  if (format != GL_RGBA || type != GL_UNSIGNED_BYTE)
    return {GL_INVALID_OPERATION, "format and type are not GL_RGBA and GL_UNSIGNED_BYTE"};
  return GL_NO_ERROR;
}

GLint es2_storage_format(GLint internalformat) { return internalformat == GL_BGRA ? GL_RGBA8 : internalformat; }

bool es2_tex_parameter_allowed(GLenum pname, GLenum value) {
  if (pname != GL_TEXTURE_WRAP_S && pname != GL_TEXTURE_WRAP_T) return true;
  return value == GL_REPEAT || value == GL_CLAMP_TO_EDGE || value == GL_MIRRORED_REPEAT;
}

bool es2_renderbuffer_format(GLenum internalformat) {
  switch (internalformat) {
    case GL_RGBA4: case GL_RGB5_A1: case GL_RGB565: case GL_DEPTH_COMPONENT16: case GL_STENCIL_INDEX8:
    case GL_RGB8: case GL_RGBA8: case GL_DEPTH_COMPONENT24: case GL_DEPTH24_STENCIL8:
      return true;
    default: return false;
  }
}

bool es2_copy_tex_image_format(GLenum internalformat) {
  switch (internalformat) {
    case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_RGB: case GL_RGBA: return true;
    default: return false;
  }
}

std::vector<uint8_t> es2_base_format_pixels(const uint8_t* rgba, size_t pixels, GLenum format) {
  std::vector<int> picks;  // the RGBA components kept, in order
  switch (format) {
    case GL_RGB: picks = {0, 1, 2}; break;
    case GL_LUMINANCE_ALPHA: picks = {0, 3}; break;
    case GL_LUMINANCE: picks = {0}; break;
    case GL_ALPHA: picks = {3}; break;
    default: return std::vector<uint8_t>(rgba, rgba + pixels * 4);
  }
  std::vector<uint8_t> out;
  out.reserve(pixels * picks.size());
  for (size_t i = 0; i < pixels * 4; i += 4)
    for (int c : picks) out.push_back(rgba[i + size_t(c)]);
  return out;
}

}  // namespace pineda
