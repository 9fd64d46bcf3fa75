// The single-precision forms OpenGL ES 1.1 has instead of GL's double ones
// (OES_single_precision): glOrthof, glFrustumf, glClipPlanef, glGetClipPlanef, glDepthRangef,
// glClearDepthf.
#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {

void Orthof(Context& ctx, GLfloat l, GLfloat r, GLfloat b, GLfloat t, GLfloat n, GLfloat f) {
  Ortho(ctx, l, r, b, t, n, f);
}

void Frustumf(Context& ctx, GLfloat l, GLfloat r, GLfloat b, GLfloat t, GLfloat n, GLfloat f) {
  Frustum(ctx, l, r, b, t, n, f);
}

void ClipPlanef(Context& ctx, GLenum plane, const GLfloat* equation) {
  if (!equation) return ClipPlane(ctx, plane, nullptr);
  const GLdouble e[4] = {equation[0], equation[1], equation[2], equation[3]};
  ClipPlane(ctx, plane, e);
}

void GetClipPlanef(Context& ctx, GLenum plane, GLfloat* equation) {
  GLdouble e[4] = {};
  const uint64_t errors = ctx.errors_recorded();
  GetClipPlane(ctx, plane, e);
  if (!equation || ctx.errors_recorded() != errors) return;
  for (int i = 0; i < 4; ++i) equation[i] = static_cast<GLfloat>(e[i]);
}

void DepthRangef(Context& ctx, GLfloat n, GLfloat f) { DepthRange(ctx, n, f); }

void ClearDepthf(Context& ctx, GLfloat depth) { ClearDepth(ctx, depth); }

}  // namespace pineda::gl
