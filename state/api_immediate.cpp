// Immediate mode: glBegin/glEnd and the current vertex attributes in every variant.
#include <algorithm>
#include <cstdint>

#include "glapi/gl_entry_points.h"
#include "state/color_material.h"
#include "state/component_convert.h"
#include "state/context.h"
#include "state/current_vertex.h"
#include "state/draw.h"
#include "state/programs/generic_attribs.h"
#include "state/enum_translate.h"

namespace pineda {

raster::VertexInput current_vertex(const Context& ctx, float x, float y, float z, float w) {
  raster::VertexInput v;
  v.position[0] = x;
  v.position[1] = y;
  v.position[2] = z;
  v.position[3] = w;
  std::copy(ctx.current_color, ctx.current_color + 4, v.color);
  std::copy(ctx.current_normal, ctx.current_normal + 3, v.normal);
  for (int u = 0; u < raster::kMaxTextureUnits; ++u)
    std::copy(ctx.texture_units[u].current_texcoord, ctx.texture_units[u].current_texcoord + 4, v.texcoord[u]);
  v.edge_flag = ctx.current_edge_flag;
  std::copy(ctx.extras.current_secondary_color, ctx.extras.current_secondary_color + 3, v.secondary_color);
  v.fog_coord = ctx.extras.current_fog_coord;
  return v;
}

}  // namespace pineda

namespace pineda::gl {
namespace {

// GL's conversion of integer colour and normal components to floating point.
inline float to_float(GLfloat v) { return v; }
inline float to_float(GLdouble v) { return static_cast<float>(v); }

void emit_vertex(Context& ctx, float x, float y, float z, float w) {
  if (!ctx.in_begin_end) return;  // outside Begin/End a vertex has no effect
  ctx.immediate.push_back(current_vertex(ctx, x, y, z, w));
  capture_immediate_generics(ctx, ctx.immediate.back());
}

void set_color(Context& ctx, float r, float g, float b, float a) {
  ctx.current_color[0] = r;
  ctx.current_color[1] = g;
  ctx.current_color[2] = b;
  ctx.current_color[3] = a;
  track_color_material(ctx);
}

void set_texcoord(Context& ctx, GLuint unit, float s, float t, float r, float q) {
  float* tc = ctx.texture_units[unit].current_texcoord;
  tc[0] = s;
  tc[1] = t;
  tc[2] = r;
  tc[3] = q;
}

}  // namespace

void Begin(Context& ctx, GLenum mode) {
  raster::Primitive p;
  if (!to_primitive(mode, p)) return ctx.record_error(GL_INVALID_ENUM, "mode is not a primitive type");
  if (!check_draw_framebuffer(ctx)) return;  // as Mesa: no primitive begins
  ctx.in_begin_end = true;
  ctx.begin_mode = mode;
  ctx.immediate.clear();
  ctx.immediate_materials.clear();
  ctx.programs.immediate_generic.clear();
}

void End(Context& ctx) {
  if (!ctx.in_begin_end) return ctx.record_error(GL_INVALID_OPERATION, "called outside glBegin and glEnd");
  ctx.in_begin_end = false;
  draw_vertices(ctx, ctx.begin_mode, ctx.immediate, {}, ctx.immediate_materials, AttribSource::Immediate);
  ctx.immediate.clear();
  ctx.immediate_materials.clear();
  ctx.programs.immediate_generic.clear();
}

// Vertex: 2, 3, 4 components; d f i s; scalar and vector forms.
#define PINEDA_VERTEX(T, suffix)                                                             \
  void Vertex2##suffix(Context& ctx, T x, T y) { emit_vertex(ctx, x, y, 0.f, 1.f); }         \
  void Vertex3##suffix(Context& ctx, T x, T y, T z) { emit_vertex(ctx, x, y, z, 1.f); }      \
  void Vertex4##suffix(Context& ctx, T x, T y, T z, T w) { emit_vertex(ctx, x, y, z, w); }   \
  void Vertex2##suffix##v(Context& ctx, const T* v) {                                        \
    if (v) emit_vertex(ctx, v[0], v[1], 0.f, 1.f);                                           \
  }                                                                                          \
  void Vertex3##suffix##v(Context& ctx, const T* v) {                                        \
    if (v) emit_vertex(ctx, v[0], v[1], v[2], 1.f);                                          \
  }                                                                                          \
  void Vertex4##suffix##v(Context& ctx, const T* v) {                                        \
    if (v) emit_vertex(ctx, v[0], v[1], v[2], v[3]);                                         \
  }
PINEDA_VERTEX(GLdouble, d)
PINEDA_VERTEX(GLfloat, f)
PINEDA_VERTEX(GLint, i)
PINEDA_VERTEX(GLshort, s)
#undef PINEDA_VERTEX

// Colour: 3 and 4 components of every type; integer types are normalized.
#define PINEDA_COLOR(T, suffix)                                                                    \
  void Color3##suffix(Context& ctx, T r, T g, T b) { set_color(ctx, norm(r), norm(g), norm(b), 1.f); }  \
  void Color4##suffix(Context& ctx, T r, T g, T b, T a) {                                               \
    set_color(ctx, norm(r), norm(g), norm(b), norm(a));                                                 \
  }                                                                                                     \
  void Color3##suffix##v(Context& ctx, const T* v) {                                                    \
    if (v) set_color(ctx, norm(v[0]), norm(v[1]), norm(v[2]), 1.f);                                     \
  }                                                                                                     \
  void Color4##suffix##v(Context& ctx, const T* v) {                                                    \
    if (v) set_color(ctx, norm(v[0]), norm(v[1]), norm(v[2]), norm(v[3]));                              \
  }
PINEDA_COLOR(GLbyte, b)
PINEDA_COLOR(GLdouble, d)
PINEDA_COLOR(GLfloat, f)
PINEDA_COLOR(GLint, i)
PINEDA_COLOR(GLshort, s)
PINEDA_COLOR(GLubyte, ub)
PINEDA_COLOR(GLuint, ui)
PINEDA_COLOR(GLushort, us)
#undef PINEDA_COLOR

// Texture coordinates: 1 to 4 components, d f i s, for the active texture unit 0.
#define PINEDA_TEXCOORD(T, suffix)                                                                     \
  void TexCoord1##suffix(Context& ctx, T s) { set_texcoord(ctx, 0, s, 0.f, 0.f, 1.f); }                \
  void TexCoord2##suffix(Context& ctx, T s, T t) { set_texcoord(ctx, 0, s, t, 0.f, 1.f); }             \
  void TexCoord3##suffix(Context& ctx, T s, T t, T r) { set_texcoord(ctx, 0, s, t, r, 1.f); }          \
  void TexCoord4##suffix(Context& ctx, T s, T t, T r, T q) { set_texcoord(ctx, 0, s, t, r, q); }       \
  void TexCoord1##suffix##v(Context& ctx, const T* v) {                                                \
    if (v) set_texcoord(ctx, 0, v[0], 0.f, 0.f, 1.f);                                                  \
  }                                                                                                    \
  void TexCoord2##suffix##v(Context& ctx, const T* v) {                                                \
    if (v) set_texcoord(ctx, 0, v[0], v[1], 0.f, 1.f);                                                 \
  }                                                                                                    \
  void TexCoord3##suffix##v(Context& ctx, const T* v) {                                                \
    if (v) set_texcoord(ctx, 0, v[0], v[1], v[2], 1.f);                                                \
  }                                                                                                    \
  void TexCoord4##suffix##v(Context& ctx, const T* v) {                                                \
    if (v) set_texcoord(ctx, 0, v[0], v[1], v[2], v[3]);                                               \
  }
PINEDA_TEXCOORD(GLdouble, d)
PINEDA_TEXCOORD(GLfloat, f)
PINEDA_TEXCOORD(GLint, i)
PINEDA_TEXCOORD(GLshort, s)
#undef PINEDA_TEXCOORD

// Normals: signed integer types are normalized.
#define PINEDA_NORMAL(T, suffix)                                                    \
  void Normal3##suffix(Context& ctx, T x, T y, T z) {                               \
    ctx.current_normal[0] = norm(x);                                                \
    ctx.current_normal[1] = norm(y);                                                \
    ctx.current_normal[2] = norm(z);                                                \
  }                                                                                 \
  void Normal3##suffix##v(Context& ctx, const T* v) {                               \
    if (v) Normal3##suffix(ctx, v[0], v[1], v[2]);                                  \
  }
PINEDA_NORMAL(GLbyte, b)
PINEDA_NORMAL(GLdouble, d)
PINEDA_NORMAL(GLfloat, f)
PINEDA_NORMAL(GLint, i)
PINEDA_NORMAL(GLshort, s)
#undef PINEDA_NORMAL

void EdgeFlag(Context& ctx, GLboolean flag) { ctx.current_edge_flag = flag != GL_FALSE; }
void EdgeFlagv(Context& ctx, const GLboolean* flag) {
  if (flag) ctx.current_edge_flag = *flag != GL_FALSE;
}

// glRect: the polygon (x1,y1) (x2,y1) (x2,y2) (x1,y2) at z = 0.
#define PINEDA_RECT(T, suffix)                                                        \
  void Rect##suffix(Context& ctx, T x1, T y1, T x2, T y2) {                           \
    Begin(ctx, GL_POLYGON);                                                           \
    emit_vertex(ctx, x1, y1, 0.f, 1.f);                                               \
    emit_vertex(ctx, x2, y1, 0.f, 1.f);                                               \
    emit_vertex(ctx, x2, y2, 0.f, 1.f);                                               \
    emit_vertex(ctx, x1, y2, 0.f, 1.f);                                               \
    End(ctx);                                                                         \
  }                                                                                   \
  void Rect##suffix##v(Context& ctx, const T* v1, const T* v2) {                      \
    if (v1 && v2) Rect##suffix(ctx, v1[0], v1[1], v2[0], v2[1]);                       \
  }
PINEDA_RECT(GLdouble, d)
PINEDA_RECT(GLfloat, f)
PINEDA_RECT(GLint, i)
PINEDA_RECT(GLshort, s)
#undef PINEDA_RECT

}  // namespace pineda::gl
