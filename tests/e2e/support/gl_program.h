// A GL program linked from a vertex and a fragment shader's sources, with attribute bindings,
// for tests that draw through shaders (the current context's GL 2.0 entry points).
#pragma once
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#include <initializer_list>
#include <utility>

namespace pineda::test {

inline GLuint link_gl_program(const char* vertex, const char* fragment,
                              std::initializer_list<std::pair<GLuint, const char*>> bindings = {}) {
  const GLuint program = glCreateProgram();
  for (const auto& [type, source] : {std::pair{GL_VERTEX_SHADER, vertex}, std::pair{GL_FRAGMENT_SHADER, fragment}}) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    glAttachShader(program, shader);
    glDeleteShader(shader);
  }
  for (const auto& [location, name] : bindings) glBindAttribLocation(program, location, name);
  glLinkProgram(program);
  return program;
}

}  // namespace pineda::test
