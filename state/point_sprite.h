// Point sprites (GL 2.0, ARB_point_sprite, OES_point_sprite): glTexEnv's COORD_REPLACE of the
// active unit. The enable is a capability (api_enable.cpp), POINT_SPRITE_COORD_ORIGIN a point
// parameter (point_parameters.cpp); all of it lives in DrawState::point_params.sprite.
#pragma once
#include <GL/gl.h>

namespace pineda {

class Context;

// glTexEnv(GL_POINT_SPRITE, pname, v): records the GL error when it is not COORD_REPLACE with
// TRUE or FALSE.
void set_point_sprite_env(Context& ctx, GLenum pname, GLfloat value);
// glGetTexEnv(GL_POINT_SPRITE, pname): false (and the error) when pname is not COORD_REPLACE.
bool get_point_sprite_env(Context& ctx, GLenum pname, GLfloat& value);

}  // namespace pineda
