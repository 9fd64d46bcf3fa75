// Helpers for the programmable-pipeline tests: compiling and linking from source strings.
#pragma once
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {

class ProgramTest : public GlTest {
 protected:
  GLuint compile(GLenum type, const char* source) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    return s;
  }
  GLint shader_int(GLuint s, GLenum pname) {
    GLint v = -12345;
    glGetShaderiv(s, pname, &v);
    return v;
  }
  GLint program_int(GLuint p, GLenum pname) {
    GLint v = -12345;
    glGetProgramiv(p, pname, &v);
    return v;
  }
  std::string program_log(GLuint p) {
    char buf[4096] = {};
    glGetProgramInfoLog(p, sizeof buf, nullptr, buf);
    return buf;
  }
  // Compiles, attaches and links; the program's info log explains a failure.
  GLuint link(const char* vs, const char* fs) {
    const GLuint p = glCreateProgram();
    if (vs) glAttachShader(p, compile(GL_VERTEX_SHADER, vs));
    if (fs) glAttachShader(p, compile(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    return p;
  }
  // As link, with attribute locations bound first; in use when it links.
  GLuint link_in_use(const char* vs, const char* fs, std::initializer_list<std::pair<GLuint, const char*>> locations) {
    const GLuint p = glCreateProgram();
    glAttachShader(p, compile(GL_VERTEX_SHADER, vs));
    glAttachShader(p, compile(GL_FRAGMENT_SHADER, fs));
    for (const auto& [location, name] : locations) glBindAttribLocation(p, location, name);
    glLinkProgram(p);
    EXPECT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
    glUseProgram(p);
    return p;
  }
  // The whole window's colours (read_all) and 32-bit depths.
  struct ColourAndDepth {
    std::vector<uint8_t> colour;
    std::vector<GLuint> depth;
  };
  ColourAndDepth read_colour_and_depth() {
    ColourAndDepth out{read_all(), std::vector<GLuint>(size_t(width()) * height())};
    glReadPixels(0, 0, width(), height(), GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out.depth.data());
    return out;
  }
};

}  // namespace pineda::test
