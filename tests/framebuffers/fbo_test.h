// The fixture of the framebuffer object tests: a 16x16 window surface, one unit per pixel,
// and helpers that make framebuffer objects of textures and renderbuffers.
#pragma once
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <utility>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {

class FboTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {16, 16, 24, 8}; }
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    GlTest::TearDown();
  }

  GLuint make_fbo() {
    GLuint fb = 0;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    return fb;
  }

  // A width x height renderbuffer of `format`, bound to GL_RENDERBUFFER.
  GLuint make_renderbuffer(GLenum format, int w, int h) {
    GLuint rb = 0;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
    return rb;
  }

  // A 2D texture with level 0 of this format and size (no data), NEAREST filtering.
  GLuint make_texture(GLint format, int w, int h, GLenum data_format = GL_RGBA, GLenum type = GL_UNSIGNED_BYTE) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, data_format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return tex;
  }

  GLenum status() { return glCheckFramebufferStatus(GL_FRAMEBUFFER); }

  // A textured quad over [0, w] x [0, h] with texture coordinates 0..1 (REPLACE).
  void draw_textured(GLuint tex, float w, float h) {
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(1, 0); glVertex2f(w, 0);
    glTexCoord2f(1, 1); glVertex2f(w, h);
    glTexCoord2f(0, 1); glVertex2f(0, h);
    glEnd();
    glDisable(GL_TEXTURE_2D);
  }

  // A linked program of `fs` and a vertex shader of ftransform() passing gl_Color on.
  GLuint fragment_program(const char* fs) {
    const char* vs = "void main() { gl_FrontColor = gl_Color; gl_Position = ftransform(); }";
    const GLuint p = glCreateProgram();
    for (auto [type, src] : {std::pair{GL_VERTEX_SHADER, vs}, std::pair{GL_FRAGMENT_SHADER, fs}}) {
      const GLuint s = glCreateShader(type);
      glShaderSource(s, 1, &src, nullptr);
      glCompileShader(s);
      glAttachShader(p, s);
      glDeleteShader(s);
    }
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    return p;
  }

  int get_int(GLenum pname) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
  }
};

}  // namespace pineda::test
