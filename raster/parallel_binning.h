// A large draw of filled polygons (triangles, strips, fans, quads) set up, binned and rasterized
// on every thread at once, each thread in a band of tile rows of its own: every thread takes all
// of the draw's primitives through the geometry stage, into a scene whose render area is its band
// (so set-up drops the triangles outside it at their bounding box), and runs that scene itself
// whenever it fills. Nothing a thread sets up is read by another core (handing small
// triangles' set-ups between cores cost more than rasterizing them on this project's VM:
// small_prim_sharing.h), and each tile still sees the draw's primitives in order. The set-ups
// and the decisions made along the draw (rectangle pairs: rectangle_pair.h) are the ones one
// thread makes; only the bounds are cut at the bands' edges, which lie on tile edges, where every
// primitive is cut anyway: the same image. Not lines or points: a line's stipple counts only the
// lines that cover a pixel of the clip rectangle (GeometryStage::draw_window_line).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "raster/band_split.h"
#include "raster/draw_state.h"
#include "raster/framebuffer.h"
#include "raster/vertex.h"
#include "raster/window_transform.h"

namespace pineda::raster {

class Scene;
class WorkerPool;

// What the geometry stage of a draw takes (Renderer::draw's arguments).
struct GeometryInput {
  Primitive mode = Primitive::Triangles;
  std::span<const ClipVertex> vertices;
  std::span<const uint32_t> indices;
  const float* varyings = nullptr;          // a programmable draw's
  const PreparedWindow* windows = nullptr;  // the window positions taken ahead, if they were
  size_t count() const { return indices.empty() ? vertices.size() : indices.size(); }
};

class ParallelBinning {
 public:
  // One lane per thread of the pool.
  explicit ParallelBinning(int threads);
  ~ParallelBinning();
  void reset(const Framebuffer& fb);

  // Whether the draw goes this way: with several threads and bands, polygons of at least
  // kMinVertices vertices (or indices) filled on both faces (no edges drawn as lines).
  bool takes(const DrawState& state, const GeometryInput& input) const;

  // Draws what `queued`'s current draw is, after running what `queued` holds (afterwards it holds
  // only the current draw). Geometry runs under `float_modes` (the calling thread's) everywhere.
  void draw(Scene& queued, const GeometryInput& input, WorkerPool& pool, unsigned float_modes);

 private:
  // Smaller draws keep binning on the calling thread while the others run full scenes (a choice,
  // not tuned: small_tris' and glsl_skinned's draws are far above it, glsl_many_draws' far below).
  static constexpr size_t kMinVertices = 3 * 4096;
  struct Lane;
  std::vector<std::unique_ptr<Lane>> lanes_;
  int pixel_rows_ = 0;         // the framebuffer's rendered rows
  BandSplit split_;            // lane i draws in band i
  std::vector<double> times_;  // each band's time in the draw (s)
};

}  // namespace pineda::raster
