// The fragment stage of a programmable draw: the draw's fragment shader over up to four 2x2
// quads of a row at a time (one 16-lane shader::FragmentBlock), then the same per-fragment
// operations as fixed function.
#pragma once
#include <cstdint>
#include <memory>

#include "raster/draw_record.h"

namespace pineda::raster {

// A QuadRoutine (draw_record.h) for draws whose DrawState::shader is set.
uint32_t shade_program_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                             const uint8_t* masks);
// The same for a framebuffer with several draw buffers (Framebuffer::color_targets > 1): one run
// of the shader, gl_FragData[i] into draw buffer i, depth and stencil once.
uint32_t shade_program_target_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y,
                                    int count, const uint8_t* masks);

// The SampleQuadRoutines (sample_targets.h) of the two: the shader runs once per pixel of a
// multisampled draw, and each sample's coverage and depth decide what it writes in its plane.
uint32_t shade_program_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x, int y,
                                    int count, const uint16_t* masks);
uint32_t shade_program_target_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x,
                                           int y, int count, const uint16_t* masks);

// The quads of consecutive primitives of one draw taken by shade_program_quads, packed into full
// shader blocks across rows and primitives (a small triangle covers a quad or two; shaded alone,
// most of its block's lanes idle), with the same results as shading each row when it comes.
// A tile's commands go through one batch; flush before anything else touches the buffers.
class ShaderQuadBatch {
 public:
  ShaderQuadBatch();
  ~ShaderQuadBatch();
  ShaderQuadBatch(const ShaderQuadBatch&) = delete;
  ShaderQuadBatch& operator=(const ShaderQuadBatch&) = delete;

  // Whether the draw's rows may come here (its routine is shade_program_quads).
  static bool takes(const DrawRecord& d);
  // The draw whose quads wait, or null.
  const DrawRecord* draw() const;
  // A row of quads as a QuadRoutine takes it. Another draw's quads waiting are flushed first.
  void add_row(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
               const uint8_t* masks);
  // Shades, tests and writes what waits; returns the samples that passed (of draw(), when it
  // counts them). The primitives and framebuffer added must live until then.
  uint32_t flush();

 private:
  struct Blocks;
  std::unique_ptr<Blocks> blocks_;
};

}  // namespace pineda::raster
