// The matrix stacks: modelview, projection and one texture stack per unit.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

// Null, with GL_INVALID_OPERATION, for the texture stack of a texture image unit past
// MAX_TEXTURE_COORDS: it has none (GL 2.0 2.11.2).
MatrixStack* current_stack(Context& ctx) {
  switch (ctx.matrix_mode) {
    case GL_PROJECTION: return &ctx.projection;
    case GL_TEXTURE:
      if (ctx.active_texture >= raster::kMaxTextureUnits) {
        ctx.record_error(GL_INVALID_OPERATION, "the active texture unit is above GL_MAX_TEXTURE_UNITS");
        return nullptr;
      }
      return &ctx.texture_matrix[ctx.active_texture];
    default: return &ctx.modelview;
  }
}

void load(Context& ctx, const glm::dmat4& m) {
  if (MatrixStack* s = current_stack(ctx)) s->top() = m;
}

void multiply(Context& ctx, const glm::dmat4& m) {
  if (MatrixStack* s = current_stack(ctx)) s->top() = s->top() * m;
}

template <typename T>
glm::dmat4 from_column_major(const T* m) {
  glm::dmat4 r;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) r[c][row] = static_cast<double>(m[c * 4 + row]);
  return r;
}

void rotate(Context& ctx, double angle, double x, double y, double z) {
  const double len = std::sqrt(x * x + y * y + z * z);
  if (len == 0.0 || !std::isfinite(len)) return;  // GL leaves a zero axis undefined: no change
  multiply(ctx, glm::rotate(glm::dmat4(1.0), glm::radians(angle), glm::dvec3(x, y, z) / len));
}

}  // namespace

void MatrixMode(Context& ctx, GLenum mode) {
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_MODELVIEW, GL_PROJECTION or GL_TEXTURE");
  ctx.matrix_mode = mode;
}

void LoadIdentity(Context& ctx) { load(ctx, glm::dmat4(1.0)); }
void LoadMatrixf(Context& ctx, const GLfloat* m) {
  if (m) load(ctx, from_column_major(m));
}
void LoadMatrixd(Context& ctx, const GLdouble* m) {
  if (m) load(ctx, from_column_major(m));
}
void MultMatrixf(Context& ctx, const GLfloat* m) {
  if (m) multiply(ctx, from_column_major(m));
}
void MultMatrixd(Context& ctx, const GLdouble* m) {
  if (m) multiply(ctx, from_column_major(m));
}

// GL 1.3 (ARB_transpose_matrix): the same matrices given row by row.
void LoadTransposeMatrixf(Context& ctx, const GLfloat* m) {
  if (m) load(ctx, glm::transpose(from_column_major(m)));
}
void LoadTransposeMatrixd(Context& ctx, const GLdouble* m) {
  if (m) load(ctx, glm::transpose(from_column_major(m)));
}
void MultTransposeMatrixf(Context& ctx, const GLfloat* m) {
  if (m) multiply(ctx, glm::transpose(from_column_major(m)));
}
void MultTransposeMatrixd(Context& ctx, const GLdouble* m) {
  if (m) multiply(ctx, glm::transpose(from_column_major(m)));
}
void LoadTransposeMatrixfARB(Context& ctx, const GLfloat* m) { LoadTransposeMatrixf(ctx, m); }
void LoadTransposeMatrixdARB(Context& ctx, const GLdouble* m) { LoadTransposeMatrixd(ctx, m); }
void MultTransposeMatrixfARB(Context& ctx, const GLfloat* m) { MultTransposeMatrixf(ctx, m); }
void MultTransposeMatrixdARB(Context& ctx, const GLdouble* m) { MultTransposeMatrixd(ctx, m); }

void PushMatrix(Context& ctx) {
  MatrixStack* s = current_stack(ctx);
  if (!s) return;
  if (s->stack.size() >= s->max_depth) return ctx.record_error(GL_STACK_OVERFLOW, "the current matrix stack is full");
  s->stack.push_back(s->top());
}

void PopMatrix(Context& ctx) {
  MatrixStack* s = current_stack(ctx);
  if (!s) return;
  if (s->stack.size() <= 1) return ctx.record_error(GL_STACK_UNDERFLOW, "the current matrix stack has one matrix only");
  s->stack.pop_back();
}

void Rotated(Context& ctx, GLdouble angle, GLdouble x, GLdouble y, GLdouble z) { rotate(ctx, angle, x, y, z); }
void Rotatef(Context& ctx, GLfloat angle, GLfloat x, GLfloat y, GLfloat z) { rotate(ctx, angle, x, y, z); }

void Translated(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  multiply(ctx, glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z)));
}
void Translatef(Context& ctx, GLfloat x, GLfloat y, GLfloat z) { Translated(ctx, x, y, z); }

void Scaled(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  multiply(ctx, glm::scale(glm::dmat4(1.0), glm::dvec3(x, y, z)));
}
void Scalef(Context& ctx, GLfloat x, GLfloat y, GLfloat z) { Scaled(ctx, x, y, z); }

void Frustum(Context& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  if (n <= 0.0 || f <= 0.0) return ctx.record_error(GL_INVALID_VALUE, "nearVal or farVal is not positive");
  if (l == r || b == t || n == f)
    return ctx.record_error(GL_INVALID_VALUE, "left equals right, bottom equals top or nearVal equals farVal");
  multiply(ctx, glm::frustum(l, r, b, t, n, f));
}

void Ortho(Context& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  if (l == r || b == t || n == f)
    return ctx.record_error(GL_INVALID_VALUE, "left equals right, bottom equals top or nearVal equals farVal");
  multiply(ctx, glm::ortho(l, r, b, t, n, f));
}

}  // namespace pineda::gl
