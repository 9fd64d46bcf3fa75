#include "raster/scene.h"

#include <algorithm>
#include <cstring>

#include "raster/cleared_tiles.h"
#include "raster/float_modes.h"
#include "raster/multisample.h"
#include "raster/prefetch_for_write.h"
#include "raster/raster_limits.h"
#include "raster/shader_draw.h"
#include "raster/shader_quads.h"
#include "raster/tile_raster.h"
#include "raster/worker_pool.h"

namespace pineda::raster {
namespace {

// A PrimSetup is about 560 bytes: 1024 of them (560 KiB) are still in the L2 cache when the
// tiles read them back; at 65536 (36 MiB) binning and rasterizing small triangles both waited
// on memory (small_tris: 340 -> 205 ms per frame, one thread).
constexpr size_t kMaxPrims = size_t{1} << 10;
// A new scene's room for primitives, grown to kMaxPrims when it fills: a frame of a few large
// primitives writes one small page of records, not a huge one (on this kind of VM the first
// touch of a huge page at times costs what its 512 small pages would: texture_upload's first
// frame 5.1 -> 4.1 ms, one thread).
constexpr size_t kFirstPrims = 64;
constexpr size_t kMaxCommands = size_t{1} << 22;
constexpr size_t kMaxDraws = 4096;
constexpr size_t kMaxRetainedTextureBytes = size_t{256} << 20;
constexpr size_t kMaxPlaneChunks = 64;  // 12 MiB of varying planes
// Below this many binned commands the calling thread does the work alone.
constexpr size_t kSmallScene = 64;
// Primitives whose bounding boxes cover fewer pixels than this on average are small
// (small_prims): handing them to another core may cost more than rasterizing them
// (small_prim_sharing.h). At 32, glsl_many_draws' triangles (boxes of 36 pixels) were always
// shared, and ran in 29 ms a frame with two threads against 20 with one.
constexpr size_t kSharedPixelsPerPrim = 64;

}  // namespace

void Scene::reset(const Framebuffer& fb) {
  fb_ = fb;
  render_w_ = std::clamp(fb.width, 0, kMaxRenderSize);
  render_h_ = std::clamp(fb.height, 0, kMaxRenderSize);
  band_y0_ = 0;
  band_y1_ = render_h_;
  tiles_x_ = (render_w_ + kTileSize - 1) / kTileSize;
  tiles_y_ = (render_h_ + kTileSize - 1) / kTileSize;
  if (tiles_x_ == 0 || tiles_y_ == 0) tiles_x_ = tiles_y_ = 0;
  draws_.clear();
  prims_.grow(kFirstPrims);
  prim_count_ = 0;
  bounded_pixels_ = 0;
  clears_.clear();
  bins_.assign(static_cast<size_t>(tiles_x_) * tiles_y_, {});
  touched_tiles_.clear();
  commands_ = 0;
  retained_images_.clear();
  retained_texture_bytes_ = 0;
  plane_chunks_.clear();
  planes_used_ = 0;
}

DrawRepeat Scene::repeat_of_current_draw(const DrawState& state, bool fades_points) const {
  if (!current_repeatable_ || draws_.empty() || draws_.back()->fades_points != fades_points) return DrawRepeat::No;
  // The bytes before and after the shader's pointer, then the pointer.
  const auto* bytes = reinterpret_cast<const unsigned char*>(&state);
  const size_t at = static_cast<size_t>(reinterpret_cast<const unsigned char*>(&state.shader) - bytes);
  const size_t after = at + sizeof state.shader;
  if (std::memcmp(current_state_.data(), bytes, at) != 0 ||
      std::memcmp(current_state_.data() + after, bytes + after, sizeof(DrawState) - after) != 0)
    return DrawRepeat::No;
  if (std::memcmp(current_state_.data() + at, bytes + at, sizeof state.shader) == 0) return DrawRepeat::Whole;
  const ShaderDraw* current = draws_.back()->state.shader.get();
  const ShaderDraw* next = state.shader.get();
  return current && next && current->program == next->program && current->two_side == next->two_side &&
                 current->color_output == next->color_output
             ? DrawRepeat::ButUniforms
             : DrawRepeat::No;
}

void Scene::begin_draw(std::shared_ptr<const DrawRecord> draw, const DrawState* made_from) {
  draws_.push_back(std::move(draw));
  current_repeatable_ = made_from != nullptr;
  if (made_from) std::memcpy(current_state_.data(), static_cast<const void*>(made_from), sizeof(DrawState));
  retain_textures(*draws_.back());
}

void Scene::retain_textures(const DrawRecord& draw) {
  for (int k = 0; k < draw.num_units; ++k) {
    const TextureImage* image = draw.state.texture_units[draw.units[k]].image.get();
    if (!image || std::find(retained_images_.begin(), retained_images_.end(), image) != retained_images_.end())
      continue;
    retained_images_.push_back(image);
    for (const TextureLevel& level : image->levels) retained_texture_bytes_ += level.texels.size() * sizeof(level.texels[0]);
  }
}

namespace {

// How many primitives ahead add_prim asks for the lines it will write (prefetch_for_write.h).
constexpr size_t kWriteAhead = 6;

// The first `bytes` of `from` into `to`, in whole 16-byte pieces (sizeof(PrimSetup) is a
// multiple of 16): vector moves, where a memcpy of a variable size became `rep movs` here, whose
// start-up cost per primitive was most of add_prim's time.
void copy_prim(PrimSetup& to, const PrimSetup& from, size_t bytes) {
  static_assert(sizeof(PrimSetup) % 16 == 0);
  const size_t n = std::min((bytes + 15) & ~size_t{15}, sizeof(PrimSetup));
  auto* out = reinterpret_cast<unsigned char*>(&to);
  const auto* in = reinterpret_cast<const unsigned char*>(&from);
  size_t i = 0;
  for (; i + 64 <= n; i += 64) std::memcpy(out + i, in + i, 64);
  for (; i < n; i += 16) std::memcpy(out + i, in + i, 16);
}

}  // namespace

void Scene::add_prim(const PrimSetup& prim, const Plane* varying_planes, int count) {
  const PixelRect r = intersect(prim.bounds, render_area());
  if (r.empty() || draws_.empty()) return;
  const uint32_t index = static_cast<uint32_t>(prim_count_);
  bool used = false;
  // A triangle inside one tile goes to it untested: the test over its bounds almost never fails
  // (a dense mesh's triangles: it was 2.6% of glsl_skinned), and one that covers no pixel centre
  // there gives no fragment.
  const bool one_tile =
      (r.x0 >> kTileShift) == ((r.x1 - 1) >> kTileShift) && (r.y0 >> kTileShift) == ((r.y1 - 1) >> kTileShift);
  for (int ty = r.y0 >> kTileShift; ty <= (r.y1 - 1) >> kTileShift; ++ty)
    for (int tx = r.x0 >> kTileShift; tx <= (r.x1 - 1) >> kTileShift; ++tx) {
      // Coverage tests at pixel centres; a multisampled triangle may cover only samples of a tile.
      if (prim.kind == CoverageKind::Triangle && fb_.samples == 1 && !one_tile) {
        const PixelRect tile{tx * kTileSize, ty * kTileSize, (tx + 1) * kTileSize, (ty + 1) * kTileSize};
        if (!triangle_may_touch(prim, intersect(tile, r))) continue;
      }
      std::vector<uint32_t>& bin = bins_[static_cast<size_t>(ty) * tiles_x_ + tx];
      if (bin.empty()) touched_tiles_.push_back(ty * tiles_x_ + tx);
      bin.push_back(index);
      ++commands_;
      used = true;
    }
  if (!used) return;
  // (Lines and points cost more per pixel than triangles: wireframe ran faster shared.)
  const size_t pixels = static_cast<size_t>(r.x1 - r.x0) * static_cast<size_t>(r.y1 - r.y0);
  bounded_pixels_ += prim.kind == CoverageKind::Triangle ? pixels : std::max(pixels, kSharedPixelsPerPrim);
  if (prim_count_ == prims_.capacity()) prims_.grow(std::max(kMaxPrims, prims_.capacity() + kFirstPrims));
  const size_t bytes = used_bytes(std::clamp(draws_.back()->planes, 0, kMaxPlanes));
  if (prefetch_writes_ && prim_count_ + kWriteAhead < prims_.capacity())
    prefetch_for_write(&prims_.data()[prim_count_ + kWriteAhead], bytes);
  PrimSetup& stored = prims_.data()[prim_count_++];
  copy_prim(stored, prim, bytes);
  stored.draw = static_cast<uint32_t>(draws_.size() - 1);
  if (count <= 0) return;
  const size_t n = static_cast<size_t>(count);
  if (plane_chunks_.empty() || planes_used_ + n > kPlaneChunk) {
    plane_chunks_.push_back(std::make_unique<Plane[]>(kPlaneChunk));
    planes_used_ = 0;
  }
  Plane* dst = plane_chunks_.back().get() + planes_used_;
  if (prefetch_writes_ && planes_used_ + (kWriteAhead + 1) * n <= kPlaneChunk)
    prefetch_for_write(dst + kWriteAhead * n, n * sizeof(Plane));
  std::copy(varying_planes, varying_planes + n, dst);
  planes_used_ += n;
  stored.varying_planes = dst;
}

void Scene::add_clear(const ClearRecord& clear) {
  const PixelRect r = intersect(clear.rect, render_area());
  if (r.empty()) return;
  const uint32_t index = static_cast<uint32_t>(clears_.size()) | kClearBit;
  clears_.push_back(clear);
  for (int ty = r.y0 >> kTileShift; ty <= (r.y1 - 1) >> kTileShift; ++ty)
    for (int tx = r.x0 >> kTileShift; tx <= (r.x1 - 1) >> kTileShift; ++tx) {
      std::vector<uint32_t>& bin = bins_[static_cast<size_t>(ty) * tiles_x_ + tx];
      if (bin.empty()) touched_tiles_.push_back(ty * tiles_x_ + tx);
      bin.push_back(index);
      ++commands_;
    }
}

bool Scene::full() const {
  return prim_count_ >= kMaxPrims || commands_ >= kMaxCommands || clears_.size() >= kMaxPrims ||
         draws_.size() >= kMaxDraws || retained_texture_bytes_ >= kMaxRetainedTextureBytes ||
         plane_chunks_.size() >= kMaxPlaneChunks;
}

void Scene::run_tile(int tile) const {
  // The application's modes on its own thread would make a tile it takes differ from one a
  // worker takes: every tile computes under the default modes, except that a programmable
  // draw's commands run under the shaders' modes, set once for each run of them rather than by
  // every shader run (its MXCSR writes took 2-3% of the shader scenes).
  ScopedFloatModes modes(kDefaultFloatModes);
  bool shader_modes = false;
  auto use_shader_modes = [&](bool on) {
    if (on != shader_modes) modes.set(on ? kShaderFloatModes : kDefaultFloatModes);
    shader_modes = on;
  };
  const int tx = tile % tiles_x_, ty = tile / tiles_x_;
  const PixelRect rect = intersect({tx * kTileSize, ty * kTileSize, (tx + 1) * kTileSize, (ty + 1) * kTileSize},
                                   render_area());
  const bool multisampled = fb_.samples > 1;
  ClearedTile* known = fb_.cleared_tiles && !multisampled && fb_.color_targets == 1
                           ? &fb_.cleared_tiles->tile(static_cast<size_t>(tile))
                           : nullptr;
  // Consecutive primitives of a programmable draw share shader blocks (shader_quads.h).
  ShaderQuadBatch batch;
  auto flush = [&] {
    if (const DrawRecord* draw = batch.draw())
      if (const uint32_t passed = batch.flush()) draw->state.sample_counter->passed.fetch_add(passed, std::memory_order_relaxed);
  };
  for (const uint32_t cmd : bins_[tile]) {
    if (cmd & kClearBit) {
      flush();
      use_shader_modes(false);
      const ClearRecord& clear = clears_[cmd & ~kClearBit];
      if (multisampled) {
        apply_clear_samples(clear, fb_, rect);
      } else if (known) {
        ClearRecord left = clear;
        skip_cleared_buffers(left, rect, *known);
        apply_clear(left, fb_, rect);
      } else {
        apply_clear(clear, fb_, rect);
      }
    } else {
      if (known) *known = {};  // whatever the primitive writes
      const PrimSetup& prim = prims_.data()[cmd];
      const DrawRecord& draw = *draws_[prim.draw];
      if (&draw != batch.draw()) flush();
      use_shader_modes(draw.state.shader != nullptr);
      const uint64_t passed =
          multisampled ? rasterize_samples_in_tile(prim, draw, fb_, rect)
                       : rasterize_in_tile(prim, draw, fb_, rect, ShaderQuadBatch::takes(draw) ? &batch : nullptr);
      if (passed) draw.state.sample_counter->passed.fetch_add(passed, std::memory_order_relaxed);
    }
  }
  flush();
}

void Scene::execute(WorkerPool& pool) {
  if (commands_ > 0) {
    prepare_cleared_tiles();
    if (!worth_sharing()) {
      for (const int t : touched_tiles_) run_tile(t);
    } else {
      order_for_threads();
      pool.run(static_cast<int>(touched_tiles_.size()), [this](int i) { run_tile(touched_tiles_[i]); });
    }
  }
  end_execution();
}

void Scene::execute_here() {
  for (const int t : touched_tiles_) run_tile(t);
  end_execution();
}

void Scene::prepare_cleared_tiles() const {
  if (fb_.cleared_tiles) fb_.cleared_tiles->prepare(bins_.size());
}

void Scene::end_execution() {
  drop_commands();
  if (draws_.size() > 1) draws_.erase(draws_.begin(), draws_.end() - 1);
  if (!draws_.empty()) retain_textures(*draws_.back());
}

// Threads take tiles in this order, one after another: the even columns, then the odd ones,
// so that tiles rendered at the same time are not side by side. Side-by-side tiles share a cache
// line at each row's edges unless the rows start on lines (an OSMesa buffer the application
// allocated, a width that is not a multiple of 16 pixels): overdraw at 1000x768, two threads,
// ran no faster than one. Each tile's commands keep their order, so the image is the same.
void Scene::order_for_threads() {
  const int tiles_x = tiles_x_;
  std::sort(touched_tiles_.begin(), touched_tiles_.end(), [tiles_x](int a, int b) {
    const int ka = (a % tiles_x & 1) * (1 << 30) + a, kb = (b % tiles_x & 1) * (1 << 30) + b;
    return ka < kb;
  });
}

bool Scene::small_prims() const { return clears_.empty() && bounded_pixels_ < kSharedPixelsPerPrim * prim_count_; }

bool Scene::worth_sharing() const { return commands_ >= kSmallScene && (share_small_prims_ || !small_prims()); }

bool Scene::worth_starting(const WorkerPool& pool) const { return worth_sharing() && pool.threads() > 1; }

void Scene::start(WorkerPool& pool) {
  prepare_cleared_tiles();
  order_for_threads();
  pool.start(static_cast<int>(touched_tiles_.size()), [this](int i) { run_tile(touched_tiles_[i]); });
}

void Scene::finish(WorkerPool& pool) {
  pool.wait();
  drop_commands();
  draws_.clear();
}

void Scene::continue_draw(const Scene& from) {
  if (from.draws_.empty()) return;
  draws_.push_back(from.draws_.back());
  current_repeatable_ = from.current_repeatable_;
  current_state_ = from.current_state_;
  retain_textures(*draws_.back());
}

void Scene::drop_commands() {
  for (const int t : touched_tiles_) bins_[t].clear();
  touched_tiles_.clear();
  prim_count_ = 0;
  bounded_pixels_ = 0;
  clears_.clear();
  commands_ = 0;
  retained_images_.clear();
  retained_texture_bytes_ = 0;
  if (plane_chunks_.size() > 1) plane_chunks_.erase(plane_chunks_.begin(), plane_chunks_.end() - 1);
  planes_used_ = 0;
}

}  // namespace pineda::raster
