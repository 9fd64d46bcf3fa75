// DEPTH24_STENCIL8 textures (EXT_packed_depth_stencil): images in and out, and rendering into
// one attached at DEPTH_STENCIL_ATTACHMENT.
#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

using DepthStencilTextureTest = FboTest;

TEST_F(DepthStencilTextureTest, ImageRoundTrip) {
  const GLuint in[4] = {0xffffff01u, 0x00000002u, 0x800000ffu, 0x12345680u};
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 2, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, in);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint bits = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &bits);
  EXPECT_EQ(bits, 8);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &bits);
  EXPECT_EQ(bits, 24);
  GLuint out[4] = {0, 0, 0, 0};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(out[i], in[i]) << i;
  const GLuint sub = 0x40000007u;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &sub);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  EXPECT_EQ(out[3], sub);
  // Depth or depth-stencil data for depth or depth-stencil formats only, and the other way round
  // (GL 3.3 3.8.3, as Mesa); stencil indices for no texture format.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 2, 0, GL_RGBA, GL_FLOAT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 2, 0, GL_STENCIL_INDEX, GL_INT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, 2, 2, 0, GL_DEPTH_STENCIL, GL_FLOAT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_INT_24_8, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDeleteTextures(1, &tex);
}

// A depth-stencil format takes DEPTH_COMPONENT data into its depth (its stencil stays), a depth
// format the depth of DEPTH_STENCIL data.
TEST_F(DepthStencilTextureTest, DepthDataIntoDepthStencilAndTheOtherWayRound) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const GLfloat depths[2] = {0.0f, 1.0f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLuint out[2] = {1, 1};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  EXPECT_EQ(out[0], 0x00000000u);
  EXPECT_EQ(out[1], 0xffffff00u);  // stencil 0
  const GLuint packed = 0x80000042u;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &packed);
  const GLfloat one = 1.0f;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  EXPECT_EQ(out[0], 0xffffff42u);  // the new depth, the stencil kept

  const GLuint in[2] = {0xffffff11u, 0x00000022u};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, in);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLuint depth_out[2] = {1, 1};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth_out);
  EXPECT_EQ(depth_out[0], 0xffffffffu);  // the depths alone
  EXPECT_EQ(depth_out[1], 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteTextures(1, &tex);
}

TEST_F(DepthStencilTextureTest, RenderDepthAndStencilIntoIt) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 4, 4);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, nullptr);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(get_int(GL_STENCIL_BITS), 8);
  glClearDepth(1.0);
  glClearStencil(3);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 9, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  draw_window_quad(2, 4, 0.5f);  // the left half: window depth 0.25, stencil 9
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  GLuint out[16];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  EXPECT_EQ(out[0], (4194304u << 8) | 9u);  // 0.25 * 16777215 = 4194303.75
  EXPECT_EQ(out[3], 0xffffff03u);
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &color);
  glDeleteTextures(1, &tex);
}

}  // namespace
}  // namespace pineda::test
