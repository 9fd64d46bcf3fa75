// Point sprites (GL 2.0 section 3.3, ARB_point_sprite, OES_point_sprite): a point drawn as a
// square of its exact size, whose texture coordinates run from 0 to 1 across it.
#pragma once
#include <cstdint>

#include "raster/prim_setup.h"

namespace pineda::raster {

struct PointSprite {
  bool enabled = false;
  bool origin_lower_left = false;  // POINT_SPRITE_COORD_ORIGIN; GL's default is UPPER_LEFT
  uint32_t coord_replace = 0;      // bit u: unit u's (s, t, r, q) become (s, t, 0, 1) across the point
};

struct DrawRecord;
struct SetupParams;
struct WinVert;

// The sprite coordinates as planes about the point's exact window position (the reference of
// the point's planes): s = 1/2 + (x_f + 1/2 - x_w) / size, t = 1/2 -+ (y_f + 1/2 - y_w) / size.
void sprite_coord_planes(float size, bool origin_lower_left, Plane& s, Plane& t);

// A point sprite of `size` pixels (kept to 1/256 pixel, at least one): the pixels whose centres
// lie in the square centred on the point, with the replaced units' coordinates. False when it
// covers no pixel.
bool setup_point_sprite(const WinVert& v, float size, const PointSprite& sprite, const DrawRecord& draw,
                        const SetupParams& params, PrimSetup& out);

// The replaced units' coordinates across a sprite of side `size` (pixels) whose planes are
// about the point's exact window position.
void replace_sprite_coords(float size, const PointSprite& sprite, const DrawRecord& draw, PrimSetup& out);

}  // namespace pineda::raster
