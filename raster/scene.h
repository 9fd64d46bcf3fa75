// The deferred work for one framebuffer: draws, set-up primitives and clears, binned into
// 64x64 tiles; executed tile by tile, in command order within each tile.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "raster/clear.h"
#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"
#include "raster/zeroed_store.h"

namespace pineda::raster {

class WorkerPool;

enum class DrawRepeat { No, Whole, ButUniforms };

class Scene {
 public:
  // Drops everything queued and bins for `fb` from now on.
  void reset(const Framebuffer& fb);
  const Framebuffer& framebuffer() const { return fb_; }
  // The area primitives may cover: the framebuffer, limited to the largest rendered size (and to
  // the rows of limit_to_rows).
  PixelRect render_area() const {
    return tiles_x_ ? PixelRect{0, band_y0_, render_w_, band_y1_} : PixelRect{0, 0, 0, 0};
  }
  // Until the next reset, primitives are binned only where they cover rows [y0, y1)
  // (parallel_binning.h); y0 and y1 on tile edges or the render area's.
  void limit_to_rows(int y0, int y1) {
    band_y0_ = std::clamp(y0, 0, render_h_);
    band_y1_ = std::clamp(y1, band_y0_, render_h_);
  }

  // Primitives added afterwards belong to this draw. `made_from`: the DrawState make_draw_record
  // made the record from, for this scene's framebuffer, so that a later draw of the same state
  // may go on with the record (null: none may).
  void begin_draw(std::shared_ptr<const DrawRecord> draw, const DrawState* made_from = nullptr);
  const DrawRecord& current_draw() const { return *draws_.back(); }
  // Whether the current draw's record is the one make_draw_record would make for a draw of
  // `state` and `fades_points` (its other inputs, the framebuffer and the SIMD path, do not
  // change within a scene): its made_from had the same bytes (Whole). ButUniforms: a
  // programmable draw whose state differs only in its ShaderDraw, of the same program, facing and
  // colour output (its uniforms changed): the record make_draw_record would make is the current
  // one with `state.shader`, where a record depends on the ShaderDraw only through those.
  DrawRepeat repeat_of_current_draw(const DrawState& state, bool fades_points) const;
  // A programmable draw's primitives bring their varying planes (`count` of them, copied into
  // the scene with a primitive that touches a tile).
  void add_prim(const PrimSetup& prim, const Plane* varying_planes = nullptr, int count = 0);
  void add_clear(const ClearRecord& clear);

  bool empty() const { return commands_ == 0; }
  // True when the scene holds enough work that it should be executed now (memory bound).
  bool full() const;

  // Runs all commands; afterwards the scene is empty but keeps the current draw, so that a
  // draw interrupted by a full scene can go on adding primitives.
  void execute(WorkerPool& pool);
  // As execute, every tile on the calling thread, the framebuffer's cleared tiles already
  // prepared (prepare_cleared_tiles) for a scene that runs beside others.
  void execute_here();
  void prepare_cleared_tiles() const;
  // Between draws, after execute: lets the current draw's record go too, and the texture images
  // it keeps alive (a texture changed now can then be changed in place: TextureObject).
  void forget_draws() { draws_.clear(); }

  // Running while the calling thread goes on binning into another scene: start hands the
  // commands to the pool's threads (worth it only for a scene that is not small, with a pool that
  // has threads of its own); finish waits for them and empties the scene wholly (the other
  // scene goes on with the current draw: continue_draw). The scene must not move in between.
  bool worth_starting(const WorkerPool& pool) const;
  // Whether the queued primitives are small (their bounding boxes average under 64 pixels, no
  // clear among them), and whether such a scene is spread over threads all the same
  // (small_prim_sharing.h; default: no).
  bool small_prims() const;
  void share_small_prims(bool share) { share_small_prims_ = share; }
  size_t prim_count() const { return prim_count_; }
  // Whether binning asks ahead for the lines it will write (prefetch_for_write.h): worth it when
  // other threads read the scene's memory between its turns at binning; only where the CPU has
  // PREFETCHW.
  void prefetch_writes(bool ahead) { prefetch_writes_ = ahead; }
  void start(WorkerPool& pool);
  void finish(WorkerPool& pool);
  // The current draw of `from`, shared, so that a draw interrupted by a full scene goes on here.
  void continue_draw(const Scene& from);

 private:
  static constexpr uint32_t kClearBit = 0x80000000u;

  // Whether the commands are worth spreading over threads: not a small scene, nor one of small
  // primitives unless told to share them.
  bool worth_sharing() const;
  void run_tile(int tile) const;
  void order_for_threads();  // of touched_tiles_ (scene.cpp)
  // execute's end: drops the commands and every draw but the current one.
  void end_execution();
  void retain_textures(const DrawRecord& draw);
  // Drops the executed commands and what they kept alive; the draws stay.
  void drop_commands();

  Framebuffer fb_;
  int render_w_ = 0, render_h_ = 0;
  int band_y0_ = 0, band_y1_ = 0;  // render_area's rows
  int tiles_x_ = 0, tiles_y_ = 0;
  // Shared, and never changed once begun: the current draw's record stays where it is while a
  // draw that filled the scene goes on adding primitives, here or in the next scene, and the
  // pool's threads may read it while this goes on.
  std::deque<std::shared_ptr<const DrawRecord>> draws_;
  // The bytes of draws_.back()'s made_from, if it had one. Compared bitwise: cheaper than member
  // by member (which took an eighth of a one-triangle draw), exact for floats (a zero's sign), and
  // conservative (padding that differs only makes a new record). A pointer that compares equal
  // names the same object: the record keeps its objects alive.
  bool current_repeatable_ = false;
  std::array<unsigned char, sizeof(DrawState)> current_state_{};
  // Room for kMaxPrims records, in zeroed pages touched only as records are written (576 KiB a
  // scene: a program drawing a few primitives no longer first-touches all of it); the first
  // prim_count_ are queued, each holding only the planes its draw uses (a whole PrimSetup is
  // large: copying all of it took a tenth of small triangles).
  ZeroedStore<PrimSetup> prims_;
  size_t prim_count_ = 0;
  size_t bounded_pixels_ = 0;  // the queued primitives' bounding boxes' pixels, summed
  bool share_small_prims_ = false;
  bool prefetch_writes_ = false;
  std::vector<ClearRecord> clears_;
  std::vector<std::vector<uint32_t>> bins_;
  std::vector<int> touched_tiles_;
  size_t commands_ = 0;
  // The distinct texture images that queued draws keep alive (a program that creates, draws
  // with and deletes textures in a loop must not pile them up until the next flush).
  std::vector<const TextureImage*> retained_images_;
  size_t retained_texture_bytes_ = 0;
  // Varying planes of programmable primitives, in chunks that never move while queued.
  static constexpr size_t kPlaneChunk = 16384;
  std::vector<std::unique_ptr<Plane[]>> plane_chunks_;
  size_t planes_used_ = 0;  // in the last chunk
};

}  // namespace pineda::raster
