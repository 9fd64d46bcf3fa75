// The deferred work for one framebuffer: draws, set-up primitives and clears, binned into
// 64x64 tiles; executed tile by tile, in command order within each tile.
#pragma once
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "raster/clear.h"
#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

class WorkerPool;

class Scene {
 public:
  // Drops everything queued and bins for `fb` from now on.
  void reset(const Framebuffer& fb);
  const Framebuffer& framebuffer() const { return fb_; }
  // The area primitives may cover: the framebuffer, limited to the largest rendered size.
  PixelRect render_area() const { return {0, 0, tiles_x_ ? render_w_ : 0, tiles_y_ ? render_h_ : 0}; }

  // Primitives added afterwards belong to this draw.
  void begin_draw(DrawRecord&& draw);
  const DrawRecord& current_draw() const { return draws_.back(); }
  void add_prim(const PrimSetup& prim);
  // A primitive of a programmable draw with its varying planes (copied into the scene).
  void add_prim(PrimSetup prim, const Plane* varying_planes, int count);
  void add_clear(const ClearRecord& clear);

  bool empty() const { return commands_ == 0; }
  // True when the scene holds enough work that it should be executed now (memory bound).
  bool full() const;

  // Runs all commands; afterwards the scene is empty but keeps the current draw, so that a
  // draw interrupted by a full scene can go on adding primitives.
  void execute(WorkerPool& pool);

 private:
  static constexpr uint32_t kClearBit = 0x80000000u;

  void run_tile(int tile) const;
  void retain_textures(const DrawRecord& draw);

  Framebuffer fb_;
  int render_w_ = 0, render_h_ = 0;
  int tiles_x_ = 0, tiles_y_ = 0;
  // A deque: dropping executed draws from the front keeps references to the current one valid
  // while a draw that filled the scene is still adding primitives.
  std::deque<DrawRecord> draws_;
  std::vector<PrimSetup> prims_;
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
