// The GLfixed forms of the single-value state calls and the current vertex attributes
// (OpenGL ES 1.1, OES_fixed_point): converted to float and passed to the float forms.
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/es1/fixed.h"

namespace pineda::gl {
using es1::from_fixed;

void AlphaFuncx(Context& ctx, GLenum func, GLfixed ref) { AlphaFunc(ctx, func, from_fixed(ref)); }

void ClearColorx(Context& ctx, GLfixed r, GLfixed g, GLfixed b, GLfixed a) {
  ClearColor(ctx, from_fixed(r), from_fixed(g), from_fixed(b), from_fixed(a));
}

void Color4x(Context& ctx, GLfixed r, GLfixed g, GLfixed b, GLfixed a) {
  Color4f(ctx, from_fixed(r), from_fixed(g), from_fixed(b), from_fixed(a));
}

void Normal3x(Context& ctx, GLfixed x, GLfixed y, GLfixed z) {
  Normal3f(ctx, from_fixed(x), from_fixed(y), from_fixed(z));
}

void MultiTexCoord4x(Context& ctx, GLenum target, GLfixed s, GLfixed t, GLfixed r, GLfixed q) {
  MultiTexCoord4f(ctx, target, from_fixed(s), from_fixed(t), from_fixed(r), from_fixed(q));
}

void LineWidthx(Context& ctx, GLfixed width) { LineWidth(ctx, from_fixed(width)); }

void PointSizex(Context& ctx, GLfixed size) { PointSize(ctx, from_fixed(size)); }

void PolygonOffsetx(Context& ctx, GLfixed factor, GLfixed units) {
  PolygonOffset(ctx, from_fixed(factor), from_fixed(units));
}

void SampleCoveragex(Context& ctx, GLclampx value, GLboolean invert) {
  SampleCoverage(ctx, from_fixed(value), invert);
}

}  // namespace pineda::gl
