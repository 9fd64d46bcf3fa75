#include "raster/geometry.h"

#include <algorithm>
#include <cmath>

#include "raster/fragment_ops.h"
#include "raster/point_sprite.h"
#include "raster/raster_limits.h"
#include "raster/reference_triangle.h"
#include "raster/reference_lines_points.h"
#include "raster/shader_draw.h"

namespace pineda::raster {
namespace {


int rounded_size(float size, int max) {
  if (!(size >= 1.5f)) return 1;
  return static_cast<int>(std::min(std::floor(size + 0.5f), static_cast<float>(max)));
}

// Antialiased sizes are kept to 1/256 pixel (GL_SMOOTH_*_GRANULARITY), at least one pixel.
double smooth_size(float size, int max) {
  if (!(size >= 1.f)) return 1.0;
  return std::min(std::round(double{size} * kSubpixelOne) / kSubpixelOne, static_cast<double>(max));
}

int clamp_to_int(int64_t v) { return static_cast<int>(std::clamp<int64_t>(v, INT32_MIN, INT32_MAX)); }



// glPolygonOffset's r, the smallest resolvable difference, in depth-buffer steps. One step is not
// always resolvable: positions are floats, and near the near plane (eye distance just above 1) a
// float distance moves window z by 2^-23, two steps of a 24-bit buffer. llvmpipe's r is also two
// steps (piglit gl-1.4-polygon-offset measures it against the separation it can draw).
constexpr double kResolvableDepthSteps = 2.0;

}  // namespace

GeometryStage::GeometryStage(Scene& scene, WindowCache& window_cache, std::vector<Plane>& varying_planes,
                             PrimSetup& filled_triangle, std::function<void()> on_full, bool reference)
    : scene_(scene),
      on_full_(std::move(on_full)),
      reference_(reference),
      window_cache_(window_cache),
      cached_prim_(filled_triangle),
      varying_planes_(varying_planes) {
  const DrawState& s = scene_.current_draw().state;
  const Viewport& vp = s.viewport;
  if (vp.width <= 0 || vp.height <= 0) return;
  PixelRect rect{vp.x, vp.y, clamp_to_int(int64_t{vp.x} + vp.width), clamp_to_int(int64_t{vp.y} + vp.height)};
  if (s.scissor_test) {
    const Rect& sc = s.scissor;
    rect = intersect(rect, {sc.x, sc.y, clamp_to_int(int64_t{sc.x} + sc.width), clamp_to_int(int64_t{sc.y} + sc.height)});
  }
  clip_rect_ = intersect(rect, scene_.render_area());
  if (clip_rect_.empty()) return;
  active_ = true;

  transform_ = WindowTransform(vp, s.clip_planes, scene_.current_draw().depth_max);
  volume_ = transform_.volume();
  line_width_ = s.line_width;
  point_size_ = derived_point_size(s.point_params, s.point_size, 0.f);
  line_smooth_ = s.line_smooth;
  sample_points_ = scene_.framebuffer().samples > 1 && s.multisample.multisample;
  // Stippled multisampled lines keep the single-sampled shape, whose dashes the stipple counts.
  rectangle_lines_ = sample_points_ && !s.line_stipple.enabled;
  point_smooth_ = s.point_smooth;
  point_size_per_vertex_ = s.point_params.per_vertex();
  shader_ = s.shader.get();
  if (shader_) {
    reference_ = false;  // the reference path has no fragment shader stage
    varying_count_ = shader_->program->varying_floats();
    volume_.attrs = varying_count_;
    varying_planes_.assign(static_cast<size_t>(varying_count_) + 1, Plane{});
    if (s.flat_shading)
      for (const shader::Varying& v : shader_->program->varyings()) {
        if (v.name != "gl_Color" && v.name != "gl_SecondaryColor") continue;
        flat_ranges_.emplace_back(v.offset, v.components);
        if (v.back_offset >= 0) flat_ranges_.emplace_back(v.back_offset, v.components);
      }
    Style front;  // (style_for's for a programmable draw: no fixed-function colours)
    front.flat = s.flat_shading;
    shader_fill_params_ = params(front);
  }
  pairs_rectangles_ = !reference && scene_.framebuffer().samples == 1;  // (reference: as given)
}

void GeometryStage::to_clip(const ClipVertex& v, ClipVert& c) const {
  clip_position(v, c);
  if (shader_) {
    const float* in = varyings_ + (&v - vertex_base_) * varying_count_;
    std::copy(in, in + varying_count_, c.attr);
    return;
  }
  for (int i = 0; i < 4; ++i) {
    c.attr[i] = v.color[i];
    c.attr[4 + i] = v.back_color[i];
  }
  for (int u = 0; u < kMaxTextureUnits; ++u)
    for (int i = 0; i < 4; ++i) c.attr[kClipTexAttrs + 4 * u + i] = v.texcoord[u][i];
  for (int i = 0; i < 3; ++i) {
    c.attr[kClipSecondaryAttrs + i] = v.secondary[i];
    c.attr[kClipSecondaryAttrs + 3 + i] = v.back_secondary[i];
  }
  c.attr[kClipFogAttr] = v.fog;
}

namespace {

// The fixed-function attributes of a vertex into its window vertex's planes (DrawRecord plane
// order): colour(), texcoord(unit), secondary() and fog() give where they are.
template <typename Source>
void plane_attributes(const DrawRecord& d, const Source& src, WinVert& w) {
  const float* color = src.color();
  for (int i = 0; i < 4; ++i) w.attr[i] = color[i];
  for (int k = 0; k < d.num_units; ++k) {
    const float* tc = src.texcoord(d.units[k]);
    float* out = &w.attr[d.tex_plane[k]];
    out[0] = tc[0];
    out[1] = tc[1];
    out[2] = tc[3];
    if (d.r_plane[k] >= 0) w.attr[d.r_plane[k]] = tc[2];
  }
  if (d.secondary_plane >= 0)
    for (int i = 0; i < 3; ++i) w.attr[d.secondary_plane + i] = src.secondary()[i];
  if (d.fog_plane >= 0) w.attr[d.fog_plane] = src.fog();
}

// A clipped vertex's attributes, front or back.
struct ClipVertAttributes {
  const ClipVert& v;
  bool back;
  const float* color() const { return &v.attr[back ? 4 : 0]; }
  const float* texcoord(int unit) const { return &v.attr[kClipTexAttrs + 4 * unit]; }
  const float* secondary() const { return &v.attr[kClipSecondaryAttrs + (back ? 3 : 0)]; }
  float fog() const { return v.attr[kClipFogAttr]; }
};

// A transformed vertex's front attributes, read where they are (no ClipVert copy first).
struct FrontAttributes {
  const ClipVertex& v;
  const float* color() const { return v.color; }
  const float* texcoord(int unit) const { return v.texcoord[unit]; }
  const float* secondary() const { return v.secondary; }
  float fog() const { return v.fog; }
};

}  // namespace

void GeometryStage::to_window(const ClipVert& v, bool back_color, WinVert& w) const {
  transform_.position(v, w);
  if (shader_) {
    w.varyings = v.attr;
    return;
  }
  w.varyings = nullptr;
  plane_attributes(scene_.current_draw(), ClipVertAttributes{v, back_color}, w);
}

SetupParams GeometryStage::params(const Style& style) const {
  SetupParams p;
  p.clip = clip_rect_;
  p.sample_bounds = scene_.framebuffer().samples > 1;
  p.planes = scene_.current_draw().planes;
  p.flat = style.flat;
  for (int i = 0; i < 4; ++i) p.flat_color[i] = style.flat_color[i];
  p.back_facing = style.back_facing;
  p.depth_offset = style.depth_offset;
  if (shader_) {
    p.programmable = true;
    p.varyings = varying_count_;
    p.varying_out = varying_planes_.data();
    varying_planes_.back() = Plane{};
  }
  return p;
}

GeometryStage::Style GeometryStage::style_for(const ClipVertex& provoking, bool back_facing) const {
  Style st;
  st.back_facing = back_facing;
  st.flat = scene_.current_draw().state.flat_shading;
  if (shader_) return st;  // varyings in their own array: the fixed-function colours are not set
  const float* c = back_facing ? provoking.back_color : provoking.color;
  for (int i = 0; i < 4; ++i) st.flat_color[i] = clamp01(c[i]);
  return st;
}

void GeometryStage::emit(const PrimSetup& prim) {
  if (reference_) {
    reference_lines_points(prim, scene_.current_draw(), scene_.framebuffer());
    return;
  }
  if (shader_) scene_.add_prim(prim, varying_planes_.data(), varying_count_ + 1);
  else scene_.add_prim(prim);
  if (scene_.full()) on_full_();
}

void GeometryStage::draw_line(ClipVert a, ClipVert b, const Style& style) {
  // Lines are clipped to the view volume itself (not the guard band) before they are widened,
  // as GL specifies: a wide line never reaches into the viewport from a clipped-off part.
  ClipVolume view;
  view.user_planes = volume_.user_planes;
  if (!clip_line(a, b, view)) return;
  const WinVert wa = to_window(a, style.back_facing), wb = to_window(b, style.back_facing);
  if (!has_window_position(wa) || !has_window_position(wb)) return;
  draw_window_line(wa, wb, style);
}

void GeometryStage::draw_window_line(const WinVert& wa, const WinVert& wb, const Style& style) {
  if (rectangle_lines_) return draw_line_rectangle(wa, wb, style);
  PrimSetup prim;
  const bool covered = line_smooth_ ? setup_smooth_line(wa, wb, smooth_size(line_width_, kMaxLineWidth), params(style), prim)
                                    : setup_line(wa, wb, rounded_size(line_width_, kMaxLineWidth), params(style), prim);
  if (!covered) return;
  // The stipple counts whole pixels of major-axis distance from the first vertex on, across a
  // strip, as llvmpipe (Mesa's draw module) does. It measures from the snapped positions that
  // coverage uses (llvmpipe rasterizes each stipple dash from snapped ends too), so that a
  // vertex on a pixel centre starts the pattern at that pixel despite rounding in the transform.
  LineCoverage& l = prim.line;
  const int64_t d_major = l.x_major ? wb.x - wa.x : wb.y - wa.y;
  l.stipple_origin = static_cast<float>(l.x_major ? wa.x : wa.y) / kSubpixelOne;
  l.stipple_step = d_major >= 0 ? 1 : -1;
  l.stipple_length = static_cast<float>(std::max(std::llabs(wb.x - wa.x), std::llabs(wb.y - wa.y))) / kSubpixelOne;
  l.stipple_count = stipple_count_;
  stipple_count_ += l.stipple_length;
  emit(prim);
}

// A multisampled line (GL 1.5 3.4.4, whatever LINE_SMOOTH says): the rectangle of the line's
// width centred on the segment, as two triangles, covering the samples that lie inside it. Its
// attributes vary along the segment only, so both triangles get the same planes.
void GeometryStage::draw_line_rectangle(const WinVert& a, const WinVert& b, const Style& style) {
  const double dx = b.fx - a.fx, dy = b.fy - a.fy, length = std::hypot(dx, dy);
  if (!(length > 0.0)) return;
  const double half = smooth_size(line_width_, kMaxLineWidth) / 2.0;
  const double nx = -dy / length * half, ny = dx / length * half;
  WinVert corners[4] = {a, a, b, b};
  const double side[4] = {1.0, -1.0, -1.0, 1.0};  // around the rectangle
  for (int i = 0; i < 4; ++i) {
    corners[i].fx += side[i] * nx;
    corners[i].fy += side[i] * ny;
    corners[i].x = snap(corners[i].fx);
    corners[i].y = snap(corners[i].fy);
  }
  const SetupParams p = params(style);
  PrimSetup prim;
  if (setup_triangle(corners[0], corners[1], corners[2], p, prim)) emit(prim);
  if (setup_triangle(corners[0], corners[2], corners[3], p, prim)) emit(prim);
}

float GeometryStage::point_size_of(const ClipVertex& v) const {
  return point_size_per_vertex_ ? v.point_size : point_size_;
}

void GeometryStage::draw_point(const ClipVert& v, const Style& style, float size) {
  const double x = v.pos[0], y = v.pos[1], z = v.pos[2], w = v.pos[3];
  // A point is drawn when its centre is inside the clip volume.
  if (!(w > 0.0 && -w <= x && x <= w && -w <= y && y <= w && -w <= z && z <= w)) return;
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if ((volume_.user_planes >> i & 1u) && !(v.user[i] >= 0.0)) return;
  const WinVert wv = to_window(v, style.back_facing);
  if (!has_window_position(wv)) return;
  if (sample_points_) return draw_sample_point(wv, style, size);
  PrimSetup prim;
  const SetupParams p = params(style);
  const DrawRecord& d = scene_.current_draw();
  const PointSprite& sprite = d.state.point_params.sprite;  // point smoothing is ignored for sprites
  const double drawn_size = sprite.enabled ? size
                            : point_smooth_ ? smooth_size(size, kMaxPointSize)
                                            : rounded_size(size, kMaxPointSize);
  const bool covered = sprite.enabled  ? setup_point_sprite(wv, size, sprite, d, p, prim)
                       : point_smooth_ ? setup_smooth_point(wv, drawn_size, p, prim)
                                       : setup_point(wv, static_cast<int>(drawn_size), p, prim);
  if (shader_) varying_planes_.back() = Plane{static_cast<float>(wv.fx), static_cast<float>(wv.fy), static_cast<float>(drawn_size)};
  if (covered) emit(prim);
}

// A multisampled point (GL 1.5 3.3.3, whatever POINT_SMOOTH says): the samples inside the disc
// of its size or, a sprite, inside its square; its size in antialiased points' steps (1/256),
// as the spec asks of the disc (a sprite's size is kept to those steps single-sampled too).
void GeometryStage::draw_sample_point(const WinVert& v, const Style& style, float size) {
  const DrawRecord& d = scene_.current_draw();
  const PointSprite& sprite = d.state.point_params.sprite;
  const PointFade faded = point_fade(size, d.state.point_params.fade_threshold);
  const double drawn_size = smooth_size(faded.size, kMaxPointSize);
  PrimSetup prim;
  const bool covered = setup_sample_point(v, std::llround(drawn_size * kSubpixelOne), sprite.enabled, params(style), prim);
  prim.sample_point.fade = faded.fade;
  if (sprite.enabled) replace_sprite_coords(static_cast<float>(drawn_size), sprite, d, prim);
  if (shader_) varying_planes_.back() = Plane{static_cast<float>(v.fx), static_cast<float>(v.fy), static_cast<float>(drawn_size)};
  if (covered) emit(prim);
}

void GeometryStage::point(const ClipVertex& v) {
  if (!active_ || !finite_position(v)) return;
  emit_held_half();
  draw_point(to_clip(v), style_for(v, false), point_size_of(v));
}

void GeometryStage::line(const ClipVertex& a, const ClipVertex& b, const ClipVertex& provoking) {
  if (!active_ || !finite_position(a) || !finite_position(b)) return;
  emit_held_half();
  // A line inside the view volume, clipping would leave as it is: its ends' window vertices
  // come from the cache, so a strip's vertices are taken to the window once, not twice (the
  // same positions and front attributes draw_line computes). Conditions as polygon()'s, and
  // ends in different slots (the second end's window would replace the first's).
  if (vertex_base_ && flat_ranges_.empty() && !reference_ &&
      !window_cache_.share_slot(static_cast<size_t>(&a - vertex_base_), static_cast<size_t>(&b - vertex_base_))) {
    const WinVert* wa = cached_view_window(a);
    const WinVert* wb = wa ? cached_view_window(b) : nullptr;
    if (wb) return draw_window_line(*wa, *wb, style_for(provoking, false));
  }
  ClipVert ca = to_clip(a), cb = to_clip(b);
  flatten_varyings(ca, provoking);
  flatten_varyings(cb, provoking);
  draw_line(ca, cb, style_for(provoking, false));
}

void GeometryStage::flatten_varyings(ClipVert& v, const ClipVertex& provoking) const {
  if (flat_ranges_.empty()) return;
  const float* from = varyings_ + (&provoking - vertex_base_) * varying_count_;
  for (const auto& [offset, count] : flat_ranges_)
    for (int i = offset; i < offset + count && i < varying_count_; ++i) v.attr[i] = from[i];
}

void GeometryStage::use_back_varyings(ClipVert& v) const {
  if (!shader_ || !shader_->two_side) return;
  for (const shader::Varying& var : shader_->program->varyings()) {
    if (var.back_offset < 0) continue;
    for (int i = 0; i < var.components; ++i) {
      const int from = var.back_offset + i, to = var.offset + i;
      if (from < varying_count_ && to < varying_count_) v.attr[to] = v.attr[from];
    }
  }
}

double GeometryStage::polygon_offset(const std::vector<WinVert>& window, bool enabled) const {
  if (!enabled) return 0.0;
  const DrawState& s = scene_.current_draw().state;
  double dzdx = 0.0, dzdy = 0.0;
  for (size_t i = 1; i + 1 < window.size(); ++i)
    if (depth_slopes(window[0], window[i], window[i + 1], dzdx, dzdy)) break;
  const double slope = std::max(std::fabs(dzdx), std::fabs(dzdy));
  const double offset = s.offset_factor * slope + kResolvableDepthSteps * s.offset_units;
  return std::isfinite(offset) ? offset : 0.0;
}

void GeometryStage::window_positions(size_t begin, size_t end, PreparedWindow* out, SimdPath path) const {
  transform_.prepare_many(vertex_base_ + begin, varyings_ + begin * static_cast<size_t>(varying_count_),
                          static_cast<size_t>(varying_count_), end - begin, out, path);
}

const WinVert* GeometryStage::cached_window(const ClipVertex& v) {
  const size_t index = static_cast<size_t>(&v - vertex_base_);
  if (index >= vertex_count_) return nullptr;
  bool fresh = false;
  WindowSlot& slot = window_cache_.slot(index, fresh);
  if (fresh && prepared_) {  // the position worked out ahead (WindowTransform::prepare's)
    const PreparedWindow& p = prepared_[index];
    if (p.usable) {
      static_cast<WinPosition&>(slot.window) = p.position;  // with a programmable vertex's varyings
      if (!shader_) plane_attributes(scene_.current_draw(), FrontAttributes{v}, slot.window);
      slot.usable = true;
    }
  } else if (fresh) {
    if (finite_position(v)) {
      // Only the position and clip distances are clipped: the attributes are read where they
      // are (a programmable vertex's varyings stay in the draw's array).
      clip_position(v, cache_clip_);
      if (clip_outcode(cache_clip_, volume_) == 0) {
        transform_.position(cache_clip_, slot.window);
        if (shader_) {
          slot.window.varyings = varyings_ + index * static_cast<size_t>(varying_count_);
        } else {
          slot.window.varyings = nullptr;
          plane_attributes(scene_.current_draw(), FrontAttributes{v}, slot.window);
        }
        slot.usable = has_window_position(slot.window);
      }
    }
  }
  return slot.usable ? &slot.window : nullptr;
}

// cached_window for a vertex inside the view volume, null otherwise.
const WinVert* GeometryStage::cached_view_window(const ClipVertex& v) {
  const WinVert* w = cached_window(v);
  if (!w) return nullptr;
  bool fresh = false;
  WindowSlot& slot = window_cache_.slot(static_cast<size_t>(&v - vertex_base_), fresh);  // cached_window's
  if (slot.in_view < 0) {
    ClipVolume view;
    view.user_planes = volume_.user_planes;
    clip_position(v, cache_clip_);
    slot.in_view = clip_outcode(cache_clip_, view) == 0 ? 1 : 0;
  }
  return slot.in_view ? w : nullptr;
}

// polygon() for a triangle of cached vertices that is culled or filled front facing without
// an offset; false leaves the triangle to polygon()'s general path (the same result).
bool GeometryStage::fill_cached_triangle(std::span<const ClipVertex* const> v, const ClipVertex& provoking) {
  if (prepared_ && shader_) {
    const WinPosition* w[3];
    for (int i = 0; i < 3; ++i) {
      const size_t index = static_cast<size_t>(v[i] - vertex_base_);
      if (index >= vertex_count_ || !prepared_[index].usable) return false;
      const PreparedWindow& p = prepared_[index];
      w[i] = &p.position;
    }
    return fill_window_triangle(w, provoking);
  }
  // (Vertices sharing a cache slot leave two of w pointing at one window: a zero area, which
  // fill_window_triangle leaves to the general path.)
  const WinVert* w[3];
  for (int i = 0; i < 3; ++i)
    if (!(w[i] = cached_window(*v[i]))) return false;
  return fill_window_triangle(w, provoking);
}

template <typename Vertex>
bool GeometryStage::fill_window_triangle(const Vertex* const (&w)[3], const ClipVertex& provoking) {
  const int64_t area = signed_area2(*w[0], *w[1], *w[2]);
  const DrawState& s = scene_.current_draw().state;
  const bool front = s.front_ccw ? area > 0 : area < 0;
  if (s.cull_face && (front ? s.cull_front : s.cull_back)) return true;
  if (!front || s.polygon_front != PolygonMode::Fill || s.offset_fill) return false;
  if (area == 0) return true;
  // (A draw of three vertices has no second triangle: holding its one back would only cost.)
  if (pairs_rectangles_ && vertex_count_ > 3 && unpaired_ < kUnpairedHalves && pair_into_rectangle(w, provoking))
    return true;
  emit_held_half();
  if (setup_filled_triangle(*w[0], *w[1], *w[2], provoking)) emit(cached_prim_);
  return true;
}

template <typename Vertex>
bool GeometryStage::setup_filled_triangle(const Vertex& a, const Vertex& b, const Vertex& c,
                                          const ClipVertex& provoking) {
  if (shader_) {
    varying_planes_.back() = Plane{};  // (a point of the draw, from glPolygonMode, set it)
    return setup_triangle<WinPosition>(a, b, c, shader_fill_params_, cached_prim_);
  }
  if constexpr (std::is_same_v<Vertex, WinVert>) return setup_triangle(a, b, c, params(style_for(provoking, false)), cached_prim_);
  return false;  // (prepared windows are a programmable draw's)
}

template <typename Vertex>
bool GeometryStage::pair_into_rectangle(const Vertex* const (&w)[3], const ClipVertex& provoking) {
  int corner = 0;
  int64_t x0, y0, x1, y1;
  if (!may_be_rectangle_half(*w[0], *w[1], *w[2]) || !rectangle_corner(*w[0], *w[1], *w[2], corner, x0, y0, x1, y1))
    return false;
  const int count = shader_ ? varying_count_ : scene_.current_draw().planes;
  auto values = [&](const auto& v) -> const float* {
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, WinVert>) return shader_ ? v.varyings : v.attr;
    return v.varyings;
  };
  if (!shader_ && !std::is_same_v<Vertex, WinVert>) return false;
  if (holding_) {
    const float* held_values[3] = {values(held_.v[0]), values(held_.v[1]), values(held_.v[2])};
    const WinPosition* v[3] = {w[0], w[1], w[2]};
    const float* v_values[3] = {values(*w[0]), values(*w[1]), values(*w[2])};
    if (completes_rectangle(held_, held_values, v, v_values, count) && same_flat_color(*held_provoking_, provoking)) {
      holding_ = false;
      unpaired_ = 0;
      // The held half's setup (its planes are the rectangle's), then the rectangle's coverage.
      if (setup_filled_triangle(held_.v[0], held_.v[1], held_.v[2], *held_provoking_)) {
        make_rectangle(held_, clip_rect_, cached_prim_);
        if (!cached_prim_.bounds.empty()) emit(cached_prim_);
      }
      return true;
    }
    emit_held_half();
    ++unpaired_;
  }
  // Held: its vertices copied (a cached window may be replaced by the next triangle's).
  for (int i = 0; i < 3; ++i) {
    static_cast<WinPosition&>(held_.v[i]) = *w[i];
    if (!shader_) std::copy_n(values(*w[i]), count, held_.v[i].attr);
  }
  held_.corner = corner;
  held_.x0 = x0;
  held_.y0 = y0;
  held_.x1 = x1;
  held_.y1 = y1;
  held_provoking_ = &provoking;
  holding_ = true;
  return true;
}

// Whether two triangles' provoking vertices give them the same flat colour (GL_FLAT: the
// fixed-function colours are the provoking vertex's; a program's varyings are not flat here).
bool GeometryStage::same_flat_color(const ClipVertex& a, const ClipVertex& b) const {
  if (shader_ || !scene_.current_draw().state.flat_shading) return true;
  const Style sa = style_for(a, false), sb = style_for(b, false);
  return std::equal(sa.flat_color, sa.flat_color + 4, sb.flat_color);
}

void GeometryStage::emit_held_half() {
  if (!holding_) return;
  holding_ = false;
  if (setup_filled_triangle(held_.v[0], held_.v[1], held_.v[2], *held_provoking_)) emit(cached_prim_);
}

bool GeometryStage::reads_edge_flags() const {
  const DrawState& s = scene_.current_draw().state;
  return s.polygon_front != PolygonMode::Fill || s.polygon_back != PolygonMode::Fill;
}

void GeometryStage::polygon(std::span<const ClipVertex* const> v, std::span<const bool> edge_flags,
                            const ClipVertex& provoking) {
  if (!active_) return;
  // Not for flat-shaded gl_Color varyings, which polygon() takes from the provoking vertex.
  if (v.size() == 3 && vertex_base_ && flat_ranges_.empty() && !reference_ && fill_cached_triangle(v, provoking))
    return;
  emit_held_half();
  for (const ClipVertex* p : v)
    if (!finite_position(*p)) return;
  in_.resize(v.size());
  for (size_t i = 0; i < v.size(); ++i) to_clip(*v[i], in_[i]);
  for (ClipVert& c : in_) flatten_varyings(c, provoking);
  // Most polygons lie inside the clip volume: they are used as they are, not copied.
  bool inside = true;
  for (const ClipVert& c : in_) inside &= clip_outcode(c, volume_) == 0;
  if (!inside) clip_polygon(in_, volume_, clipped_, scratch_);
  std::vector<ClipVert>& visible = inside ? in_ : clipped_;  // Fill may change it; in_ is not read after Fill
  if (visible.size() < 3) return;

  // Facing from the snapped window positions of the visible part.
  window_.resize(visible.size());
  for (size_t i = 0; i < visible.size(); ++i) {
    to_window(visible[i], false, window_[i]);
    if (!has_window_position(window_[i])) return;
  }
  int64_t area = 0;
  for (size_t i = 1; i + 1 < window_.size(); ++i) area += signed_area2(window_[0], window_[i], window_[i + 1]);
  const DrawState& s = scene_.current_draw().state;
  const bool front = s.front_ccw ? area > 0 : area < 0;
  if (s.cull_face && (front ? s.cull_front : s.cull_back)) return;
  const PolygonMode mode = front ? s.polygon_front : s.polygon_back;
  Style style = style_for(provoking, !front);

  if (mode == PolygonMode::Fill) {
    if (area == 0) return;
    style.depth_offset = polygon_offset(window_, s.offset_fill);
    if (!front)
      for (size_t i = 0; i < visible.size(); ++i) {
        use_back_varyings(visible[i]);
        to_window(visible[i], true, window_[i]);
      }
    const SetupParams p = params(style);
    for (size_t i = 1; i + 1 < window_.size(); ++i) {
      if (reference_) {  // unsnapped: no sliver is turned inside out
        reference_triangle(window_[0], window_[i], window_[i + 1], p, scene_.current_draw(), scene_.framebuffer());
        continue;
      }
      // Slivers that snapping turned inside out would cover pixels twice; they are dropped.
      const int64_t a = signed_area2(window_[0], window_[i], window_[i + 1]);
      if (a == 0 || (a > 0) != (area > 0)) continue;
      PrimSetup prim;
      if (setup_triangle(window_[0], window_[i], window_[i + 1], p, prim)) emit(prim);
    }
    return;
  }
  const size_t n = v.size();
  if (mode == PolygonMode::Line) {
    style.depth_offset = polygon_offset(window_, s.offset_line);
    for (size_t i = 0; i < n; ++i) {
      if (!edge_flags[i]) continue;
      restart_line_stipple();
      draw_line(in_[i], in_[(i + 1) % n], style);
    }
  } else {
    style.depth_offset = polygon_offset(window_, s.offset_point);
    for (size_t i = 0; i < n; ++i)
      if (edge_flags[i]) draw_point(in_[i], style, point_size_of(*v[i]));
  }
}

}  // namespace pineda::raster
