// The parameters whose GLfixed value is an enum (or a boolean) rather than a 16.16 number:
// the GLfixed calls pass those values as they are (OpenGL ES 1.1, as Mesa does).
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

namespace pineda::es1 {

inline bool fog_param_is_enum(GLenum pname) { return pname == GL_FOG_MODE; }

inline bool light_model_param_is_enum(GLenum pname) { return pname == GL_LIGHT_MODEL_TWO_SIDE; }

inline bool tex_env_param_is_enum(GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: case GL_COMBINE_RGB: case GL_COMBINE_ALPHA:
    case GL_SRC0_RGB: case GL_SRC1_RGB: case GL_SRC2_RGB:
    case GL_SRC0_ALPHA: case GL_SRC1_ALPHA: case GL_SRC2_ALPHA:
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB:
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA:
    case GL_COORD_REPLACE:
      return true;
    default: return false;
  }
}

// Every texture parameter of ES 1.1 (filters, wraps, GENERATE_MIPMAP, the crop rectangle).
inline bool tex_parameter_is_enum(GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: case GL_TEXTURE_MAG_FILTER: case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T: case GL_GENERATE_MIPMAP: case 0x8B9D /* GL_TEXTURE_CROP_RECT_OES */:
      return true;
    default: return false;
  }
}

}  // namespace pineda::es1
