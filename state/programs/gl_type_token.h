// shader::Type as the GL type token glGetActiveUniform and glGetActiveAttrib report.
#pragma once
#include <GL/gl.h>

#include "shader/program.h"

namespace pineda {

GLenum gl_type_token(const shader::Type& type);

}  // namespace pineda
