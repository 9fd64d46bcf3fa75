// glRasterPos (GL 1.5 spec 2.13) and glWindowPos (GL 1.4, GL_ARB_window_pos).
#include <algorithm>
#include <cmath>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/draw.h"

namespace pineda::gl {
namespace {

// The raster position is transformed like a vertex and becomes invalid when clipping would
// remove that vertex as a point.
void set_raster_pos(Context& ctx, double x, double y, double z, double w) {
  raster::VertexInput v;
  const double position[4] = {x, y, z, w};
  for (int i = 0; i < 4; ++i) v.position[i] = static_cast<float>(position[i]);
  std::copy(ctx.current_color, ctx.current_color + 4, v.color);
  std::copy(ctx.current_normal, ctx.current_normal + 3, v.normal);
  std::copy(ctx.extras.current_secondary_color, ctx.extras.current_secondary_color + 3, v.secondary_color);
  for (int u = 0; u < raster::kMaxTextureUnits; ++u)
    std::copy(ctx.texture_units[u].current_texcoord, ctx.texture_units[u].current_texcoord + 4, v.texcoord[u]);
  const raster::ClipVertex out = transform_single_vertex(ctx, v);
  RasterPosition& rp = ctx.raster_pos;
  const float* c = out.clip;
  rp.valid = std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3]) &&
             -c[3] <= c[0] && c[0] <= c[3] && -c[3] <= c[1] && c[1] <= c[3] && -c[3] <= c[2] && c[2] <= c[3] &&
             c[3] > 0.f;
  const glm::dvec4 eye = ctx.modelview.top() * glm::dvec4(x, y, z, w);
  for (int i = 0; i < raster::kMaxClipPlanes; ++i)  // GL 1.5 2.13: user clip planes too
    if (ctx.extras.clip_plane_enabled[i] && glm::dot(ctx.extras.clip_planes[i], eye) < 0.0) rp.valid = false;
  if (!rp.valid) return;
  const raster::Viewport& vp = ctx.viewport;
  const double xd = c[0] / double(c[3]), yd = c[1] / double(c[3]), zd = c[2] / double(c[3]);
  rp.window[0] = static_cast<float>(vp.x + (xd + 1.0) * 0.5 * vp.width);
  rp.window[1] = static_cast<float>(vp.y + (yd + 1.0) * 0.5 * vp.height);
  rp.window[2] = static_cast<float>((vp.far_z - vp.near_z) * 0.5 * zd + (vp.far_z + vp.near_z) * 0.5);
  rp.window[3] = c[3];
  std::copy(out.color, out.color + 4, rp.color);
  // Lit: the specular colour the lighting gives (0 unless separate specular); unlit: the current one.
  for (int i = 0; i < 4; ++i) rp.secondary_color[i] = std::clamp(ctx.extras.current_secondary_color[i], 0.f, 1.f);
  if (ctx.lighting.enabled) std::copy(out.secondary, out.secondary + 3, rp.secondary_color);
  for (int u = 0; u < raster::kMaxTextureUnits; ++u) std::copy(out.texcoord[u], out.texcoord[u] + 4, rp.texcoord[u]);
  rp.distance = ctx.extras.fog_coord_source == GL_FOG_COORDINATE ? ctx.extras.current_fog_coord
                                                                 : static_cast<float>(glm::length(glm::dvec3(eye)));
  raster_pos_select_hit(ctx);
}

// GL 1.4 2.13: x and y are window coordinates as given, z is clamped to [0, 1] and mapped
// to the depth range; the colour and texture coordinates are the current ones, unlit.
void set_window_pos(Context& ctx, double x, double y, double z) {
  RasterPosition& rp = ctx.raster_pos;
  const raster::Viewport& vp = ctx.viewport;
  rp.valid = true;
  rp.window[0] = static_cast<float>(x);
  rp.window[1] = static_cast<float>(y);
  rp.window[2] = static_cast<float>(vp.near_z + std::clamp(z, 0.0, 1.0) * (vp.far_z - vp.near_z));
  rp.window[3] = 1.f;
  for (int i = 0; i < 4; ++i) rp.color[i] = std::clamp(ctx.current_color[i], 0.f, 1.f);
  for (int i = 0; i < 4; ++i) rp.secondary_color[i] = std::clamp(ctx.extras.current_secondary_color[i], 0.f, 1.f);
  for (int u = 0; u < raster::kMaxTextureUnits; ++u)
    std::copy(ctx.texture_units[u].current_texcoord, ctx.texture_units[u].current_texcoord + 4, rp.texcoord[u]);
  rp.distance = ctx.extras.fog_coord_source == GL_FOG_COORDINATE ? ctx.extras.current_fog_coord : 0.f;
  raster_pos_select_hit(ctx);
}

}  // namespace

#define PINEDA_RASTER_POS(T, suffix)                                                             \
  void RasterPos2##suffix(Context& ctx, T x, T y) { set_raster_pos(ctx, x, y, 0, 1); }            \
  void RasterPos3##suffix(Context& ctx, T x, T y, T z) { set_raster_pos(ctx, x, y, z, 1); }       \
  void RasterPos4##suffix(Context& ctx, T x, T y, T z, T w) { set_raster_pos(ctx, x, y, z, w); }  \
  void RasterPos2##suffix##v(Context& ctx, const T* v) {                                         \
    if (v) set_raster_pos(ctx, v[0], v[1], 0, 1);                                                \
  }                                                                                              \
  void RasterPos3##suffix##v(Context& ctx, const T* v) {                                         \
    if (v) set_raster_pos(ctx, v[0], v[1], v[2], 1);                                             \
  }                                                                                              \
  void RasterPos4##suffix##v(Context& ctx, const T* v) {                                         \
    if (v) set_raster_pos(ctx, v[0], v[1], v[2], v[3]);                                          \
  }                                                                                              \
  void WindowPos2##suffix(Context& ctx, T x, T y) { set_window_pos(ctx, x, y, 0); }               \
  void WindowPos3##suffix(Context& ctx, T x, T y, T z) { set_window_pos(ctx, x, y, z); }          \
  void WindowPos2##suffix##v(Context& ctx, const T* v) {                                         \
    if (v) set_window_pos(ctx, v[0], v[1], 0);                                                   \
  }                                                                                              \
  void WindowPos3##suffix##v(Context& ctx, const T* v) {                                         \
    if (v) set_window_pos(ctx, v[0], v[1], v[2]);                                                \
  }                                                                                              \
  void WindowPos2##suffix##ARB(Context& ctx, T x, T y) { set_window_pos(ctx, x, y, 0); }          \
  void WindowPos3##suffix##ARB(Context& ctx, T x, T y, T z) { set_window_pos(ctx, x, y, z); }     \
  void WindowPos2##suffix##vARB(Context& ctx, const T* v) {                                      \
    if (v) set_window_pos(ctx, v[0], v[1], 0);                                                   \
  }                                                                                              \
  void WindowPos3##suffix##vARB(Context& ctx, const T* v) {                                      \
    if (v) set_window_pos(ctx, v[0], v[1], v[2]);                                                \
  }
PINEDA_RASTER_POS(GLdouble, d)
PINEDA_RASTER_POS(GLfloat, f)
PINEDA_RASTER_POS(GLint, i)
PINEDA_RASTER_POS(GLshort, s)
#undef PINEDA_RASTER_POS

}  // namespace pineda::gl
