// glPopAttrib for fog, clip planes, texgen, stipple and secondary colour state.
#pragma once

namespace pineda {

class Context;
struct AttribFrame;

// Restores the groups of frame.mask that hold this state (CURRENT, FOG, LINE, POLYGON,
// POLYGON_STIPPLE, TRANSFORM, TEXTURE, ENABLE).
void restore_vertex_extras(Context& ctx, const AttribFrame& frame);

}  // namespace pineda
