// The per-draw front end: clipping, facing and culling, polygon modes, setup and binning of
// the primitives that assembly produces.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "raster/clip.h"
#include "raster/primitive.h"
#include "raster/rectangle_pair.h"
#include "raster/scene.h"
#include "raster/setup.h"
#include "raster/window_cache.h"
#include "raster/window_transform.h"

namespace pineda::raster {

class GeometryStage final : public PrimitiveSink {
 public:
  // Uses the scene's current draw; `on_full` is called when the scene asks to be executed.
  // `reference`: primitives are rasterized at once by the reference path, not binned.
  // `window_cache`: the renderer's, which this draw's vertices take over (window_cache.h).
  // `varying_planes`: the renderer's room for a programmable primitive's planes, kept between
  // draws (not allocated per draw). `filled_triangle`: the renderer's room for the setup of the
  // filled triangles (fill_window_triangle), kept between draws (constructing a PrimSetup per
  // draw was a quarter of a one-triangle draw's GeometryStage).
  GeometryStage(Scene& scene, WindowCache& window_cache, std::vector<Plane>& varying_planes, PrimSetup& filled_triangle,
                std::function<void()> on_full, bool reference = false);

  void point(const ClipVertex& v) override;
  void line(const ClipVertex& a, const ClipVertex& b, const ClipVertex& provoking) override;
  void restart_line_stipple() override { stipple_count_ = 0.f; }
  void polygon(std::span<const ClipVertex* const> v, std::span<const bool> edge_flags,
               const ClipVertex& provoking) override;
  // Only the line and point polygon modes draw by edge flags.
  bool reads_edge_flags() const override;

  // False when the draw cannot produce any fragment (empty viewport or clip rectangle).
  bool active() const { return active_; }

  // The scene's current record is a new one that differs from this stage's only in its
  // ShaderDraw (Scene::repeat_of_current_draw): the stage goes on with it.
  void follow_new_uniforms() { shader_ = scene_.current_draw().state.shader.get(); }

  // Ends the draw's assembly: a triangle held back as half of a rectangle goes to the scene.
  void finish_assembly() {
    emit_held_half();
    unpaired_ = 0;
  }

  // The draw's vertices (the ones assembly passes are elements of it): triangles inside the
  // clip volume take their window positions from a cache of the recent ones. Begins a draw: the
  // renderer keeps the stage for every draw of one record (constructing one was a tenth of a
  // one-triangle draw's time), and an earlier draw's prepared windows are not this one's.
  void set_vertices(std::span<const ClipVertex> vertices) {
    vertex_base_ = vertices.data();
    vertex_count_ = vertices.size();
    prepared_ = nullptr;
    window_cache_.begin_draw(vertex_count_);
  }

  // A programmable draw: vertex i of `vertices` has the varyings at varyings + i * count,
  // count = the program's varying_floats().
  void set_varyings(const ClipVertex* vertices, const float* varyings) {
    vertex_base_ = vertices;
    varyings_ = varyings;
  }

  // Vertices [begin, end) of the draw (after set_varyings) into out[0, end - begin); may run
  // on several threads at once; `path` picks the copy of the vector code (the same windows).
  void window_positions(size_t begin, size_t end, PreparedWindow* out, SimdPath path) const;
  // Triangles of the draw take their vertices' window positions from `windows` (one per vertex).
  void use_window_positions(const PreparedWindow* windows) { prepared_ = windows; }

 private:
  struct Style {  // how a polygon's facing shapes its lines and points
    bool back_facing = false;
    bool flat = false;
    float flat_color[4] = {0, 0, 0, 0};
    double depth_offset = 0.0;
  };

  // Into `c` (a ClipVert is large: polygons fill theirs in place).
  void to_clip(const ClipVertex& v, ClipVert& c) const;
  ClipVert to_clip(const ClipVertex& v) const {
    ClipVert c;
    to_clip(v, c);
    return c;
  }
  void to_window(const ClipVert& v, bool back_color, WinVert& w) const;  // into w: as to_clip
  WinVert to_window(const ClipVert& v, bool back_color) const {
    WinVert w;
    to_window(v, back_color, w);
    return w;
  }
  SetupParams params(const Style& style) const;
  Style style_for(const ClipVertex& provoking, bool back_facing) const;
  void emit(const PrimSetup& prim);
  void draw_line(ClipVert a, ClipVert b, const Style& style);
  void draw_window_line(const WinVert& a, const WinVert& b, const Style& style);
  void draw_line_rectangle(const WinVert& a, const WinVert& b, const Style& style);
  void draw_point(const ClipVert& v, const Style& style, float size);
  void draw_sample_point(const WinVert& v, const Style& style, float size);
  float point_size_of(const ClipVertex& v) const;  // derived, before rounding
  double polygon_offset(const std::vector<WinVert>& window, bool enabled) const;
  const WinVert* cached_window(const ClipVertex& v);
  const WinVert* cached_view_window(const ClipVertex& v);
  bool fill_cached_triangle(std::span<const ClipVertex* const> v, const ClipVertex& provoking);
  template <typename Vertex>
  bool fill_window_triangle(const Vertex* const (&w)[3], const ClipVertex& provoking);
  // fill_window_triangle's rectangles (rectangle_pair.h): true when w was held back or merged.
  template <typename Vertex>
  bool pair_into_rectangle(const Vertex* const (&w)[3], const ClipVertex& provoking);
  void emit_held_half();
  bool same_flat_color(const ClipVertex& a, const ClipVertex& b) const;
  // A front-facing filled triangle's setup into cached_prim_; false when it covers no pixel.
  template <typename Vertex>
  bool setup_filled_triangle(const Vertex& a, const Vertex& b, const Vertex& c, const ClipVertex& provoking);
  void use_back_varyings(ClipVert& v) const;
  void flatten_varyings(ClipVert& v, const ClipVertex& provoking) const;

  Scene& scene_;
  std::function<void()> on_full_;
  bool reference_ = false;
  bool active_ = false;
  ClipVolume volume_;
  PixelRect clip_rect_;
  WindowTransform transform_;
  float line_width_ = 1.f, point_size_ = 1.f;  // as set (derived for points), before rounding
  bool line_smooth_ = false, point_smooth_ = false;
  bool sample_points_ = false;    // multisampled points (draw_sample_point)
  bool rectangle_lines_ = false;  // multisampled lines (draw_line_rectangle)
  bool point_size_per_vertex_ = false;
  float stipple_count_ = 0.f;  // major-axis length of the strip's lines so far (line stipple)
  std::vector<ClipVert> in_, clipped_, scratch_;
  std::vector<WinVert> window_;

  WindowCache& window_cache_;
  size_t vertex_count_ = 0;
  ClipVert cache_clip_;  // the vertex being cached (large: not on the stack per call)
  // The cached triangles' setup, reused from triangle to triangle and draw to draw: a PrimSetup
  // is large, and only setup_triangle writes this one, every field a triangle reads each time
  // (the line, smooth and sample-point fields keep their defaults; planes past the draw's count
  // are not read).
  PrimSetup& cached_prim_;

  // Programmable draws (DrawState::shader)
  const ShaderDraw* shader_ = nullptr;
  const ClipVertex* vertex_base_ = nullptr;
  const float* varyings_ = nullptr;
  int varying_count_ = 0;
  const PreparedWindow* prepared_ = nullptr;
  // Filled triangles may pair into rectangles (single-sampled, not the reference path); held_ is
  // the last one when it is half of one and not yet in the scene.
  bool pairs_rectangles_ = false;
  // Halves held and not completed since the draw's last rectangle: a mesh of right triangles
  // whose values do not lie on one plane (a grid seen from above) stops holding them at
  // kUnpairedHalves (each hold copies three vertices).
  static constexpr int kUnpairedHalves = 16;
  int unpaired_ = 0;
  bool holding_ = false;
  RectangleHalf held_;
  const ClipVertex* held_provoking_ = nullptr;
  // GL_FLAT: the colour varyings (offset, count) that take the provoking vertex's values.
  std::vector<std::pair<int, int>> flat_ranges_;
  // The setup parameters of every front-facing filled triangle of the draw (fill_window_triangle),
  // made once: per triangle they were 3% of a dense mesh's time.
  SetupParams shader_fill_params_;
  // The primitive being set up: its varying planes, then one record {x, y, size} of a point
  // (gl_PointCoord), which the scene stores with it.
  std::vector<Plane>& varying_planes_;
};

}  // namespace pineda::raster
