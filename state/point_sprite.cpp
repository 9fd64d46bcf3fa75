#include "state/point_sprite.h"

#include <GL/glext.h>

#include <cmath>

#include "state/context.h"

namespace pineda {

void set_point_sprite_env(Context& ctx, GLenum pname, GLfloat value) {
  if (pname != GL_COORD_REPLACE) return ctx.record_error(GL_INVALID_ENUM, "pname is not GL_COORD_REPLACE");
  // The value is taken as an integer, as Mesa does (so 0.5 is FALSE); only TRUE and FALSE are
  // accepted.
  const float whole = std::trunc(value);
  if (whole != 0.f && whole != 1.f)
    return ctx.record_error(GL_INVALID_VALUE, "GL_COORD_REPLACE is not GL_TRUE or GL_FALSE");
  uint32_t& replace = ctx.draw_state.point_params.sprite.coord_replace;
  const uint32_t bit = 1u << ctx.active_texture;
  replace = whole == 1.f ? replace | bit : replace & ~bit;
}

bool get_point_sprite_env(Context& ctx, GLenum pname, GLfloat& value) {
  if (pname != GL_COORD_REPLACE) {
    ctx.record_error(GL_INVALID_ENUM, "pname is not GL_COORD_REPLACE");
    return false;
  }
  value = (ctx.draw_state.point_params.sprite.coord_replace >> ctx.active_texture & 1u) ? 1.f : 0.f;
  return true;
}

}  // namespace pineda
