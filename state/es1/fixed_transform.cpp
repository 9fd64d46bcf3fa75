// The GLfixed forms of the matrix, clip-plane and depth-range calls (OpenGL ES 1.1,
// OES_fixed_point): converted to float and passed to the float forms.
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/es1/fixed.h"

namespace pineda::gl {
using es1::from_fixed;

void Orthox(Context& ctx, GLfixed l, GLfixed r, GLfixed b, GLfixed t, GLfixed n, GLfixed f) {
  Orthof(ctx, from_fixed(l), from_fixed(r), from_fixed(b), from_fixed(t), from_fixed(n), from_fixed(f));
}

void Frustumx(Context& ctx, GLfixed l, GLfixed r, GLfixed b, GLfixed t, GLfixed n, GLfixed f) {
  Frustumf(ctx, from_fixed(l), from_fixed(r), from_fixed(b), from_fixed(t), from_fixed(n), from_fixed(f));
}

void Rotatex(Context& ctx, GLfixed angle, GLfixed x, GLfixed y, GLfixed z) {
  Rotatef(ctx, from_fixed(angle), from_fixed(x), from_fixed(y), from_fixed(z));
}

void Scalex(Context& ctx, GLfixed x, GLfixed y, GLfixed z) {
  Scalef(ctx, from_fixed(x), from_fixed(y), from_fixed(z));
}

void Translatex(Context& ctx, GLfixed x, GLfixed y, GLfixed z) {
  Translatef(ctx, from_fixed(x), from_fixed(y), from_fixed(z));
}

void LoadMatrixx(Context& ctx, const GLfixed* m) {
  if (!m) return LoadMatrixf(ctx, nullptr);
  GLfloat f[16];
  for (int i = 0; i < 16; ++i) f[i] = from_fixed(m[i]);
  LoadMatrixf(ctx, f);
}

void MultMatrixx(Context& ctx, const GLfixed* m) {
  if (!m) return MultMatrixf(ctx, nullptr);
  GLfloat f[16];
  for (int i = 0; i < 16; ++i) f[i] = from_fixed(m[i]);
  MultMatrixf(ctx, f);
}

void ClipPlanex(Context& ctx, GLenum plane, const GLfixed* equation) {
  if (!equation) return ClipPlanef(ctx, plane, nullptr);
  const GLfloat e[4] = {from_fixed(equation[0]), from_fixed(equation[1]), from_fixed(equation[2]),
                        from_fixed(equation[3])};
  ClipPlanef(ctx, plane, e);
}

void GetClipPlanex(Context& ctx, GLenum plane, GLfixed* equation) {
  GLfloat e[4] = {};
  const uint64_t errors = ctx.errors_recorded();
  GetClipPlanef(ctx, plane, e);
  if (!equation || ctx.errors_recorded() != errors) return;
  for (int i = 0; i < 4; ++i) equation[i] = es1::to_fixed(e[i]);
}

void DepthRangex(Context& ctx, GLfixed n, GLfixed f) { DepthRangef(ctx, from_fixed(n), from_fixed(f)); }

void ClearDepthx(Context& ctx, GLfixed depth) { ClearDepthf(ctx, from_fixed(depth)); }

}  // namespace pineda::gl
