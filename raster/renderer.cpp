#include "raster/renderer.h"

#include "raster/clear.h"
#include "raster/draw_record.h"
#include "raster/geometry.h"
#include "raster/primitive.h"
#include "raster/scene.h"
#include "raster/worker_pool.h"

namespace pineda::raster {

struct Renderer::Impl {
  explicit Impl(int threads) : pool(resolve_thread_count(threads)) { scene.reset(fb); }
  Framebuffer fb;
  Scene scene;
  WorkerPool pool;
};

Renderer::Renderer(int threads) : impl_(std::make_unique<Impl>(threads)) {}

// Work still queued is dropped: the framebuffer's owner may already have released its memory.
Renderer::~Renderer() = default;

void Renderer::set_framebuffer(const Framebuffer& fb) {
  flush();
  impl_->fb = fb;
  impl_->scene.reset(fb);
}

const Framebuffer& Renderer::framebuffer() const { return impl_->fb; }

void Renderer::clear(const ClearState& clear) {
  ClearRecord record;
  if (!make_clear_record(clear, impl_->fb, record)) return;
  impl_->scene.add_clear(record);
  if (impl_->scene.full()) flush();
}

void Renderer::draw(const DrawState& state, Primitive mode, std::span<const ClipVertex> vertices,
                    std::span<const uint32_t> indices) {
  Scene& scene = impl_->scene;
  if (scene.render_area().empty() || vertices.empty()) return;
  scene.begin_draw(make_draw_record(state, impl_->fb));
  GeometryStage geometry(scene, [this] { flush(); });
  if (geometry.active()) assemble_primitives(mode, vertices, indices, geometry);
  if (scene.full()) flush();
}

void Renderer::flush() { impl_->scene.execute(impl_->pool); }

}  // namespace pineda::raster
