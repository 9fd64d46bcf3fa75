#include "raster/parallel_binning.h"

#include <algorithm>
#include <chrono>
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
  pixel_rows_ = std::clamp(fb.height, 0, kMaxRenderSize);
  const int tile_rows = (pixel_rows_ + kTileSize - 1) / kTileSize;
  split_.reset(tile_rows, std::min(static_cast<int>(lanes_.size()), tile_rows));
  for (auto& lane : lanes_) {
    lane->geometry.reset();
    lane->scene.reset(fb);
  }
}

bool ParallelBinning::takes(const DrawState& state, const GeometryInput& input) const {
  const bool polygons = input.mode != Primitive::Points && input.mode != Primitive::Lines &&
                        input.mode != Primitive::LineLoop && input.mode != Primitive::LineStrip;
  return split_.bands() > 1 && polygons && input.count() >= kMinVertices && state.polygon_front == PolygonMode::Fill &&
         state.polygon_back == PolygonMode::Fill;
}

void ParallelBinning::draw(Scene& queued, const GeometryInput& input, WorkerPool& pool, unsigned float_modes) {
  queued.execute(pool);
  queued.prepare_cleared_tiles();  // here, not on the lanes' threads at once
  const int bands = split_.bands();
  for (int i = 0; i < bands; ++i) {
    Lane& l = *lanes_[static_cast<size_t>(i)];
    l.scene.limit_to_rows(split_.first(i) * kTileSize, std::min(split_.end(i) * kTileSize, pixel_rows_));
    l.scene.continue_draw(queued);
    l.geometry.emplace(l.scene, l.window_cache, l.varying_planes, l.filled_triangle, [&l] { l.scene.execute_here(); });
    l.geometry->set_vertices(input.vertices);
    if (input.varyings) l.geometry->set_varyings(input.vertices.data(), input.varyings);
    if (input.windows) l.geometry->use_window_positions(input.windows);
  }
  times_.assign(static_cast<size_t>(bands), 0.0);
  pool.run(bands, [&](int i) {
    const auto start = std::chrono::steady_clock::now();
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
    times_[static_cast<size_t>(i)] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  split_.record(times_);
  std::exception_ptr failure;
  for (int i = 0; i < bands; ++i) {
    Lane& l = *lanes_[static_cast<size_t>(i)];
    l.geometry.reset();
    l.scene.forget_draws();
    if (!failure) failure = l.failure;
    l.failure = nullptr;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace pineda::raster
