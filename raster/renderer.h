// The pipeline below the API, one per context: primitive assembly, clipping, setup,
// binning into tiles, and the deferred tile rasterization on worker threads.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "raster/draw_state.h"
#include "raster/framebuffer.h"
#include "raster/function_ref.h"
#include "raster/vertex.h"

namespace pineda::raster {

class Scene;
class WorkerPool;

class Renderer {
 public:
  // threads == 0: PINEDA_THREADS if set, otherwise one per core. PINEDA_REFERENCE=1 (read here)
  // selects the reference mode (reference_mode.h): one thread, exact per-pixel rasterization;
  // PINEDA_SIMD=baseline the baseline copy of the fragment routines (simd_path.h).
  explicit Renderer(int threads = 0);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Completes pending work on the previous framebuffer, then renders into this one.
  void set_framebuffer(const Framebuffer& fb);
  const Framebuffer& framebuffer() const;

  void clear(const ClearState& clear);

  // Assembles `mode` primitives from `vertices` (in order, or through `indices` when it is
  // not empty; an index past the end of `vertices` drops its primitive), clips, sets up and
  // bins them. Nothing of `state` or the spans is referenced after the call returns.
  // A programmable draw (state.shader) passes the vertex shader's varyings too: vertex i's
  // at varyings[i * program->varying_floats()].
  void draw(const DrawState& state, Primitive mode, std::span<const ClipVertex> vertices,
            std::span<const uint32_t> indices = {}, const float* varyings = nullptr);

  // Calls fn(begin, end) on pieces that cover [0, count), each a multiple of `grain` long but
  // the last: spread over the pool's threads when none of them is rendering a scene and there
  // are at least two pieces, otherwise at once on this thread. For per-element work whose
  // results do not depend on the pieces (the vertex stages); fn must be safe to run in parallel.
  void for_each_piece(size_t count, size_t grain, FunctionRef<void(size_t, size_t)> fn);
  // The threads that render (the calling one included).
  int threads() const;
  // The grain of the vertex stages: big enough that a piece costs far more than handing it to
  // a thread; a multiple of the vertices one vertex-shader run takes.
  static constexpr size_t kVerticesPerPiece = 1024;
  // Fixed-function draws of at least this many vertices take their window positions ahead.
  static constexpr size_t kFixedFunctionVerticesAhead = 64;

  // Executes everything queued; afterwards the framebuffer's memory is up to date, and the
  // caller may write it (which tiles hold a clear's value is forgotten: cleared_tiles.h).
  void flush();
  // As flush, for a caller that only reads the framebuffer's memory afterwards (glFinish, a
  // swap, glReadPixels): what is known of cleared tiles is kept.
  void flush_for_reading();

 private:
  void submit();  // a full scene: executed, on the pool's threads while binning goes on

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pineda::raster
