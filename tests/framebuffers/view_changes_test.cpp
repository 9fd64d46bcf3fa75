// The context keeps the view of a framebuffer object between draws while nothing it is made of
// changed (state/framebuffers/view_source.h): a draw after any change of the images renders
// into the images as they are now. Exact pixel values.
#include <algorithm>
#include <vector>

#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

class ViewChangesTest : public FboTest {
 protected:
  // A bound 16x16 framebuffer object of an RGBA8 renderbuffer and a 24-bit depth texture (given
  // `depths` when not null), complete, with the depth test on (LESS).
  void make_depth_texture_target(const float* depths) {
    color_ = make_renderbuffer(GL_RGBA8, 16, 16);
    depth_ = make_texture(GL_DEPTH_COMPONENT24, 16, 16, GL_DEPTH_COMPONENT, GL_FLOAT);
    if (depths) glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    fb_ = make_fbo();
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
  }
  void delete_depth_texture_target() {
    glDeleteFramebuffers(1, &fb_);
    glDeleteRenderbuffers(1, &color_);
    glDeleteTextures(1, &depth_);
  }

  GLuint color_ = 0, depth_ = 0, fb_ = 0;
};

// A texture respecified at another size while attached: the next draw and read see the new
// 16x16 image, not the old 4x4 one.
TEST_F(ViewChangesTest, RespecifiedTextureLevel) {
  const GLuint tex = make_texture(GL_RGBA8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  clear_to(1, 0, 0, 1);
  glColor4f(0, 0, 1, 1);
  draw_window_quad(16, 16);
  EXPECT_TRUE(near_rgba(pixel(2, 2), {0, 0, 255, 255}));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  clear_to(0, 1, 0, 1);
  draw_rect(8, 8, 16, 16);
  EXPECT_TRUE(near_rgba(pixel(2, 2), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(14, 14), {0, 0, 255, 255}));
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
}

// A renderbuffer given new storage while attached.
TEST_F(ViewChangesTest, RenderbufferGivenNewStorage) {
  const GLuint rb = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  clear_to(1, 0, 0, 1);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16, 16);
  clear_to(0, 0, 0, 1);
  glColor4f(1, 1, 1, 1);
  draw_rect(12, 12, 16, 16);
  EXPECT_TRUE(near_rgba(pixel(14, 14), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(3, 3), {0, 0, 0, 255}));
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &rb);
}

// Another texture attached at the same point between two draws: the second draw goes to it
// alone.
TEST_F(ViewChangesTest, AnotherTextureAtTheSamePoint) {
  const GLuint first = make_texture(GL_RGBA8, 16, 16);
  const GLuint second = make_texture(GL_RGBA8, 16, 16);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, first, 0);
  clear_to(1, 0, 0, 1);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, second, 0);
  clear_to(0, 1, 0, 1);
  glColor4f(0, 0, 1, 1);
  draw_rect(0, 0, 8, 16);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {0, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(12, 3), {0, 255, 0, 255}));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, first, 0);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(12, 3), {255, 0, 0, 255}));
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &first);
  glDeleteTextures(1, &second);
}

// An attached depth texture given new depths (same size) by glTexImage2D: the next depth test
// compares with them. The plane at depth 0.5 fails LESS against 0.25 and passes against 0.75.
TEST_F(ViewChangesTest, DepthTextureGivenNewDepths) {
  ASSERT_NO_FATAL_FAILURE(make_depth_texture_target(nullptr));
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  clear_to(0, 0, 0, 1);
  glColor4f(1, 0, 0, 1);
  draw_rect(0, 0, 16, 8);  // passes against 1
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));
  std::vector<float> z(16 * 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) z[y * 16 + x] = x < 8 ? 0.25f : 0.75f;
  glBindTexture(GL_TEXTURE_2D, depth_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, z.data());
  glColor4f(0, 1, 0, 1);
  draw_rect(0, 8, 16, 16);
  glDisable(GL_DEPTH_TEST);
  EXPECT_TRUE(near_rgba(pixel(3, 12), {0, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(12, 12), {0, 255, 0, 255}));
  delete_depth_texture_target();
}

// The depth attachment replaced and the same depth texture attached again while the object is
// bound for reading only, its depths changed in between: the draw view, built before, must not
// keep the old attachment's integer copy; the next draw tests against the texture's depths.
TEST_F(ViewChangesTest, DepthTextureAttachedAgainWhileBoundForReading) {
  const GLuint other_depth = make_renderbuffer(GL_DEPTH_COMPONENT24, 16, 16);
  std::vector<float> z(16 * 16, 0.25f);
  ASSERT_NO_FATAL_FAILURE(make_depth_texture_target(z.data()));
  clear_to(0, 0, 0, 1);
  glColor4f(1, 0, 0, 1);
  draw_window_quad(16, 16);  // depth 0.5 fails against 0.25
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 0, 0, 255}));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glFramebufferRenderbuffer(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, other_depth);
  std::fill(z.begin(), z.begin() + 16 * 16, 0.75f);
  glBindTexture(GL_TEXTURE_2D, depth_);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 16, 8, GL_DEPTH_COMPONENT, GL_FLOAT, z.data());  // rows 0-7
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb_);
  glColor4f(0, 1, 0, 1);
  draw_window_quad(16, 16);  // depth 0.5: passes against 0.75 (rows 0-7), fails against 0.25
  glDisable(GL_DEPTH_TEST);
  EXPECT_TRUE(near_rgba(pixel(8, 4), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(8, 12), {0, 0, 0, 255}));
  glDeleteRenderbuffers(1, &other_depth);
  delete_depth_texture_target();
}

}  // namespace
}  // namespace pineda::test
