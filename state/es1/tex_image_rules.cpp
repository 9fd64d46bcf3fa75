#include "state/es1/tex_image_rules.h"

#include "state/context.h"
#include "state/es2/es2_rules.h"

namespace pineda {

bool es1_tex_image_allowed(Context& ctx, GLint internalformat, GLint border, GLenum format, GLenum type) {
  switch (internalformat) {
    case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_RGB: case GL_RGBA: break;
    default:
      ctx.record_error(GL_INVALID_VALUE, "internalformat is not GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_RGB or GL_RGBA");
      return false;
  }
  return es2_tex_image_allowed(ctx, internalformat, border, format, type);  // the rules ES 2.0 kept
}

}  // namespace pineda
