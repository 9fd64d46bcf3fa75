// Program objects: attach, link, validate, use, delete, and their queries (GL 2.0 2.15.2,
// 2.15.3, 6.1.14).
#include <algorithm>
#include <cstring>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/programs/gl_type_token.h"
#include "state/programs/program_link.h"
#include "state/programs/program_lookup.h"

namespace pineda::gl {
namespace {

bool starts_with_gl(const GLchar* name) { return std::strncmp(name, "gl_", 3) == 0; }

}  // namespace

GLuint CreateProgram(Context& ctx) { return ctx.programs.objects.create_program(); }

void AttachShader(Context& ctx, GLuint program, GLuint shader) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  if (std::find(p->attached.begin(), p->attached.end(), shader) != p->attached.end())
    return ctx.record_error(GL_INVALID_OPERATION, "the shader is already attached to the program");
  if (ctx.es2()) {  // ES 2.0 2.10.3: one shader object of each type per program
    for (GLuint other : p->attached) {
      const ShaderObject* o = ctx.programs.objects.shader(other);
      if (o && o->type == s->type)
        return ctx.record_error(GL_INVALID_OPERATION, "the program already has a shader of that type");
    }
  }
  p->attached.push_back(shader);
  ++s->attachments;
}

void DetachShader(Context& ctx, GLuint program, GLuint shader) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  auto it = std::find(p->attached.begin(), p->attached.end(), shader);
  if (it == p->attached.end())
    return ctx.record_error(GL_INVALID_OPERATION, "the shader is not attached to the program");
  p->attached.erase(it);
  if (--s->attachments <= 0 && s->delete_pending) ctx.programs.objects.remove_shader(shader);
}

void LinkProgram(Context& ctx, GLuint program) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  link_program(ctx, *p);
  if (ctx.programs.current == program && p->executable) ctx.programs.current_exec = p->executable;
}

void ValidateProgram(Context& ctx, GLuint program) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  std::string log;
  p->validate_status = validate_program(ctx, *p, log);
  p->info_log = log;
}

void UseProgram(Context& ctx, GLuint program) {
  ProgramState& ps = ctx.programs;
  std::shared_ptr<LinkedProgram> exec;
  if (program != 0) {
    ProgramObject* p = program_or_error(ctx, program);
    if (!p) return;
    if (!p->link_status || !p->executable) return ctx.record_error(GL_INVALID_OPERATION, "the program is not linked");
    exec = p->executable;
  }
  ps.use(program, std::move(exec));
}

void DeleteProgram(Context& ctx, GLuint program) {
  if (program == 0) return;
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  p->delete_pending = true;
  ctx.debug.forget_label(GL_PROGRAM, program);
  ctx.programs.objects.destroy_program_if_unused(program);
}

GLboolean IsProgram(Context& ctx, GLuint program) {
  return ctx.programs.objects.program(program) ? GL_TRUE : GL_FALSE;
}

void GetProgramiv(Context& ctx, GLuint program, GLenum pname, GLint* params) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  const LinkedProgram* exec = p->executable.get();
  const shader::Program* prog = exec ? exec->program.get() : nullptr;
  GLint value = 0;
  switch (pname) {
    case GL_DELETE_STATUS: value = p->delete_pending ? GL_TRUE : GL_FALSE; break;
    case GL_LINK_STATUS: value = p->link_status ? GL_TRUE : GL_FALSE; break;
    case GL_VALIDATE_STATUS: value = p->validate_status ? GL_TRUE : GL_FALSE; break;
    case GL_INFO_LOG_LENGTH: value = length_with_nul(p->info_log); break;
    case GL_ATTACHED_SHADERS: value = static_cast<GLint>(p->attached.size()); break;
    case GL_ACTIVE_ATTRIBUTES: value = exec ? static_cast<GLint>(exec->attributes.size()) : 0; break;
    case GL_ACTIVE_ATTRIBUTE_MAX_LENGTH:
      if (prog)
        for (int i : exec->attributes)
          value = std::max(value, static_cast<GLint>(prog->attributes()[i].name.size() + 1));
      break;
    case GL_ACTIVE_UNIFORMS: value = exec ? static_cast<GLint>(exec->uniforms.active.size()) : 0; break;
    case GL_ACTIVE_UNIFORM_MAX_LENGTH:
      if (exec)
        for (const shader::Uniform& u : exec->uniforms.active) value = std::max(value, static_cast<GLint>(u.name.size() + 1));
      break;
    default: return ctx.record_error(GL_INVALID_ENUM, "pname is not a program parameter");
  }
  if (params) *params = value;
}

void GetProgramInfoLog(Context& ctx, GLuint program, GLsizei bufSize, GLsizei* length, GLchar* infoLog) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  if (bufSize < 0) return ctx.record_error(GL_INVALID_VALUE, "bufSize is negative");
  copy_string_out(p->info_log, bufSize, length, infoLog);
}

void GetAttachedShaders(Context& ctx, GLuint program, GLsizei maxCount, GLsizei* count, GLuint* shaders) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  if (maxCount < 0) return ctx.record_error(GL_INVALID_VALUE, "maxCount is negative");
  GLsizei n = 0;
  if (shaders)
    for (; n < maxCount && n < static_cast<GLsizei>(p->attached.size()); ++n) shaders[n] = p->attached[n];
  if (count) *count = n;
}

void BindAttribLocation(Context& ctx, GLuint program, GLuint index, const GLchar* name) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  if (index >= static_cast<GLuint>(kMaxVertexAttribs))
    return ctx.record_error(GL_INVALID_VALUE, "index is not less than GL_MAX_VERTEX_ATTRIBS");
  if (!name) return;
  if (starts_with_gl(name)) return ctx.record_error(GL_INVALID_OPERATION, "name starts with gl_");
  p->bindings[name] = index;
}

GLint GetAttribLocation(Context& ctx, GLuint program, const GLchar* name) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return -1;
  if (!p->link_status || !p->executable) {
    ctx.record_error(GL_INVALID_OPERATION, "the program is not linked");
    return -1;
  }
  if (!name || starts_with_gl(name) || !p->executable->program) return -1;
  for (const shader::Attribute& a : p->executable->program->attributes())
    if (a.builtin == shader::BuiltinAttribute::None && a.name == name) return a.location;
  return -1;
}

void GetActiveAttrib(Context& ctx, GLuint program, GLuint index, GLsizei bufSize, GLsizei* length, GLint* size,
                     GLenum* type, GLchar* name) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  const LinkedProgram* exec = p->executable.get();
  if (!exec || index >= exec->attributes.size())
    return ctx.record_error(GL_INVALID_VALUE, "index is not below the number of active attributes");
  if (bufSize < 0) return ctx.record_error(GL_INVALID_VALUE, "bufSize is negative");
  const shader::Attribute& a = exec->program->attributes()[exec->attributes[index]];
  copy_string_out(a.name, bufSize, length, name);
  if (size) *size = a.array_size;
  if (type) *type = gl_type_token(a.type);
}

void GetActiveUniform(Context& ctx, GLuint program, GLuint index, GLsizei bufSize, GLsizei* length, GLint* size,
                      GLenum* type, GLchar* name) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return;
  const LinkedProgram* exec = p->executable.get();
  if (!exec || index >= exec->uniforms.active.size())
    return ctx.record_error(GL_INVALID_VALUE, "index is not below the number of active uniforms");
  if (bufSize < 0) return ctx.record_error(GL_INVALID_VALUE, "bufSize is negative");
  const shader::Uniform& u = exec->uniforms.active[index];
  copy_string_out(u.name, bufSize, length, name);
  if (size) *size = u.array_size;
  if (type) *type = gl_type_token(u.type);
}

GLint GetUniformLocation(Context& ctx, GLuint program, const GLchar* name) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return -1;
  if (!p->link_status || !p->executable) {
    ctx.record_error(GL_INVALID_OPERATION, "the program is not linked");
    return -1;
  }
  if (!name) return -1;
  return p->executable->uniforms.location(name);
}

}  // namespace pineda::gl
