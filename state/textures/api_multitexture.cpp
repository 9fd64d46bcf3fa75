// Multitexture (GL 1.3, GL_ARB_multitexture): the active server and client texture units
// and per-unit current texture coordinates.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

// The unit index named by GL_TEXTUREi, or -1 when it is not one of the first `units`.
int unit_index(GLenum texture, int units = raster::kMaxTextureUnits) {
  if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + GLenum(units)) return -1;
  return int(texture - GL_TEXTURE0);
}

void set_multi_texcoord(Context& ctx, GLenum target, float s, float t, float r, float q) {
  const int unit = unit_index(target);
  if (unit < 0) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_TEXTUREi below GL_MAX_TEXTURE_COORDS");
  const float coords[4] = {s, t, r, q};
  std::copy(coords, coords + 4, ctx.texture_units[unit].current_texcoord);
}

}  // namespace

// Any texture image unit (MAX_COMBINED_TEXTURE_IMAGE_UNITS); OpenGL ES 1.1 has the
// fixed-function units only. Texture coordinate sets stay MAX_TEXTURE_COORDS.
void ActiveTexture(Context& ctx, GLenum texture) {
  const int unit = unit_index(texture, ctx.es1() ? raster::kMaxTextureUnits : raster::kMaxTextureImageUnits);
  if (unit < 0)
    return ctx.record_error(GL_INVALID_ENUM, "texture is not GL_TEXTUREi below the number of texture units");
  ctx.active_texture = GLuint(unit);
}
void ActiveTextureARB(Context& ctx, GLenum texture) { ActiveTexture(ctx, texture); }

void ClientActiveTexture(Context& ctx, GLenum texture) {
  const int unit = unit_index(texture);
  if (unit < 0) return ctx.record_error(GL_INVALID_ENUM, "texture is not GL_TEXTUREi below GL_MAX_TEXTURE_COORDS");
  ctx.client_active_texture = GLuint(unit);
}
void ClientActiveTextureARB(Context& ctx, GLenum texture) { ClientActiveTexture(ctx, texture); }

// glMultiTexCoord{1,2,3,4}{d,f,i,s}[v] and their ARB names.
#define PINEDA_MULTI_TEXCOORD_NAMED(T, suffix, ext)                                                        \
  void MultiTexCoord1##suffix##ext(Context& ctx, GLenum u, T s) { set_multi_texcoord(ctx, u, s, 0, 0, 1); } \
  void MultiTexCoord2##suffix##ext(Context& ctx, GLenum u, T s, T t) {                                    \
    set_multi_texcoord(ctx, u, s, t, 0, 1);                                                               \
  }                                                                                                       \
  void MultiTexCoord3##suffix##ext(Context& ctx, GLenum u, T s, T t, T r) {                               \
    set_multi_texcoord(ctx, u, s, t, r, 1);                                                               \
  }                                                                                                       \
  void MultiTexCoord4##suffix##ext(Context& ctx, GLenum u, T s, T t, T r, T q) {                          \
    set_multi_texcoord(ctx, u, s, t, r, q);                                                               \
  }                                                                                                       \
  void MultiTexCoord1##suffix##v##ext(Context& ctx, GLenum u, const T* v) {                               \
    if (v) set_multi_texcoord(ctx, u, v[0], 0, 0, 1);                                                     \
  }                                                                                                       \
  void MultiTexCoord2##suffix##v##ext(Context& ctx, GLenum u, const T* v) {                               \
    if (v) set_multi_texcoord(ctx, u, v[0], v[1], 0, 1);                                                  \
  }                                                                                                       \
  void MultiTexCoord3##suffix##v##ext(Context& ctx, GLenum u, const T* v) {                               \
    if (v) set_multi_texcoord(ctx, u, v[0], v[1], v[2], 1);                                               \
  }                                                                                                       \
  void MultiTexCoord4##suffix##v##ext(Context& ctx, GLenum u, const T* v) {                               \
    if (v) set_multi_texcoord(ctx, u, v[0], v[1], v[2], v[3]);                                            \
  }
#define PINEDA_MULTI_TEXCOORD(T, suffix)     \
  PINEDA_MULTI_TEXCOORD_NAMED(T, suffix, )   \
  PINEDA_MULTI_TEXCOORD_NAMED(T, suffix, ARB)
PINEDA_MULTI_TEXCOORD(GLdouble, d)
PINEDA_MULTI_TEXCOORD(GLfloat, f)
PINEDA_MULTI_TEXCOORD(GLint, i)
PINEDA_MULTI_TEXCOORD(GLshort, s)
#undef PINEDA_MULTI_TEXCOORD
#undef PINEDA_MULTI_TEXCOORD_NAMED

}  // namespace pineda::gl
