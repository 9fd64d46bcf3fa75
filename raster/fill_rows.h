// Fill routines for the most common fixed-function draws: untextured or one texture unit
// MODULATEd or REPLACEd in lanes (DrawRecord::texture_in_lanes, bilinear or nearest; then
// without stencil or a sample count), no alpha test, fog, colour sum, stipple or smoothing, a
// stencil test or none, a depth test or none, no blending or one of blend8.h's integer blends
// (SRC_ALPHA / ONE_MINUS_SRC_ALPHA with anything; the additive SRC_ALPHA / ONE and ONE / ONE
// without stencil or a sample count). A row of 2x2 quads is shaded 8x2 pixels (16 lanes) at a
// time, each pixel row as one 8-lane vector, stencil and depth tested and written in those
// lanes; the pixels and stencil values are the same, bit for bit, as the generic quad routines'
// (fragment_pipeline.cpp).
#pragma once

#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/simd_path.h"

namespace pineda::raster {

// The fill routine for the draw, or null when its key needs the generic one.
QuadRoutine select_fill_routine(const DrawRecord& d, const Framebuffer& fb, SimdPath path = SimdPath::Best);

}  // namespace pineda::raster
