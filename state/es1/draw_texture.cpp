// OES_draw_texture (OpenGL ES 1.1): glDrawTex*OES draws a window-aligned rectangle whose
// texture coordinates map each enabled unit's crop rectangle (TEXTURE_CROP_RECT_OES, set
// through glTexParameter) onto it; the fragments then go through the whole fragment pipeline.
// Transforms, lighting, clip planes, culling and polygon offset do not apply.
#include <algorithm>
#include <array>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/draw.h"
#include "state/es1/fixed.h"

namespace pineda::gl {
namespace {

float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }  // NaN -> 0

void draw_texture(Context& ctx, float x, float y, float z, float width, float height) {
  if (!(width > 0.f) || !(height > 0.f)) return ctx.record_error(GL_INVALID_VALUE, "width or height is not positive");
  const Drawable* drawable = ctx.draw_drawable();
  if (!drawable) return;
  raster::DrawState state = fragment_snapshot(ctx);
  // (x, y) are window coordinates: a viewport over the whole framebuffer maps them through.
  const int fb_width = drawable->framebuffer.width, fb_height = drawable->framebuffer.height;
  if (fb_width <= 0 || fb_height <= 0) return;
  state.viewport = {0, 0, fb_width, fb_height, ctx.viewport.near_z, ctx.viewport.far_z};
  state.cull_face = false;
  state.polygon_front = state.polygon_back = raster::PolygonMode::Fill;
  state.offset_fill = false;
  state.clip_planes = 0;
  state.polygon_stipple.enabled = false;

  const float xs[2] = {x, x + width}, ys[2] = {y, y + height};
  const float clip_z = 2.f * clamp01(z) - 1.f;  // window depth n + z (f - n)
  std::array<raster::ClipVertex, 4> corners{};
  const int order[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // counter-clockwise
  for (int k = 0; k < 4; ++k) {
    raster::ClipVertex& v = corners[k];
    const int i = order[k][0], j = order[k][1];
    v.clip[0] = 2.f * xs[i] / float(fb_width) - 1.f;
    v.clip[1] = 2.f * ys[j] / float(fb_height) - 1.f;
    v.clip[2] = clip_z;
    v.clip[3] = 1.f;
    for (int c = 0; c < 4; ++c) v.color[c] = v.back_color[c] = clamp01(ctx.current_color[c]);
    v.edge_flag = true;
    v.fog = 0.f;  // the fragment distance for fog is 0
    for (int u = 0; u < raster::kMaxTextureUnits; ++u) {
      const raster::TextureUnit& unit = state.texture_units[u];
      float* tc = v.texcoord[u];
      tc[0] = tc[1] = tc[2] = 0.f;
      tc[3] = 1.f;
      if (!unit.image || unit.image->levels.empty()) continue;
      // Texture matrices are ignored: s = (Ucr + (X - Xs) Wcr / Ws) / Wt at the corners.
      const TextureObject& tex = ctx.textures.get_or_create(ctx.texture_units[u].bound_2d, GL_TEXTURE_2D);
      const GLint* crop = tex.params.crop_rect;
      const raster::TextureLevel& base = unit.image->levels[0];
      tc[0] = (float(crop[0]) + float(i) * float(crop[2])) / float(base.width);
      tc[1] = (float(crop[1]) + float(j) * float(crop[3])) / float(base.height);
    }
  }
  static constexpr uint32_t kIndices[4] = {0, 1, 2, 3};
  ctx.render_to_draw_buffers(
      [&] { ctx.renderer().draw(state, raster::Primitive::Quads, std::span(corners), std::span(kIndices)); });
}

}  // namespace

void DrawTexfOES(Context& ctx, GLfloat x, GLfloat y, GLfloat z, GLfloat width, GLfloat height) {
  draw_texture(ctx, x, y, z, width, height);
}
void DrawTexfvOES(Context& ctx, const GLfloat* c) {
  if (c) draw_texture(ctx, c[0], c[1], c[2], c[3], c[4]);
}
void DrawTexiOES(Context& ctx, GLint x, GLint y, GLint z, GLint width, GLint height) {
  draw_texture(ctx, float(x), float(y), float(z), float(width), float(height));
}
void DrawTexivOES(Context& ctx, const GLint* c) {
  if (c) DrawTexiOES(ctx, c[0], c[1], c[2], c[3], c[4]);
}
void DrawTexsOES(Context& ctx, GLshort x, GLshort y, GLshort z, GLshort width, GLshort height) {
  draw_texture(ctx, float(x), float(y), float(z), float(width), float(height));
}
void DrawTexsvOES(Context& ctx, const GLshort* c) {
  if (c) DrawTexsOES(ctx, c[0], c[1], c[2], c[3], c[4]);
}
void DrawTexxOES(Context& ctx, GLfixed x, GLfixed y, GLfixed z, GLfixed width, GLfixed height) {
  draw_texture(ctx, es1::from_fixed(x), es1::from_fixed(y), es1::from_fixed(z), es1::from_fixed(width),
               es1::from_fixed(height));
}
void DrawTexxvOES(Context& ctx, const GLfixed* c) {
  if (c) DrawTexxOES(ctx, c[0], c[1], c[2], c[3], c[4]);
}

}  // namespace pineda::gl
