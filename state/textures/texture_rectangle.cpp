#include "state/textures/texture_rectangle.h"

#include "state/enum_translate.h"

namespace pineda {

TexParams default_tex_params(TexTarget kind) {
  TexParams p;
  if (kind != TexTarget::Rect) return p;
  p.wrap_s = p.wrap_t = p.wrap_r = GL_CLAMP_TO_EDGE;
  p.min_filter = GL_LINEAR;
  return p;
}

GlError rectangle_parameter_error(GLenum pname, GLfloat value) {
  const GLenum e = enum_from_float(value);
  switch (pname) {
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R:
      if (e == GL_REPEAT || e == GL_MIRRORED_REPEAT)
        return {GL_INVALID_ENUM, "a rectangle texture does not repeat: param is GL_REPEAT or GL_MIRRORED_REPEAT"};
      return GL_NO_ERROR;
    case GL_TEXTURE_MIN_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR)
        return {GL_INVALID_ENUM, "a rectangle texture has no mipmaps: param is not GL_NEAREST or GL_LINEAR"};
      return GL_NO_ERROR;
    case GL_TEXTURE_BASE_LEVEL:
      if (value > 0.f) return {GL_INVALID_OPERATION, "a rectangle texture's base level is 0"};
      return GL_NO_ERROR;
    default:
      return GL_NO_ERROR;
  }
}

}  // namespace pineda
