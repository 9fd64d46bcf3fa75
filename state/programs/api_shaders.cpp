// Shader objects: glCreateShader, glShaderSource, glCompileShader, glDeleteShader and their
// queries (GL 2.0 2.15.1, 6.1.14).
#include <cstring>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/programs/program_lookup.h"

namespace pineda::gl {
namespace {

std::string joined_source(const ShaderObject& s) {
  std::string all;
  for (const std::string& part : s.sources) all += part;
  return all;
}

}  // namespace

GLuint CreateShader(Context& ctx, GLenum type) {
  if (type != GL_VERTEX_SHADER && type != GL_FRAGMENT_SHADER) {
    ctx.record_error(GL_INVALID_ENUM, "shaderType is not GL_VERTEX_SHADER or GL_FRAGMENT_SHADER");
    return 0;
  }
  return ctx.programs.objects.create_shader(type);
}

void ShaderSource(Context& ctx, GLuint shader, GLsizei count, const GLchar* const* string, const GLint* length) {
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  if (count < 0) return ctx.record_error(GL_INVALID_VALUE, "count is negative");
  if (count > 0 && !string) return ctx.record_error(GL_INVALID_VALUE, "string is null");
  std::vector<std::string> sources;
  sources.reserve(static_cast<size_t>(count));
  for (GLsizei i = 0; i < count; ++i) {
    const GLchar* str = string[i];
    if (!str) return ctx.record_error(GL_INVALID_VALUE, "an element of string is null");
    if (length && length[i] >= 0) sources.emplace_back(str, static_cast<size_t>(length[i]));
    else sources.emplace_back(str);
  }
  s->sources = std::move(sources);
  s->has_source = true;
}

void CompileShader(Context& ctx, GLuint shader) {
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  const shader::Stage stage = s->type == GL_VERTEX_SHADER ? shader::Stage::Vertex : shader::Stage::Fragment;
  const shader::Language language = ctx.attribs().gles ? shader::Language::Es100 : shader::Language::Desktop;
  shader::CompileResult result = shader::compile(stage, language, s->sources);
  s->compile_status = result.shader != nullptr;
  s->info_log = std::move(result.info_log);
  if (result.shader) s->compiled = std::move(result.shader);
}

void DeleteShader(Context& ctx, GLuint shader) {
  if (shader == 0) return;
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  ctx.debug.forget_label(GL_SHADER, shader);
  if (s->attachments > 0) {
    s->delete_pending = true;
    return;
  }
  ctx.programs.objects.remove_shader(shader);
}

GLboolean IsShader(Context& ctx, GLuint shader) {
  return ctx.programs.objects.shader(shader) ? GL_TRUE : GL_FALSE;
}

void GetShaderiv(Context& ctx, GLuint shader, GLenum pname, GLint* params) {
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  GLint value = 0;
  switch (pname) {
    case GL_SHADER_TYPE: value = static_cast<GLint>(s->type); break;
    case GL_DELETE_STATUS: value = s->delete_pending ? GL_TRUE : GL_FALSE; break;
    case GL_COMPILE_STATUS: value = s->compile_status ? GL_TRUE : GL_FALSE; break;
    case GL_INFO_LOG_LENGTH: value = length_with_nul(s->info_log); break;
    case GL_SHADER_SOURCE_LENGTH: value = s->has_source ? static_cast<GLint>(joined_source(*s).size() + 1) : 0; break;
    default: return ctx.record_error(GL_INVALID_ENUM, "pname is not a shader parameter");
  }
  if (params) *params = value;
}

void GetShaderInfoLog(Context& ctx, GLuint shader, GLsizei bufSize, GLsizei* length, GLchar* infoLog) {
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  if (bufSize < 0) return ctx.record_error(GL_INVALID_VALUE, "bufSize is negative");
  copy_string_out(s->info_log, bufSize, length, infoLog);
}

void GetShaderSource(Context& ctx, GLuint shader, GLsizei bufSize, GLsizei* length, GLchar* source) {
  ShaderObject* s = shader_or_error(ctx, shader);
  if (!s) return;
  if (bufSize < 0) return ctx.record_error(GL_INVALID_VALUE, "bufSize is negative");
  copy_string_out(joined_source(*s), bufSize, length, source);
}

}  // namespace pineda::gl
