// GL_ARB_shader_objects' own entry points: handles that name either kind of object
// (glDeleteObjectARB, glGetObjectParameter*vARB, glGetInfoLogARB, glGetHandleARB). The other
// ARB_shader_objects and ARB_vertex_shader functions are other names of the GL 2.0 ones
// (gl_functions.txt); the uniform-array forms forward here to keep their display-list copies.
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/programs/program_lookup.h"

namespace pineda::gl {
namespace {

bool shader_pname(GLenum pname) {
  switch (pname) {
    case GL_OBJECT_TYPE_ARB: case GL_OBJECT_SUBTYPE_ARB: case GL_DELETE_STATUS: case GL_COMPILE_STATUS:
    case GL_INFO_LOG_LENGTH: case GL_SHADER_SOURCE_LENGTH:
      return true;
    default: return false;
  }
}

bool program_pname(GLenum pname) {
  switch (pname) {
    case GL_OBJECT_TYPE_ARB: case GL_DELETE_STATUS: case GL_LINK_STATUS: case GL_VALIDATE_STATUS:
    case GL_INFO_LOG_LENGTH: case GL_ATTACHED_SHADERS: case GL_ACTIVE_UNIFORMS: case GL_ACTIVE_UNIFORM_MAX_LENGTH:
    case GL_ACTIVE_ATTRIBUTES: case GL_ACTIVE_ATTRIBUTE_MAX_LENGTH:
      return true;
    default: return false;
  }
}

// The value of `pname` for object `obj`; false after an error.
bool object_parameter(Context& ctx, GLhandleARB obj, GLenum pname, GLint& value) {
  const bool is_shader = ctx.programs.objects.shader(obj) != nullptr;
  const bool is_program = ctx.programs.objects.program(obj) != nullptr;
  if (!shader_pname(pname) && !program_pname(pname)) {
    ctx.record_error(GL_INVALID_ENUM, "pname is not an object parameter");
    return false;
  }
  if (!is_shader && !is_program) {
    ctx.record_error(GL_INVALID_VALUE, "obj is not a shader or program object");
    return false;
  }
  if (is_shader ? !shader_pname(pname) : !program_pname(pname)) {
    ctx.record_error(GL_INVALID_OPERATION, "pname is not a parameter of that kind of object");
    return false;
  }
  if (pname == GL_OBJECT_TYPE_ARB) {
    value = is_shader ? GL_SHADER_OBJECT_ARB : GL_PROGRAM_OBJECT_ARB;
    return true;
  }
  if (pname == GL_OBJECT_SUBTYPE_ARB) pname = GL_SHADER_TYPE;
  const uint64_t errors = ctx.errors_recorded();
  if (is_shader) GetShaderiv(ctx, obj, pname, &value);
  else GetProgramiv(ctx, obj, pname, &value);
  return ctx.errors_recorded() == errors;
}

}  // namespace

void DeleteObjectARB(Context& ctx, GLhandleARB obj) {
  if (obj == 0) return;
  if (ctx.programs.objects.shader(obj)) return DeleteShader(ctx, obj);
  if (ctx.programs.objects.program(obj)) return DeleteProgram(ctx, obj);
  ctx.record_error(GL_INVALID_VALUE, "obj is not a shader or program object");
}

GLhandleARB GetHandleARB(Context& ctx, GLenum pname) {
  if (pname != GL_PROGRAM_OBJECT_ARB) {
    ctx.record_error(GL_INVALID_ENUM, "pname is not GL_PROGRAM_OBJECT_ARB");
    return 0;
  }
  return ctx.programs.current;
}

void GetObjectParameterivARB(Context& ctx, GLhandleARB obj, GLenum pname, GLint* params) {
  GLint value = 0;
  if (object_parameter(ctx, obj, pname, value) && params) *params = value;
}

void GetObjectParameterfvARB(Context& ctx, GLhandleARB obj, GLenum pname, GLfloat* params) {
  GLint value = 0;
  if (object_parameter(ctx, obj, pname, value) && params) *params = static_cast<GLfloat>(value);
}

void GetInfoLogARB(Context& ctx, GLhandleARB obj, GLsizei maxLength, GLsizei* length, GLcharARB* infoLog) {
  if (ctx.programs.objects.shader(obj)) return GetShaderInfoLog(ctx, obj, maxLength, length, infoLog);
  if (ctx.programs.objects.program(obj)) return GetProgramInfoLog(ctx, obj, maxLength, length, infoLog);
  ctx.record_error(GL_INVALID_VALUE, "obj is not a shader or program object");
}

#define PINEDA_FORWARD_V(name, T)                                                                  \
  void name##ARB(Context& ctx, GLint location, GLsizei count, const T* value) {                    \
    name(ctx, location, count, value);                                                             \
  }                                                                                                \
  void compile_##name##ARB(Context& ctx, GLint location, GLsizei count, const T* value) {          \
    compile_##name(ctx, location, count, value);                                                   \
  }
PINEDA_FORWARD_V(Uniform1fv, GLfloat)
PINEDA_FORWARD_V(Uniform2fv, GLfloat)
PINEDA_FORWARD_V(Uniform3fv, GLfloat)
PINEDA_FORWARD_V(Uniform4fv, GLfloat)
PINEDA_FORWARD_V(Uniform1iv, GLint)
PINEDA_FORWARD_V(Uniform2iv, GLint)
PINEDA_FORWARD_V(Uniform3iv, GLint)
PINEDA_FORWARD_V(Uniform4iv, GLint)
#undef PINEDA_FORWARD_V

#define PINEDA_FORWARD_MATRIX(name)                                                                       \
  void name##ARB(Context& ctx, GLint location, GLsizei count, GLboolean transpose, const GLfloat* value) { \
    name(ctx, location, count, transpose, value);                                                         \
  }                                                                                                       \
  void compile_##name##ARB(Context& ctx, GLint location, GLsizei count, GLboolean transpose,              \
                           const GLfloat* value) {                                                        \
    compile_##name(ctx, location, count, transpose, value);                                               \
  }
PINEDA_FORWARD_MATRIX(UniformMatrix2fv)
PINEDA_FORWARD_MATRIX(UniformMatrix3fv)
PINEDA_FORWARD_MATRIX(UniformMatrix4fv)
#undef PINEDA_FORWARD_MATRIX

}  // namespace pineda::gl
