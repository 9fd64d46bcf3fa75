// The fragment stage of a programmable draw: the draw's fragment shader over up to four 2x2
// quads of a row at a time (one 16-lane shader::FragmentBlock), then the same per-fragment
// operations as fixed function.
#pragma once
#include <cstdint>

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

}  // namespace pineda::raster
