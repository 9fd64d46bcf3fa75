// The fixture of the per-draw-buffer state tests (EXT_draw_buffers2, ARB_draw_buffers_blend): a
// framebuffer object with four 16x16 RGBA8 renderbuffers as draw buffers 0-3, cleared to kCleared.
#pragma once
#include <array>

#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {

class FourDrawBuffersTest : public FboTest {
 protected:
  static constexpr int kSize = 16;
  static constexpr Rgba kCleared{10, 20, 30, 40};
  static constexpr Rgba kDrawn{200, 100, 50, 150};

  void SetUp() override {
    FboTest::SetUp();
    fb_ = make_fbo();
    for (int i = 0; i < 4; ++i) {
      rbs_[size_t(i)] = make_renderbuffer(GL_RGBA8, kSize, kSize);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_RENDERBUFFER, rbs_[size_t(i)]);
    }
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
    const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    glDrawBuffers(4, bufs);
    clear_all();
  }
  void TearDown() override {
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb_);
    glDeleteRenderbuffers(4, rbs_.data());
    FboTest::TearDown();
  }

  // Every buffer to kCleared, whatever the masks.
  static void clear_all() {
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(10 / 255.f, 20 / 255.f, 30 / 255.f, 40 / 255.f);
    glClear(GL_COLOR_BUFFER_BIT);
    glPopAttrib();
  }

  Rgba attachment_pixel(int i, int x, int y) {
    glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
    return pixel(x, y);
  }

  // [0, 8) x [0, 8) in colour c.
  static void draw_quad(const Rgba& c) {
    glColor4ub(GLubyte(c[0]), GLubyte(c[1]), GLubyte(c[2]), GLubyte(c[3]));
    glBegin(GL_QUADS);
    glVertex2f(0, 0);
    glVertex2f(8, 0);
    glVertex2f(8, 8);
    glVertex2f(0, 8);
    glEnd();
  }

  GLuint fb_ = 0;
  std::array<GLuint, 4> rbs_{};
};

}  // namespace pineda::test
