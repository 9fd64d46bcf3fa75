// Multisampled framebuffers (Framebuffer::samples > 1): each sample is a whole plane of every
// buffer. A primitive's coverage (edge functions) and depth are taken at each sample's position;
// each pixel any sample covers is then shaded once, at its centre, and every covered sample
// tested and written with that colour (sample_targets.h): shading once per pixel, as GL 1.5
// section 3.2.1 allows. Single-sampled framebuffers never reach this code.
#pragma once
#include <cstdint>

#include "raster/clear.h"
#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

// The standard 4x pattern (D3D's, Gallium's and so llvmpipe's), as offsets from the pixel
// centre in sub-pixels (1/256 px), y up: samples at (0.375, 0.125), (0.875, 0.375),
// (0.125, 0.625), (0.625, 0.875) of the pixel from its lower-left corner.
struct SampleOffset {
  int dx, dy;
};
constexpr SampleOffset kSampleOffsets4x[kMaxSamples] = {{-32, -96}, {96, -32}, {-96, 32}, {32, 96}};

// Whether a draw of `mode` into a multisampled framebuffer may draw points under
// POINT_FADE_THRESHOLD_SIZE (GL 1.4 section 3.3), whose fade its fragment routine then applies.
bool may_fade_points(const DrawState& state, Primitive mode);

// The view of one sample's plane: a single-sampled framebuffer.
Framebuffer sample_plane(const Framebuffer& fb, int sample);

// glSampleCoverage's mask (GL 1.5 4.1.3): the first round(value * samples) samples, inverted
// when asked; all samples when SAMPLE_COVERAGE is off.
uint32_t sample_coverage_mask(const MultisampleState& ms, int samples);

// A draw's record for sample `sample` when the draw needs one of its own (alpha to coverage
// becomes an alpha test per sample), otherwise `draw` itself.
const DrawRecord& sample_draw(const DrawRecord& draw, int sample);
// Makes the per-sample records of a draw into a multisampled framebuffer.
void prepare_sample_draws(DrawRecord& draw, const Framebuffer& fb, SimdPath path);

void apply_clear_samples(const ClearRecord& clear, const Framebuffer& fb, const PixelRect& tile);
// The primitive's samples in `tile`: the draw's sample_routine on each quad row, or (without
// one) its routine once per sample plane. Returns the samples that passed when counted.
uint64_t rasterize_samples_in_tile(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb,
                                   const PixelRect& tile);

// Averages the samples of pixel (x, y) into RGBA bytes: (sum + samples / 2) / samples.
void resolve_rgba8(const Framebuffer& fb, int x, int y, uint8_t out[4]);
// resolve_rgba8 of the n pixels from (x, y) rightwards, into out[4 * i] for pixel i.
void resolve_rgba8_row(const Framebuffer& fb, int x, int y, int n, uint8_t* out);
// Resolves every pixel of fb's colour planes into `out`, a single-sampled buffer of the same
// size and byte order (a multisampled window's back buffer, for swaps and reads).
void resolve_color(const Framebuffer& fb, const ColorBuffer& out);

}  // namespace pineda::raster
