#include "state/programs/program_lookup.h"

#include <algorithm>
#include <cstring>

namespace pineda {

ShaderObject* shader_or_error(Context& ctx, GLuint name) {
  if (ShaderObject* s = ctx.programs.objects.shader(name)) return s;
  if (ctx.programs.objects.program(name)) ctx.record_error(GL_INVALID_OPERATION, "shader is a program object");
  else ctx.record_error(GL_INVALID_VALUE, "shader is not a shader or program object");
  return nullptr;
}

ProgramObject* program_or_error(Context& ctx, GLuint name) {
  if (ProgramObject* p = ctx.programs.objects.program(name)) return p;
  if (ctx.programs.objects.shader(name)) ctx.record_error(GL_INVALID_OPERATION, "program is a shader object");
  else ctx.record_error(GL_INVALID_VALUE, "program is not a shader or program object");
  return nullptr;
}

void copy_string_out(const std::string& s, GLsizei buf_size, GLsizei* length, GLchar* out) {
  GLsizei n = 0;
  if (out && buf_size > 0) {
    n = static_cast<GLsizei>(std::min<size_t>(s.size(), static_cast<size_t>(buf_size) - 1));
    std::memcpy(out, s.data(), static_cast<size_t>(n));
    out[n] = '\0';
  }
  if (length) *length = n;
}

}  // namespace pineda
