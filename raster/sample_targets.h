// A multisampled draw shaded once per pixel (raster/multisample.h): what each sample then tests
// and writes, and the routine type that shades a quad row once for all samples.
#pragma once
#include <cstdint>

#include "raster/framebuffer.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

struct DrawRecord;

constexpr int kMaxSamples = 4;

// Per sample: its record (alpha to coverage gives each sample its own threshold), its setup
// (depth at the sample's position) and its plane of every buffer; null records for samples the
// draw leaves alone (glSampleCoverage).
struct SampleTargets {
  const DrawRecord* draw[kMaxSamples] = {};
  const PrimSetup* prim[kMaxSamples] = {};
  Framebuffer plane[kMaxSamples];
};

// Shades a row of `count` 2x2 quads once, at the pixel centres of the primitive `p`, quad k at
// (x + 2k, y), then runs the per-fragment operations of each sample: bits 4s to 4s + 3 of
// masks[k] are sample s's pixels of quad k (bit i: pixel (i & 1, i >> 1)). Returns the samples
// that passed the depth test when the draw counts them, 0 otherwise.
using SampleQuadRoutine = uint32_t (*)(const DrawRecord&, const PrimSetup& p, const SampleTargets&, int x, int y,
                                       int count, const uint16_t* masks);

// Sample s's pixels of a quad from its masks word.
inline unsigned sample_quad_mask(uint16_t masks, int s) { return (masks >> (4 * s)) & 0xfu; }
// The pixels any sample covers.
inline unsigned any_sample_mask(uint16_t masks) { return (masks | masks >> 4 | masks >> 8 | masks >> 12) & 0xfu; }

}  // namespace pineda::raster
