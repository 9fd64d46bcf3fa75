// GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 pixels (EXT_packed_depth_stencil) in glReadPixels
// and glDrawPixels, on the window and on a DEPTH24_STENCIL8 renderbuffer.
#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

using PackedDepthStencilTest = FboTest;

TEST_F(PackedDepthStencilTest, DrawThenReadOnARenderbuffer) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint ds = make_renderbuffer(GL_DEPTH24_STENCIL8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  const GLuint in[4] = {0x12345678u, 0x00000001u, 0xffffff80u, 0x80000042u};
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glRasterPos2i(0, 1);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, in);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  GLuint out[4] = {0, 0, 0, 0};
  glReadPixels(0, 1, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(out[i], in[i]) << i;
  // The parts read one at a time.
  GLuint z = 0;
  GLubyte s = 0;
  glReadPixels(1, 2, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
  glReadPixels(1, 2, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  EXPECT_EQ(z >> 8, 0x800000u);
  EXPECT_EQ(s, 0x42);
  glDeleteFramebuffers(1, &fb);
  const GLuint rbs[2] = {color, ds};
  glDeleteRenderbuffers(2, rbs);
}

// DEPTH_STENCIL pixels write depth even with the depth test off (as Mesa), and
// glCopyTexImage2D takes a DEPTH24_STENCIL8 internal format.
TEST_F(PackedDepthStencilTest, DrawWithoutDepthTestAndCopyToTexture) {
  const GLuint in[2] = {0x000000ffu, 0xffffff00u};
  glRasterPos2i(0, 0);
  glDrawPixels(2, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, in);
  GLuint out[2] = {1, 1};
  glReadPixels(0, 0, 2, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  EXPECT_EQ(out[0], in[0]);
  EXPECT_EQ(out[1], in[1]);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 0, 0, 2, 1, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 0, 0, 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
  EXPECT_EQ(out[0], in[0]);
  EXPECT_EQ(out[1], in[0]);
  glDeleteTextures(1, &tex);
}

TEST_F(PackedDepthStencilTest, Errors) {
  GLuint v = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  // A framebuffer without stencil has no DEPTH_STENCIL pixels.
  const GLuint color = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint depth = make_renderbuffer(GL_DEPTH_COMPONENT24, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glRasterPos2i(0, 0);
  glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDeleteFramebuffers(1, &fb);
  const GLuint rbs[2] = {color, depth};
  glDeleteRenderbuffers(2, rbs);
}

TEST_F(PackedDepthStencilTest, WindowAndSwapBytes) {
  glClearDepth(0.5);
  glClearStencil(0x5a);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLuint v = 0;
  glReadPixels(3, 3, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_EQ(v, (0x800000u << 8) | 0x5au);  // 0.5 * 16777215 + 0.5 = 8388608
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  glReadPixels(3, 3, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  EXPECT_EQ(v, __builtin_bswap32((0x800000u << 8) | 0x5au));
}

}  // namespace
}  // namespace pineda::test
