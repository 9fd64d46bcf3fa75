// glBlitFramebuffer: copies, scaling, mirroring, clipping to both framebuffers and the
// scissor, depth and stencil, and its errors.
#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

class BlitTest : public FboTest {
 protected:
  void SetUp() override {
    FboTest::SetUp();
    src_rb_ = make_renderbuffer(GL_RGBA8, 4, 4);
    glGenFramebuffers(1, &src_);
    glBindFramebuffer(GL_FRAMEBUFFER, src_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, src_rb_);
    // A 4x4 source whose pixel (i, j) is (40 i, 40 j, 200, 255).
    std::vector<uint8_t> px(4 * 4 * 4);
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        uint8_t* p = &px[4 * (j * 4 + i)];
        p[0] = uint8_t(40 * i), p[1] = uint8_t(40 * j), p[2] = 200, p[3] = 255;
      }
    glRasterPos2i(0, 0);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    clear_to(0, 0, 0, 0);
  }
  void TearDown() override {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &src_);
    glDeleteRenderbuffers(1, &src_rb_);
    FboTest::TearDown();
  }
  Rgba source(int i, int j) { return {40 * i, 40 * j, 200, 255}; }

  GLuint src_ = 0, src_rb_ = 0;
};

TEST_F(BlitTest, CopyIntoTheWindow) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  glBlitFramebuffer(0, 0, 4, 4, 5, 6, 9, 10, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_TRUE(near_rgba(pixel(5, 6), source(0, 0)));
  EXPECT_TRUE(near_rgba(pixel(8, 9), source(3, 3)));
  EXPECT_TRUE(near_rgba(pixel(7, 6), source(2, 0)));
  EXPECT_TRUE(near_rgba(pixel(9, 6), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(4, 6), {0, 0, 0, 0}));
}

TEST_F(BlitTest, ScaledAndMirrored) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  // 2x magnified, mirrored in x: destination x 0..7 reads source x 3..0.
  glBlitFramebuffer(0, 0, 4, 4, 8, 0, 0, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_TRUE(near_rgba(pixel(0, 0), source(3, 0)));
  EXPECT_TRUE(near_rgba(pixel(1, 1), source(3, 0)));
  EXPECT_TRUE(near_rgba(pixel(7, 7), source(0, 3)));
  EXPECT_TRUE(near_rgba(pixel(4, 2), source(1, 1)));
  // Minified 2:1: destination centre 0.5 reads source x 1.0, so pixels 1 and 3.
  clear_to(0, 0, 0, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 2, 2, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_TRUE(near_rgba(pixel(0, 0), source(1, 1)));
  EXPECT_TRUE(near_rgba(pixel(1, 1), source(3, 3)));
}

TEST_F(BlitTest, LinearFilter) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // Destination pixel 3 reads source x 1.75: 3/4 of pixel 1 (centre 1.5), 1/4 of pixel 2.
  EXPECT_TRUE(near_rgba(pixel(3, 0), {50, 0, 200, 255}));
  EXPECT_TRUE(near_rgba(pixel(0, 0), {0, 0, 200, 255}));  // clamped at the edge
  EXPECT_TRUE(near_rgba(pixel(4, 4), {70, 70, 200, 255}));
}

TEST_F(BlitTest, ClippedToBothFramebuffersAndTheScissor) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  // The source rectangle starts 2 pixels left of the read framebuffer: those pixels are not written.
  glBlitFramebuffer(-2, 0, 2, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(2, 1), source(0, 1)));
  // A destination past the window's right edge.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  glBlitFramebuffer(0, 0, 4, 4, 14, 8, 18, 12, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_TRUE(near_rgba(pixel(15, 8), source(1, 0)));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  // The scissor test applies.
  glEnable(GL_SCISSOR_TEST);
  glScissor(9, 0, 1, 16);
  glBlitFramebuffer(0, 0, 4, 4, 8, 0, 12, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_TRUE(near_rgba(pixel(8, 0), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(9, 0), source(1, 0)));
  EXPECT_TRUE(near_rgba(pixel(10, 0), {0, 0, 0, 0}));
}

TEST_F(BlitTest, DepthAndStencil) {
  const GLuint ds[2] = {make_renderbuffer(GL_DEPTH24_STENCIL8, 4, 4), make_renderbuffer(GL_DEPTH24_STENCIL8, 4, 4)};
  const GLuint colors[2] = {make_renderbuffer(GL_RGBA8, 4, 4), make_renderbuffer(GL_RGBA8, 4, 4)};
  GLuint fb[2];
  glGenFramebuffers(2, fb);
  for (int i = 0; i < 2; ++i) {
    glBindFramebuffer(GL_FRAMEBUFFER, fb[i]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colors[i]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds[i]);
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glClearDepth(i == 0 ? 0.25 : 1.0);
    glClearStencil(i == 0 ? 7 : 0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
  glBlitFramebuffer(0, 0, 2, 4, 0, 0, 2, 4, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // depth and stencil need NEAREST
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
  GLuint v[2] = {0, 0};
  glReadPixels(1, 1, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v[0]);
  glReadPixels(3, 1, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v[1]);
  EXPECT_EQ(v[0], (4194304u << 8) | 7u);  // 0.25 * 16777215 = 4194303.75
  EXPECT_EQ(v[1], 0xffffff00u);
  // Depth formats that differ: INVALID_OPERATION.
  const GLuint d16 = make_renderbuffer(GL_DEPTH_COMPONENT16, 4, 4);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, d16);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(2, fb);
  glDeleteRenderbuffers(2, ds);
  glDeleteRenderbuffers(2, colors);
  glDeleteRenderbuffers(1, &d16);
}

TEST_F(BlitTest, Errors) {
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_ACCUM_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_COLOR_BUFFER_BIT, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_STENCIL_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLuint empty = 0;
  glGenFramebuffers(1, &empty);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, empty);
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &empty);
}

TEST_F(BlitTest, ReducedFormatDestination) {
  const GLuint rb = make_renderbuffer(GL_RGBA4, 4, 4);
  GLuint fb = 0;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, src_);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
  EXPECT_TRUE(near_rgba(pixel(1, 2), {34, 85, 204, 255}));  // 40 -> 2/15, 80 -> 5/15, 200 -> 12/15
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &rb);
}

}  // namespace
}  // namespace pineda::test
