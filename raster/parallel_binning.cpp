#include "raster/parallel_binning.h"

#include <algorithm>
#include <exception>
#include <optional>

#include "raster/float_modes.h"
#include "raster/geometry.h"
#include "raster/raster_limits.h"
#include "raster/scene.h"
#include "raster/window_cache.h"
#include "raster/worker_pool.h"

namespace pineda::raster {

// One band's scene and what its geometry stage keeps from triangle to triangle.
struct ParallelBinning::Lane {
  alignas(64) Scene scene;  // (on lines of its own: the lanes are written on different threads)
  WindowCache window_cache;
  std::vector<Plane> varying_planes;
  PrimSetup filled_triangle;
  std::optional<GeometryStage> geometry;
  std::exception_ptr failure;  // what binning threw (std::bad_alloc), for the calling thread
};

ParallelBinning::ParallelBinning(int threads) {
  for (int i = 0; i < threads; ++i) lanes_.push_back(std::make_unique<Lane>());
}

ParallelBinning::~ParallelBinning() = default;

void ParallelBinning::reset(const Framebuffer& fb) {
  const int lanes = static_cast<int>(lanes_.size());
  const int rows = std::clamp(fb.height, 0, kMaxRenderSize);
  const int tile_rows = (rows + kTileSize - 1) / kTileSize;
  bands_ = std::min(lanes, tile_rows);
  for (int i = 0; i < lanes; ++i) {
    Lane& lane = *lanes_[static_cast<size_t>(i)];
    lane.geometry.reset();
    lane.scene.reset(fb);
    // Lane i: tile rows [i * tile_rows / bands, (i + 1) * tile_rows / bands).
    const int first = i < bands_ ? i * tile_rows / bands_ : tile_rows;
    const int end = i < bands_ ? (i + 1) * tile_rows / bands_ : tile_rows;
    lane.scene.limit_to_rows(first * kTileSize, std::min(end * kTileSize, rows));
  }
}

bool ParallelBinning::takes(const DrawState& state, const GeometryInput& input) const {
  const bool polygons = input.mode != Primitive::Points && input.mode != Primitive::Lines &&
                        input.mode != Primitive::LineLoop && input.mode != Primitive::LineStrip;
  return bands_ > 1 && polygons && input.count() >= kMinVertices && state.polygon_front == PolygonMode::Fill &&
         state.polygon_back == PolygonMode::Fill;
}

void ParallelBinning::draw(Scene& queued, const GeometryInput& input, WorkerPool& pool, unsigned float_modes) {
  queued.execute(pool);
  queued.prepare_cleared_tiles();  // here, not on the lanes' threads at once
  for (int i = 0; i < bands_; ++i) {
    Lane& l = *lanes_[static_cast<size_t>(i)];
    l.scene.continue_draw(queued);
    l.geometry.emplace(l.scene, l.window_cache, l.varying_planes, l.filled_triangle, [&l] { l.scene.execute_here(); });
    l.geometry->set_vertices(input.vertices);
    if (input.varyings) l.geometry->set_varyings(input.vertices.data(), input.varyings);
    if (input.windows) l.geometry->use_window_positions(input.windows);
  }
  pool.run(bands_, [&](int i) {
    Lane& l = *lanes_[static_cast<size_t>(i)];
    try {
      const ScopedFloatModes modes(float_modes);
      if (l.geometry->active()) {
        assemble_primitives(input.mode, input.vertices, input.indices, *l.geometry);
        l.geometry->finish_assembly();
      }
    } catch (...) {  // (nothing may leave a pool's thread) the draw ends where binning stopped
      l.failure = std::current_exception();
    }
    l.scene.execute_here();
  });
  std::exception_ptr failure;
  for (int i = 0; i < bands_; ++i) {
    Lane& l = *lanes_[static_cast<size_t>(i)];
    l.geometry.reset();
    l.scene.forget_draws();
    if (!failure) failure = l.failure;
    l.failure = nullptr;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace pineda::raster
