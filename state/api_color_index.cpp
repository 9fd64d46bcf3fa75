// glIndex*, glClearIndex, glIndexMask and their glGet values (glIndexPointer: api_arrays.cpp).
#include "glapi/gl_entry_points.h"
#include "state/color_index.h"
#include "state/context.h"

namespace pineda {

bool query_color_index(Context& ctx, unsigned pname, GetValues& out) {
  const ColorIndexState& s = ctx.color_index;
  switch (pname) {
    case GL_CURRENT_INDEX: out = get_floats({s.current_index}); return true;
    case GL_INDEX_CLEAR_VALUE: out = get_floats({s.clear_index}); return true;
    case GL_INDEX_WRITEMASK: out = get_ints({double(s.write_mask)}); return true;
    default: return false;
  }
}

}  // namespace pineda

namespace pineda::gl {

// The index is a floating-point value: integer forms are converted, not normalized.
#define PINEDA_INDEX(T, suffix)                                                          \
  void Index##suffix(Context& ctx, T c) { ctx.color_index.current_index = static_cast<float>(c); } \
  void Index##suffix##v(Context& ctx, const T* c) {                                      \
    if (c) Index##suffix(ctx, *c);                                                       \
  }
PINEDA_INDEX(GLdouble, d)
PINEDA_INDEX(GLfloat, f)
PINEDA_INDEX(GLint, i)
PINEDA_INDEX(GLshort, s)
PINEDA_INDEX(GLubyte, ub)
#undef PINEDA_INDEX

void ClearIndex(Context& ctx, GLfloat c) { ctx.color_index.clear_index = c; }
void IndexMask(Context& ctx, GLuint mask) { ctx.color_index.write_mask = mask; }

}  // namespace pineda::gl
