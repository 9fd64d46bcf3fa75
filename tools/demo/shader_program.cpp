#define GL_GLEXT_PROTOTYPES
#include "shader_program.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>

namespace pineda::demo {
namespace {

GLuint compile(const char* scene, GLenum type, const char* source) {
  GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    std::fprintf(stderr, "%s: shader does not compile: %s\n", scene, log);
  }
  return shader;
}

}  // namespace

unsigned linkProgram(const char* scene, const char* vertexSource, const char* fragmentSource,
                     std::initializer_list<const char*> attributes) {
  const GLuint program = glCreateProgram();
  const GLuint vs = compile(scene, GL_VERTEX_SHADER, vertexSource);
  const GLuint fs = compile(scene, GL_FRAGMENT_SHADER, fragmentSource);
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  GLuint index = 0;
  for (const char* name : attributes) glBindAttribLocation(program, index++, name);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    std::fprintf(stderr, "%s: program does not link: %s\n", scene, log);
  }
  return program;
}

}  // namespace pineda::demo
