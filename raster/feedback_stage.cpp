#include "raster/feedback_stage.h"

#include <algorithm>
#include <cmath>

namespace pineda::raster {
namespace {

// ClipVert attributes: colour 0..3, back colour 4..7, then unit 0's s, t, r, q.
constexpr int kBackColorAttr = 4, kTexcoordAttr = 8;

bool finite(const ClipVertex& v) {
  return std::isfinite(v.clip[0]) && std::isfinite(v.clip[1]) && std::isfinite(v.clip[2]) && std::isfinite(v.clip[3]);
}

class FeedbackStage final : public PrimitiveSink {
 public:
  FeedbackStage(const DrawState& state, FeedbackSink& sink) : s_(state), sink_(sink) {}

  void point(const ClipVertex& v) override {
    if (!finite(v)) return;
    const ClipVert c = to_clip(v);
    if (clip_outcode(c, volume_) == 0) sink_.point(to_feedback(c, false));
  }

  void line(const ClipVertex& a, const ClipVertex& b, const ClipVertex&) override {
    if (!finite(a) || !finite(b)) return;
    ClipVert ca = to_clip(a), cb = to_clip(b);
    if (!clip_line(ca, cb, volume_)) return;
    sink_.line(to_feedback(ca, false), to_feedback(cb, false), reset_);
    reset_ = false;
  }

  // Called by assembly (where it knows line stipple) before each strip or independent line.
  void restart_line_stipple() override { reset_ = true; }

  void polygon(std::span<const ClipVertex* const> v, std::span<const bool> edge_flags, const ClipVertex&) override {
    for (const ClipVertex* p : v)
      if (!finite(*p)) return;
    in_.clear();
    for (const ClipVertex* p : v) in_.push_back(to_clip(*p));
    clip_polygon(in_, volume_, clipped_, scratch_);
    if (clipped_.size() < 3) return;
    window_.clear();
    for (const ClipVert& c : clipped_) window_.push_back(to_feedback(c, false));
    double area = 0;
    for (size_t i = 1; i + 1 < window_.size(); ++i) {
      const double* p0 = window_[0].window;
      const double* p1 = window_[i].window;
      const double* p2 = window_[i + 1].window;
      area += (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
    }
    const bool front = s_.front_ccw ? area > 0 : area < 0;
    if (s_.cull_face && (front ? s_.cull_front : s_.cull_back)) return;
    if (!front)
      for (size_t i = 0; i < clipped_.size(); ++i) window_[i] = to_feedback(clipped_[i], true);
    const PolygonMode mode = front ? s_.polygon_front : s_.polygon_back;
    if (mode == PolygonMode::Fill) return sink_.polygon(window_);
    // Unfilled: the boundary edges of the original polygon, when clipping left it whole.
    const bool whole = clipped_.size() == v.size();
    for (size_t i = 0; i < window_.size(); ++i) {
      if (whole && !edge_flags[i]) continue;
      if (mode == PolygonMode::Point) sink_.point(window_[i]);
      else sink_.line(window_[i], window_[(i + 1) % window_.size()], i == 0);
    }
  }

 private:
  static ClipVert to_clip(const ClipVertex& v) {
    ClipVert c{};
    for (int i = 0; i < 4; ++i) {
      c.pos[i] = v.clip[i];
      c.attr[i] = v.color[i];
      c.attr[kBackColorAttr + i] = v.back_color[i];
      c.attr[kTexcoordAttr + i] = v.texcoord[0][i];
    }
    return c;
  }

  FeedbackVertex to_feedback(const ClipVert& c, bool back_color) const {
    const Viewport& vp = s_.viewport;
    const double inv_w = 1.0 / c.pos[3];
    const double near_z = std::clamp(vp.near_z, 0.0, 1.0), far_z = std::clamp(vp.far_z, 0.0, 1.0);
    FeedbackVertex f;
    f.window[0] = (c.pos[0] * inv_w + 1.0) * vp.width * 0.5 + vp.x;
    f.window[1] = (c.pos[1] * inv_w + 1.0) * vp.height * 0.5 + vp.y;
    f.window[2] = std::clamp(near_z + (far_z - near_z) * (c.pos[2] * inv_w + 1.0) * 0.5, 0.0, 1.0);
    f.window[3] = c.pos[3];
    const int color = back_color ? kBackColorAttr : 0;
    for (int i = 0; i < 4; ++i) {
      f.color[i] = std::clamp(c.attr[color + i], 0.f, 1.f);
      f.texcoord[i] = c.attr[kTexcoordAttr + i];
    }
    return f;
  }

  const DrawState& s_;
  FeedbackSink& sink_;
  ClipVolume volume_;  // the view volume: x, y and z in [-w, w]
  bool reset_ = true;
  std::vector<ClipVert> in_, clipped_, scratch_;
  std::vector<FeedbackVertex> window_;
};

}  // namespace

void feedback_primitives(const DrawState& state, Primitive mode, std::span<const ClipVertex> vertices,
                         std::span<const uint32_t> indices, FeedbackSink& sink) {
  FeedbackStage stage(state, sink);
  assemble_primitives(mode, vertices, indices, stage);
}

}  // namespace pineda::raster
