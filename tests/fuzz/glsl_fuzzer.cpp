// libFuzzer target for the GLSL compiler: the input is shader sources that go through the GL
// API (glShaderSource, glCompileShader, glLinkProgram, glUseProgram) and, when they link, a
// small draw, so that lowering, optimizing and executing run too.
//
// Input: byte 0 chooses the context (bit 0: 0 = OpenGL ES 2.0 with GLSL ES 1.00, 1 = OpenGL 2.1
// with GLSL 1.10/1.20) and whether the vertex and fragment shaders are attached (bits 1-2: 0 or
// 3 = both, 1 = vertex only, 2 = fragment only); the rest is sources separated by NUL bytes:
// vertex, fragment, then more shaders for the vertex and fragment stage in turn (desktop GL links
// several shaders per stage). tests/fuzz/make_glsl_seed.py writes such files.
#define GL_GLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "tests/es1/egl_context.h"

namespace {

// One 4x4 fragment block: a shader that loops until the executor's iteration budget ends its
// loops costs that budget once per vertex batch and fragment block of the draws.
constexpr int kSize = 4;
constexpr size_t kMaxShaders = 6;
constexpr EGLint kEs2Attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
constexpr EGLint kGl21Attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};

std::vector<std::string_view> split_sources(std::string_view text) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < kMaxShaders) {
    const size_t end = text.find('\0');
    if (end == std::string_view::npos) break;
    parts.push_back(text.substr(0, end));
    text.remove_prefix(end + 1);
  }
  parts.push_back(text);
  return parts;
}

// Reads the info log of a shader or program as an application does: its length, then the text.
void read_info_log(GLuint object, bool program) {
  GLint length = 0;
  (program ? glGetProgramiv : glGetShaderiv)(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(length > 0 ? length : 1), '\0');
  (program ? glGetProgramInfoLog : glGetShaderInfoLog)(object, GLsizei(log.size()), nullptr, log.data());
}

void compile_and_attach(GLuint program, GLenum type, std::string_view source) {
  const GLuint shader = glCreateShader(type);
  const GLchar* text = source.data();
  const GLint length = GLint(source.size());
  glShaderSource(shader, 1, &text, &length);  // not NUL-terminated: the length counts
  glCompileShader(shader);
  GLint status = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &status);
  read_info_log(shader, false);
  glAttachShader(program, shader);
  glDeleteShader(shader);  // deleted with the program
}

// Calls use(index, location, size, type) for each active uniform (or attribute) of `program`
// that has a location.
template <class Use>
void for_each_active(GLuint program, bool uniforms, Use use) {
  GLint count = 0;
  glGetProgramiv(program, uniforms ? GL_ACTIVE_UNIFORMS : GL_ACTIVE_ATTRIBUTES, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[256];
    GLint size = 0;
    GLenum type = 0;
    if (uniforms)
      glGetActiveUniform(program, GLuint(i), sizeof(name), nullptr, &size, &type, name);
    else
      glGetActiveAttrib(program, GLuint(i), sizeof(name), nullptr, &size, &type, name);
    const GLint location = uniforms ? glGetUniformLocation(program, name) : glGetAttribLocation(program, name);
    if (location >= 0) use(i, location, size, type);
  }
}

// Every active uniform gets values that differ per uniform; samplers get units 0 to 7.
void set_uniforms(GLuint program) {
  for_each_active(program, true, [](GLint i, GLint location, GLint size, GLenum type) {
    if (size <= 0 || size > 4096) return;
    std::vector<GLfloat> floats(size_t(size) * 16);
    std::vector<GLint> ints(size_t(size) * 4);
    for (size_t k = 0; k < floats.size(); ++k) floats[k] = 0.25f * float((i + k) % 7) - 0.5f;
    for (size_t k = 0; k < ints.size(); ++k) ints[k] = GLint((i + k) % 8);
    switch (type) {
      case GL_FLOAT: glUniform1fv(location, size, floats.data()); break;
      case GL_FLOAT_VEC2: glUniform2fv(location, size, floats.data()); break;
      case GL_FLOAT_VEC3: glUniform3fv(location, size, floats.data()); break;
      case GL_FLOAT_VEC4: glUniform4fv(location, size, floats.data()); break;
      case GL_INT: case GL_BOOL: case GL_SAMPLER_1D: case GL_SAMPLER_2D: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
      case GL_SAMPLER_1D_SHADOW: case GL_SAMPLER_2D_SHADOW: glUniform1iv(location, size, ints.data()); break;
      case GL_INT_VEC2: case GL_BOOL_VEC2: glUniform2iv(location, size, ints.data()); break;
      case GL_INT_VEC3: case GL_BOOL_VEC3: glUniform3iv(location, size, ints.data()); break;
      case GL_INT_VEC4: case GL_BOOL_VEC4: glUniform4iv(location, size, ints.data()); break;
      case GL_FLOAT_MAT2: glUniformMatrix2fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT3: glUniformMatrix3fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT4: glUniformMatrix4fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT2x3: glUniformMatrix2x3fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT3x2: glUniformMatrix3x2fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT2x4: glUniformMatrix2x4fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT4x2: glUniformMatrix4x2fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT3x4: glUniformMatrix3x4fv(location, size, GL_FALSE, floats.data()); break;
      case GL_FLOAT_MAT4x3: glUniformMatrix4x3fv(location, size, GL_FALSE, floats.data()); break;
      default: break;
    }
  });
}

// A 2x2 texture on each of the 8 units, 2D and cube map, so that samplers read something.
void bind_textures() {
  const uint8_t texels[16] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 255, 255, 255, 255};
  for (GLenum unit = 0; unit < 8; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    GLuint textures[2];
    glGenTextures(2, textures);
    glBindTexture(GL_TEXTURE_2D, textures[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, unit % 2 ? GL_LINEAR : GL_NEAREST);
    glBindTexture(GL_TEXTURE_CUBE_MAP, textures[1]);
    for (GLenum face = 0; face < 6; ++face)
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  }
  glActiveTexture(GL_TEXTURE0);
}

// Every active attribute (and attribute 0, the position) reads a client array of 4 vertices:
// a triangle over the viewport, a line across it and a point inside.
void draw(GLuint program) {
  static const GLfloat kVertices[4 * 4] = {-1, -1, 0.5f, 1, 3, -1, 0, 1, -1, 3, -0.5f, 1, 0.1f, 0.2f, 0, 2};
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, kVertices);
  for_each_active(program, false, [](GLint, GLint location, GLint, GLenum) {
    glEnableVertexAttribArray(GLuint(location));
    glVertexAttribPointer(GLuint(location), 4, GL_FLOAT, GL_FALSE, 0, kVertices);
  });
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDrawArrays(GL_LINES, 2, 2);
  glDrawArrays(GL_POINTS, 3, 1);
  uint8_t pixels[kSize * kSize * 4];
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("PINEDA_THREADS", "1", 1);  // one rasterizer thread: the same run for every input
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const bool desktop = data[0] & 1;
  const int stages = (data[0] >> 1) & 3;
  const bool attach_vertex = stages != 2, attach_fragment = stages != 1;
  const auto sources = split_sources({reinterpret_cast<const char*>(data + 1), size - 1});
  // A fresh context per input, so that every finding reproduces from its input alone.
  pineda::es1_test::EglContext context(desktop ? EGL_OPENGL_API : EGL_OPENGL_ES_API,
                                       desktop ? kGl21Attribs : kEs2Attribs, kSize, kSize,
                                       desktop ? EGL_OPENGL_BIT : EGL_OPENGL_ES2_BIT);
  if (!context.ok()) abort();
  const GLuint program = glCreateProgram();
  for (size_t i = 0; i < sources.size(); ++i) {
    const bool vertex = i % 2 == 0;
    if (vertex ? attach_vertex : attach_fragment)
      compile_and_attach(program, vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER, sources[i]);
  }
  glBindAttribLocation(program, 1, "color");
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  read_info_log(program, true);
  if (linked) {
    glUseProgram(program);
    glValidateProgram(program);
    set_uniforms(program);
    bind_textures();
    draw(program);
    glFinish();
  }
  glDeleteProgram(program);
  eglBindAPI(EGL_OPENGL_API);
  return 0;
}
