// The shader-compiler calls OpenGL ES 2.0 adds (ES 2.0 2.10.1, 2.10.2, 6.1.8):
// glGetShaderPrecisionFormat, glReleaseShaderCompiler, glShaderBinary.
#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {

// The interpreter computes every precision in IEEE single precision, and holds ints as
// floats holding integers, exact up to 2^24 (shader/README.md).
void GetShaderPrecisionFormat(Context& ctx, GLenum shadertype, GLenum precisiontype, GLint* range, GLint* precision) {
  if (shadertype != GL_VERTEX_SHADER && shadertype != GL_FRAGMENT_SHADER)
    return ctx.record_error(GL_INVALID_ENUM, "shadertype is not VERTEX_SHADER or FRAGMENT_SHADER");
  GLint r[2], p;
  switch (precisiontype) {
    case GL_LOW_FLOAT: case GL_MEDIUM_FLOAT: case GL_HIGH_FLOAT: r[0] = 127; r[1] = 127; p = 23; break;
    case GL_LOW_INT: case GL_MEDIUM_INT: case GL_HIGH_INT: r[0] = 24; r[1] = 24; p = 0; break;
    default: return ctx.record_error(GL_INVALID_ENUM, "precisiontype is not a precision");
  }
  if (range) {
    range[0] = r[0];
    range[1] = r[1];
  }
  if (precision) *precision = p;
}

// Nothing to release: glslang's tables stay for the next compile, as the spec allows.
void ReleaseShaderCompiler(Context&) {}

// NUM_SHADER_BINARY_FORMATS is 0: no format is valid.
void ShaderBinary(Context& ctx, GLsizei count, const GLuint*, GLenum, const void*, GLsizei length) {
  if (count < 0 || length < 0) return ctx.record_error(GL_INVALID_VALUE, "count or length is negative");
  ctx.record_error(GL_INVALID_ENUM, "binaryFormat: Pineda has no shader binary formats");
}

}  // namespace pineda::gl
