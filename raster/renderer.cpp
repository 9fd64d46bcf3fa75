#include "raster/renderer.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "raster/clear.h"
#include "raster/cleared_tiles.h"
#include "raster/draw_record.h"
#include "raster/float_modes.h"
#include "raster/fragment_pipeline.h"
#include "raster/geometry.h"
#include "raster/multisample.h"
#include "raster/parallel_binning.h"
#include "raster/prefetch_for_write.h"
#include "raster/primitive.h"
#include "raster/record_pool.h"
#include "raster/reference_lines_points.h"
#include "raster/reference_mode.h"
#include "raster/scene.h"
#include "raster/small_prim_sharing.h"
#include "raster/worker_pool.h"
#include "raster/zeroed_store.h"

namespace pineda::raster {

struct Renderer::Impl {
  explicit Impl(int threads, bool reference_mode, SimdPath simd_path)
      : reference(reference_mode),
        simd(simd_path),
        pool(reference ? 1 : resolve_thread_count(threads)),
        parallel_binning(pool.threads()) {
    scene.reset(fb);
    running.reset(fb);
    parallel_binning.reset(fb);
    // Each scene is read by the pool's threads between its turns at binning.
    const bool prefetch = pool.threads() > 1 && cpu_has_prefetchw();
    scene.prefetch_writes(prefetch);
    running.prefetch_writes(prefetch);
  }
  const bool reference;  // PINEDA_REFERENCE at creation: primitives drawn at once, per pixel
  const SimdPath simd;   // PINEDA_SIMD at creation
  // Waits for the running scene, if one runs, and empties it.
  void finish_running() {
    if (!running_started) return;
    running.finish(pool);
    running_started = false;
  }

  Framebuffer fb;
  // Each on cache lines of its own: the binning thread writes `scene`'s counters while the
  // pool's threads read `running` (sharing a line at their boundary cost glsl_skinned a sixth
  // of its time with two threads, depending on where the heap placed this object).
  alignas(64) Scene scene;    // binning
  alignas(64) Scene running;  // executed by the pool's threads while `scene` bins the next commands
  alignas(64) bool running_started = false;  // (the binning thread's: off `running`'s lines)
  // Scenes of small primitives: which way they go, and when the last one was handed off (a
  // scene's time runs from the previous hand-off of such a scene to its own; none at first and
  // after a flush).
  SmallPrimSharing small_prim_sharing;
  std::chrono::steady_clock::time_point last_small_hand_off;
  bool timing_small = false, last_small_shared = false;
  ZeroedStore<PreparedWindow> windows;  // room for a large draw's vertices
  RecordPoolHandle records = make_record_pool();  // Scene::begin_draw's
  WindowCache window_cache;  // the draws' post-transform cache (the binning thread's)
  std::vector<Plane> varying_planes;  // GeometryStage's
  PrimSetup filled_triangle;  // GeometryStage's
  std::optional<GeometryStage> geometry;  // the current draw record's (Renderer::draw)
  WorkerPool pool;  // after the scenes: its threads are joined before the scenes go
  ParallelBinning parallel_binning;  // (its threads are idle between its draws)
};

Renderer::Renderer(int threads) : impl_(std::make_unique<Impl>(threads, reference_mode_from_environment(), simd_path_from_environment())) {}

// Work still queued is dropped: the framebuffer's owner may already have released its memory.
// (A scene already started is finished: its owner flushes before releasing the memory, as
// Context does, so only a draw that filled a scene since can have started one.)
Renderer::~Renderer() { impl_->finish_running(); }

void Renderer::set_framebuffer(const Framebuffer& fb) {
  flush();
  impl_->fb = fb;
  impl_->geometry.reset();  // (the scene's draws go: no draw repeats)
  impl_->scene.reset(fb);
  impl_->running.reset(fb);
  impl_->parallel_binning.reset(fb);
}

const Framebuffer& Renderer::framebuffer() const { return impl_->fb; }

void Renderer::clear(const ClearState& clear) {
  ClearRecord record;
  if (!make_clear_record(clear, impl_->fb, record)) return;
  impl_->scene.add_clear(record);
  if (impl_->scene.full()) submit();
}

void Renderer::draw(const DrawState& state, Primitive mode, std::span<const ClipVertex> vertices,
                    std::span<const uint32_t> indices, const float* varyings) {
  Scene& scene = impl_->scene;
  if (scene.render_area().empty() || vertices.empty()) return;
  // A draw of the current draw's state (nothing changed since the last call) goes on with its
  // record: making and releasing one was a fifth of a one-triangle draw's time.
  const bool fades_points = impl_->fb.samples > 1 && may_fade_points(state, mode);
  const DrawRepeat repeat = scene.repeat_of_current_draw(state, fades_points);
  // Only the uniforms changed (a uniform set between draws): the current record with the draw's
  // ShaderDraw and the same geometry stage, without working the rest out again (making the
  // record and the stage was a tenth of glsl_many_draws' frame). Not where records are made
  // per sample or per draw buffer: those hold the ShaderDraw too.
  if (repeat == DrawRepeat::ButUniforms && impl_->fb.samples == 1 && impl_->fb.color_targets <= 1 &&
      !impl_->reference) {
    DrawRecord record = scene.current_draw();
    record.state.shader = state.shader;
    scene.begin_draw(make_pooled_record(impl_->records.get(), std::move(record)), &state);
    if (impl_->geometry) impl_->geometry->follow_new_uniforms();
  } else if (repeat != DrawRepeat::Whole) {
    DrawRecord record = make_draw_record(state, impl_->fb, impl_->simd, fades_points);
    if (impl_->fb.samples > 1) prepare_sample_draws(record, impl_->fb, impl_->simd);
    if (impl_->reference && !state.shader) {
      flush();  // queued clears first: reference primitives are drawn into the framebuffer at once
      record.routine = reference_plane_quads;
      record.sample_routine = nullptr;  // multisampled: the reference routine on each sample plane
    }
    scene.begin_draw(make_pooled_record(impl_->records.get(), std::move(record)), impl_->reference ? nullptr : &state);
    impl_->geometry.reset();
  }
  // Kept for the next draw while it repeats this draw's record or changes only its uniforms.
  if (!impl_->geometry)
    impl_->geometry.emplace(scene, impl_->window_cache, impl_->varying_planes, impl_->filled_triangle, [this] { submit(); },
                            impl_->reference);
  GeometryStage& geometry = *impl_->geometry;
  geometry.set_vertices(vertices);
  if (state.shader) geometry.set_varyings(vertices.data(), varyings);
  // A draw's window positions, ahead of assembly, in vector lanes and on every thread: a large
  // programmable draw's; a fixed-function draw's unless small (its vertices were all just
  // transformed anyway) or in reference mode.
  const bool ahead = state.shader ? vertices.size() >= kVerticesPerPiece
                                  : !impl_->reference && vertices.size() >= kFixedFunctionVerticesAhead;
  if (geometry.active() && ahead) {
    PreparedWindow* windows = impl_->windows.grow(vertices.size());
    for_each_piece(vertices.size(), kVerticesPerPiece,
                   [&](size_t begin, size_t end) { geometry.window_positions(begin, end, windows + begin, impl_->simd); });
    geometry.use_window_positions(windows);
  }
  if (geometry.active()) {
    const GeometryInput input{mode, vertices, indices, state.shader ? varyings : nullptr,
                              ahead ? impl_->windows.data() : nullptr};
    if (impl_->parallel_binning.takes(state, input)) {
      impl_->finish_running();
      impl_->parallel_binning.draw(scene, input, impl_->pool, ScopedFloatModes::current());
      return;
    }
    assemble_primitives(mode, vertices, indices, geometry);
    geometry.finish_assembly();
  }
  if (scene.full()) submit();
}

int Renderer::threads() const { return impl_->pool.threads(); }

void Renderer::for_each_piece(size_t count, size_t grain, FunctionRef<void(size_t, size_t)> fn) {
  if (count == 0) return;
  Impl& r = *impl_;
  if (r.running_started && r.pool.finished()) r.finish_running();
  grain = std::max<size_t>(grain, 1);
  const size_t grains = (count + grain - 1) / grain;
  if (r.pool.threads() == 1 || r.running_started || grains < 2) return fn(0, count);
  // A few pieces per thread, so that a thread the system delays holds up little.
  const size_t pieces = std::min(grains, static_cast<size_t>(r.pool.threads()) * 4);
  const size_t piece = (grains + pieces - 1) / pieces * grain;
  // Every piece computes as the caller alone would: under the caller's rounding and flushing.
  const unsigned caller_modes = ScopedFloatModes::current();
  r.pool.run(static_cast<int>((count + piece - 1) / piece), [&](int i) {
    const ScopedFloatModes modes(caller_modes);
    const size_t begin = static_cast<size_t>(i) * piece;
    fn(begin, std::min(count, begin + piece));
  });
}

void Renderer::flush() {
  flush_for_reading();
  if (impl_->fb.cleared_tiles) impl_->fb.cleared_tiles->forget();
}

void Renderer::flush_for_reading() {
  impl_->finish_running();
  impl_->timing_small = false;
  impl_->scene.share_small_prims(impl_->small_prim_sharing.share());
  impl_->scene.execute(impl_->pool);
  impl_->scene.forget_draws();
}

// A full scene runs on the pool's threads while this one bins the next (the two never run at
// once: a tile's commands keep their order); with no threads of its own, or a small scene, it
// runs now as flush runs it.
void Renderer::submit() {
  Impl& r = *impl_;
  r.finish_running();
  const bool small = r.pool.threads() > 1 && r.scene.small_prims();
  const bool share = r.small_prim_sharing.share();
  const size_t prims = r.scene.prim_count();
  r.scene.share_small_prims(share);
  // Runs after the scene is executed or started: the time of its hand-off goes to its way.
  auto time_small_scene = [&] {
    if (!small) {
      r.timing_small = false;
      return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (r.timing_small && r.last_small_shared == share)
      r.small_prim_sharing.record(share, std::chrono::duration<double, std::nano>(now - r.last_small_hand_off).count(), prims);
    r.last_small_hand_off = now;
    r.last_small_shared = share;
    r.timing_small = true;
  };
  if (!r.scene.worth_starting(r.pool)) {
    r.scene.execute(r.pool);
    time_small_scene();
    return;
  }
  std::swap(r.scene, r.running);  // the emptied scene bins on, with the current draw
  r.scene.continue_draw(r.running);
  r.running.start(r.pool);
  r.running_started = true;
  time_small_scene();
}

}  // namespace pineda::raster
