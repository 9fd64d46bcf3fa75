#include "state/programs/program_lookup.h"

#include <algorithm>
#include <cstring>

namespace pineda {

ShaderObject* shader_or_error(Context& ctx, GLuint name) {
  if (ShaderObject* s = ctx.programs.objects.shader(name)) return s;
  ctx.record_error(ctx.programs.objects.program(name) ? GL_INVALID_OPERATION : GL_INVALID_VALUE);
  return nullptr;
}

ProgramObject* program_or_error(Context& ctx, GLuint name) {
  if (ProgramObject* p = ctx.programs.objects.program(name)) return p;
  ctx.record_error(ctx.programs.objects.shader(name) ? GL_INVALID_OPERATION : GL_INVALID_VALUE);
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
