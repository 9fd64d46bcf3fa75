// The current secondary colour (GL 1.4, EXT_secondary_color).
#include "glapi/gl_entry_points.h"
#include "state/component_convert.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

void set_secondary(Context& ctx, float r, float g, float b) {
  float* c = ctx.extras.current_secondary_color;
  c[0] = r;
  c[1] = g;
  c[2] = b;
  c[3] = 1.f;
}

}  // namespace

#define PINEDA_SECONDARY_COLOR(T, suffix, ext)                                                        \
  void SecondaryColor3##suffix##ext(Context& ctx, T r, T g, T b) {                                     \
    set_secondary(ctx, norm(r), norm(g), norm(b));                                                     \
  }                                                                                                    \
  void SecondaryColor3##suffix##v##ext(Context& ctx, const T* v) {                                     \
    if (v) set_secondary(ctx, norm(v[0]), norm(v[1]), norm(v[2]));                                     \
  }
#define PINEDA_SECONDARY_COLOR_BOTH(T, suffix) \
  PINEDA_SECONDARY_COLOR(T, suffix, )          \
  PINEDA_SECONDARY_COLOR(T, suffix, EXT)
PINEDA_SECONDARY_COLOR_BOTH(GLbyte, b)
PINEDA_SECONDARY_COLOR_BOTH(GLshort, s)
PINEDA_SECONDARY_COLOR_BOTH(GLint, i)
PINEDA_SECONDARY_COLOR_BOTH(GLfloat, f)
PINEDA_SECONDARY_COLOR_BOTH(GLdouble, d)
PINEDA_SECONDARY_COLOR_BOTH(GLubyte, ub)
PINEDA_SECONDARY_COLOR_BOTH(GLushort, us)
PINEDA_SECONDARY_COLOR_BOTH(GLuint, ui)
#undef PINEDA_SECONDARY_COLOR_BOTH
#undef PINEDA_SECONDARY_COLOR

}  // namespace pineda::gl
