// glClipPlane / glGetClipPlane: user clip planes, kept in eye coordinates.
#include <glm/gtc/matrix_inverse.hpp>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

bool plane_index(Context& ctx, GLenum plane, int& index) {
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + raster::kMaxClipPlanes) {
    ctx.record_error(GL_INVALID_ENUM, "plane is not GL_CLIP_PLANEi");
    return false;
  }
  index = static_cast<int>(plane - GL_CLIP_PLANE0);
  return true;
}

}  // namespace

void ClipPlane(Context& ctx, GLenum plane, const GLdouble* equation) {
  int i = 0;
  if (!plane_index(ctx, plane, i) || !equation) return;
  // GL 1.5 section 2.12: (p1 p2 p3 p4) M^-1, M the modelview at the time of the call.
  const glm::dvec4 p(equation[0], equation[1], equation[2], equation[3]);
  ctx.extras.clip_planes[i] = glm::transpose(glm::inverse(ctx.modelview.top())) * p;
}

void GetClipPlane(Context& ctx, GLenum plane, GLdouble* equation) {
  int i = 0;
  if (!plane_index(ctx, plane, i) || !equation) return;
  for (int c = 0; c < 4; ++c) equation[c] = ctx.extras.clip_planes[i][c];
}

}  // namespace pineda::gl
