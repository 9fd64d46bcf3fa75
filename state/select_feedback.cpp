#include "state/select_feedback.h"

#include <algorithm>
#include <cmath>

#include "raster/feedback_stage.h"
#include "state/context.h"

namespace pineda {
namespace {

// GL 1.1 5.2: depths in [0, 1] scaled to [0, 2^32 - 1].
GLuint select_depth(double z) { return static_cast<GLuint>(std::llround(std::clamp(z, 0.0, 1.0) * 4294967295.0)); }

class SelectSink final : public raster::FeedbackSink {
 public:
  explicit SelectSink(RenderModeState& rm) : rm_(rm) {}
  void point(const raster::FeedbackVertex& v) override { hit(v); }
  void line(const raster::FeedbackVertex& a, const raster::FeedbackVertex& b, bool) override {
    hit(a);
    hit(b);
  }
  void polygon(std::span<const raster::FeedbackVertex> v) override {
    for (const raster::FeedbackVertex& p : v) hit(p);
  }

 private:
  void hit(const raster::FeedbackVertex& v) { rm_.hit_at(v.window[2]); }
  RenderModeState& rm_;
};

// GL 1.1 table 5.2: what each feedback type writes per vertex.
void feedback_vertex(RenderModeState& rm, const raster::FeedbackVertex& v) {
  const GLenum type = rm.feedback_type;
  const int coords = type == GL_2D ? 2 : (type == GL_4D_COLOR_TEXTURE ? 4 : 3);
  for (int i = 0; i < coords; ++i) rm.feedback_value(v.window[i]);
  if (type == GL_2D || type == GL_3D) return;
  for (int i = 0; i < 4; ++i) rm.feedback_value(v.color[i]);
  if (type == GL_3D_COLOR) return;
  for (int i = 0; i < 4; ++i) rm.feedback_value(v.texcoord[i]);
}

class FeedbackTokens final : public raster::FeedbackSink {
 public:
  explicit FeedbackTokens(RenderModeState& rm) : rm_(rm) {}
  void point(const raster::FeedbackVertex& v) override {
    rm_.feedback_value(GL_POINT_TOKEN);
    vertex(v);
  }
  void line(const raster::FeedbackVertex& a, const raster::FeedbackVertex& b, bool reset) override {
    rm_.feedback_value(reset ? GL_LINE_RESET_TOKEN : GL_LINE_TOKEN);
    vertex(a);
    vertex(b);
  }
  void polygon(std::span<const raster::FeedbackVertex> v) override {
    rm_.feedback_value(GL_POLYGON_TOKEN);
    rm_.feedback_value(double(v.size()));
    for (const raster::FeedbackVertex& p : v) vertex(p);
  }

 private:
  void vertex(const raster::FeedbackVertex& v) { feedback_vertex(rm_, v); }
  RenderModeState& rm_;
};

}  // namespace

void RenderModeState::write_hit_record() {
  if (!hit) return;
  select_value(GLuint(names.size()));
  select_value(select_depth(hit_min_z));
  select_value(select_depth(hit_max_z));
  for (GLuint n : names) select_value(n);
  ++hits;
  hit = false;
  hit_min_z = 1.0;
  hit_max_z = 0.0;
}

bool pixel_rect_feedback(Context& ctx, GLenum token) {
  RenderModeState& rm = ctx.render_mode;
  if (rm.mode == GL_RENDER) return false;
  const RasterPosition& rp = ctx.raster_pos;
  if (rm.mode != GL_FEEDBACK || !rp.valid) return true;
  raster::FeedbackVertex v;
  for (int i = 0; i < 4; ++i) {
    v.window[i] = rp.window[i];
    v.color[i] = rp.color[i];
    v.texcoord[i] = rp.texcoord[0][i];
  }
  rm.feedback_value(token);
  feedback_vertex(rm, v);
  return true;
}

void raster_pos_select_hit(Context& ctx) {
  if (ctx.render_mode.mode == GL_SELECT && ctx.raster_pos.valid) ctx.render_mode.hit_at(ctx.raster_pos.window[2]);
}

void select_feedback_draw(Context& ctx, const raster::DrawState& state, raster::Primitive mode,
                          std::span<const raster::ClipVertex> vertices, std::span<const uint32_t> indices) {
  RenderModeState& rm = ctx.render_mode;
  if (rm.mode == GL_SELECT) {
    SelectSink sink(rm);
    raster::feedback_primitives(state, mode, vertices, indices, sink);
  } else {
    FeedbackTokens sink(rm);
    raster::feedback_primitives(state, mode, vertices, indices, sink);
  }
}

}  // namespace pineda
