// The enable bits behind glEnable and glEnableClientState.
#pragma once
#include <GL/gl.h>

namespace pineda {

class Context;

// Whether `pname` (an enable or a glGet) is fixed-function state of the active texture unit
// that the unit, a texture image unit past MAX_TEXTURE_UNITS, does not have.
bool missing_texture_unit_state(const Context& ctx, GLenum pname);
// The flag for a server capability (glEnable) or null when `cap` is not one (or is one of a
// texture unit's and the active unit has no fixed-function state).
bool* server_capability(Context& ctx, GLenum cap);
// The flag for a client array (glEnableClientState) or null when `array` is not one.
bool* client_capability(Context& ctx, GLenum array);

// The same for fog, stipple, clip planes, texgen and the colour sum (vertex_extras_caps.cpp).
bool* vertex_extras_capability(Context& ctx, GLenum cap);
bool* vertex_extras_client_capability(Context& ctx, GLenum array);

}  // namespace pineda
