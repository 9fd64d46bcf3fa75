// Name checks shared by the shader and program entry points (GL 2.0 2.15): a name that is
// neither kind is INVALID_VALUE, a name of the other kind INVALID_OPERATION.
#pragma once
#include <GL/gl.h>

#include <string>

#include "state/context.h"

namespace pineda {

ShaderObject* shader_or_error(Context& ctx, GLuint name);
ProgramObject* program_or_error(Context& ctx, GLuint name);

// glGet*InfoLog / glGetShaderSource: copies at most bufSize - 1 characters and a NUL.
void copy_string_out(const std::string& s, GLsizei buf_size, GLsizei* length, GLchar* out);
// The length those queries report: with the terminating NUL; an empty string reports 0.
inline GLint length_with_nul(const std::string& s) { return s.empty() ? 0 : static_cast<GLint>(s.size() + 1); }

}  // namespace pineda
