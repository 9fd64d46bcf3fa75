// The pixel-transfer operations of GL 1.5 spec 3.6.5, applied wherever pixels move between
// client memory and the framebuffer (DrawPixels, CopyPixels, ReadPixels).
#pragma once
#include <cstdint>

#include "state/pixels/pixel_state.h"

namespace pineda {

// Scale and bias, then the R_TO_R.. maps when MAP_COLOR is on; the result is clamped to [0, 1].
void transfer_color(const PixelMode& mode, const PixelMaps& maps, float rgba[4]);
// Whether transfer_color changes nothing but clamping.
bool color_transfer_is_identity(const PixelMode& mode);
// Depth scale and bias, clamped to [0, 1].
double transfer_depth(const PixelMode& mode, double depth);
// Index shift and offset, then S_TO_S when MAP_STENCIL is on.
int64_t transfer_stencil(const PixelMode& mode, const PixelMaps& maps, int64_t index);
// A colour index in RGBA mode: shift and offset, then the I_TO_R.. maps (always applied).
void index_to_rgba(const PixelMode& mode, const PixelMaps& maps, int64_t index, float rgba[4]);

}  // namespace pineda
