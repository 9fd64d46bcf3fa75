// GL_ARB_depth_buffer_float: DEPTH_COMPONENT32F and DEPTH32F_STENCIL8 renderbuffers and
// textures, FLOAT_32_UNSIGNED_INT_24_8_REV pixels, queries, blits and errors.
#include <cstring>
#include <string>

#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

// One FLOAT_32_UNSIGNED_INT_24_8_REV pixel: the depth, then the stencil in the low 8 bits.
struct DepthStencilF {
  float depth;
  GLuint stencil;
};
static_assert(sizeof(DepthStencilF) == 8);

class DepthBufferFloatTest : public FboTest {
 protected:
  // A 4x4 framebuffer object of an RGBA8 colour renderbuffer and a depth renderbuffer of
  // `depth_format` (attached to depth and, for a stencil format, stencil).
  void make_target(GLenum depth_format) {
    color_ = make_renderbuffer(GL_RGBA8, 4, 4);
    depth_ = make_renderbuffer(depth_format, 4, 4);
    fb_ = make_fbo();
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    if (depth_format == GL_DEPTH32F_STENCIL8)
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  }
  void TearDown() override {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb_);
    const GLuint rbs[2] = {color_, depth_};
    glDeleteRenderbuffers(2, rbs);
    FboTest::TearDown();
  }
  float depth_at(int x, int y) {
    float z = -1.f;
    glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
    return z;
  }
  GLuint fb_ = 0, color_ = 0, depth_ = 0;
};

TEST_F(DepthBufferFloatTest, Advertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_depth_buffer_float "), std::string::npos);
}

TEST_F(DepthBufferFloatTest, RenderbufferAndAttachmentQueries) {
  make_target(GL_DEPTH_COMPONENT32F);
  GLint v = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v);
  EXPECT_EQ(v, GL_DEPTH_COMPONENT32F);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v);
  EXPECT_EQ(v, 32);
  EXPECT_EQ(get_int(GL_DEPTH_BITS), 32);
  EXPECT_EQ(get_int(GL_STENCIL_BITS), 0);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &v);
  EXPECT_EQ(v, GL_FLOAT);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &v);
  EXPECT_EQ(v, 32);
  // DEPTH32F_STENCIL8 keeps 8 stencil bits.
  const GLuint ds = make_renderbuffer(GL_DEPTH32F_STENCIL8, 4, 4);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &v);
  EXPECT_EQ(v, 8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(get_int(GL_DEPTH_BITS), 32);
  EXPECT_EQ(get_int(GL_STENCIL_BITS), 8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  glDeleteRenderbuffers(1, &ds);
}

// Clears and depth-tested draws store the depth as a float: 0.5 and 0.75 read back exactly,
// clear values are clamped to [0, 1], and the test keeps the nearer quad.
TEST_F(DepthBufferFloatTest, ClearDrawAndDepthTest) {
  make_target(GL_DEPTH_COMPONENT32F);
  glClearDepth(2.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  EXPECT_EQ(depth_at(0, 0), 1.f);
  glClearDepth(0.75);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glColor3f(1, 0, 0);
  draw_rect(0, 0, 2, 4, 0.f);  // window depth 0.5
  glColor3f(0, 1, 0);
  draw_rect(0, 0, 4, 4, -0.25f);  // 0.625: behind the first quad, in front of the clear
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(depth_at(0, 0), 0.5f);
  EXPECT_EQ(depth_at(3, 3), 0.625f);
  GLubyte px[4][4];
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[0]);
  glReadPixels(2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[1]);
  EXPECT_EQ(px[0][0], 255);
  EXPECT_EQ(px[0][1], 0);
  EXPECT_EQ(px[1][0], 0);
  EXPECT_EQ(px[1][1], 255);
}

// DEPTH_STENCIL pixels of type FLOAT_32_UNSIGNED_INT_24_8_REV through glDrawPixels,
// glReadPixels and glCopyPixels, and read as UNSIGNED_INT_24_8.
TEST_F(DepthBufferFloatTest, PackedFloatPixels) {
  make_target(GL_DEPTH32F_STENCIL8);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  const DepthStencilF in[4] = {{0.25f, 0x42u}, {0.f, 0xffffff07u}, {0.75f, 0x80u}, {1.f, 0xffu}};
  glRasterPos2i(0, 0);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, in);
  DepthStencilF out[4];
  std::memset(out, 0xcd, sizeof out);
  glReadPixels(0, 0, 2, 2, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(out[i].depth, in[i].depth) << i;
    EXPECT_EQ(out[i].stencil, in[i].stencil & 0xffu) << i;  // the unused 24 bits read 0
  }
  GLuint packed = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &packed);
  EXPECT_EQ(packed, (0x400000u << 8) | 0x42u);
  // glCopyPixels of depth and stencil to the top right.
  glRasterPos2i(2, 2);
  glCopyPixels(0, 0, 2, 2, GL_DEPTH_STENCIL);
  glReadPixels(2, 2, 2, 2, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(out[i].depth, in[i].depth) << i;
    EXPECT_EQ(out[i].stencil, in[i].stencil & 0xffu) << i;
  }
}

// A display list keeps the FLOAT_32_UNSIGNED_INT_24_8_REV pixels as they were when compiled.
TEST_F(DepthBufferFloatTest, PackedFloatPixelsInADisplayList) {
  make_target(GL_DEPTH32F_STENCIL8);
  DepthStencilF in[2] = {{0.375f, 6u}, {0.875f, 0x1ffu}};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glRasterPos2i(1, 1);
  glDrawPixels(2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, in);
  glEndList();
  in[0] = {0.f, 0u};
  glCallList(list);
  DepthStencilF out[2] = {};
  glReadPixels(1, 1, 2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
  EXPECT_EQ(out[0].depth, 0.375f);
  EXPECT_EQ(out[0].stencil, 6u);
  EXPECT_EQ(out[1].depth, 0.875f);
  EXPECT_EQ(out[1].stencil, 0xffu);
  glDeleteLists(list, 1);
}

// The window's 24-bit depth buffer takes FLOAT_32_UNSIGNED_INT_24_8_REV pixels too.
TEST_F(DepthBufferFloatTest, PackedFloatPixelsOnTheWindow) {
  const DepthStencilF in[2] = {{1.f, 5u}, {0.f, 0xaau}};
  glRasterPos2i(0, 0);
  glDrawPixels(2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, in);
  DepthStencilF out[2] = {};
  glReadPixels(0, 0, 2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(out[i].depth, in[i].depth) << i;
    EXPECT_EQ(out[i].stencil, in[i].stencil) << i;
  }
  GLuint packed[2] = {};
  glReadPixels(0, 0, 2, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed);
  EXPECT_EQ(packed[0], 0xffffff05u);
  EXPECT_EQ(packed[1], 0xaau);
}

// glCopyTexImage2D and glCopyTexSubImage2D into DEPTH32F_STENCIL8 keep float precision (a
// 24-bit copy would read 0.1 as 1677721 / 16777215).
TEST_F(DepthBufferFloatTest, CopyTexImageKeepsFloatDepth) {
  make_target(GL_DEPTH32F_STENCIL8);
  glClearDepth(0.1f);
  glClearStencil(3);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 0, 0, 2, 1, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glClearDepth(0.2f);
  glClearStencil(4);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 0, 0, 1, 1);
  DepthStencilF out[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
  EXPECT_EQ(out[0].depth, 0.1f);
  EXPECT_EQ(out[0].stencil, 3u);
  EXPECT_EQ(out[1].depth, 0.2f);
  EXPECT_EQ(out[1].stencil, 4u);
  glDeleteTextures(1, &tex);
}

TEST_F(DepthBufferFloatTest, PixelErrors) {
  float v[2] = {};
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDrawPixels(1, 1, GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  // DEPTH_COMPONENT data goes into a depth-stencil format's depth (GL 3.3 3.8.3, as Mesa).
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 1, 1, 0, GL_RGBA, GL_FLOAT, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDeleteTextures(1, &tex);
  // No stencil buffer: no DEPTH_STENCIL pixels.
  make_target(GL_DEPTH_COMPONENT32F);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

// Depth blits copy between DEPTH_COMPONENT32F and DEPTH32F_STENCIL8, not between float and
// integer depth (GL_INVALID_OPERATION, as Mesa).
TEST_F(DepthBufferFloatTest, BlitBetweenFormats) {
  make_target(GL_DEPTH_COMPONENT32F);
  glClearDepth(0.375);
  glClear(GL_DEPTH_BUFFER_BIT);
  const GLuint dst_color = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint dst_depth = make_renderbuffer(GL_DEPTH32F_STENCIL8, 4, 4);
  const GLuint dst_fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, dst_color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, dst_depth);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb_);
  glBlitFramebuffer(0, 0, 2, 2, 0, 0, 2, 2, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, dst_fb);
  EXPECT_EQ(depth_at(1, 1), 0.375f);
  EXPECT_EQ(depth_at(2, 2), 1.f);
  // Integer depth of the same size is another format.
  const GLuint int_depth = make_renderbuffer(GL_DEPTH_COMPONENT32, 4, 4);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, int_depth);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb_);
  glBlitFramebuffer(0, 0, 2, 2, 0, 0, 2, 2, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &dst_fb);
  const GLuint rbs[3] = {dst_color, dst_depth, int_depth};
  glDeleteRenderbuffers(3, rbs);
}

// A DEPTH_COMPONENT32F texture keeps the uploaded floats (clamped to [0, 1]) without
// truncating them to integer bits; its sizes and types say float.
TEST_F(DepthBufferFloatTest, TextureImageAndQueries) {
  const float in[4] = {1e-6f, 0.3f, -1.f, 2.f};
  GLuint tex = make_texture(GL_DEPTH_COMPONENT32F, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, in);
  float out[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out);
  EXPECT_EQ(out[0], 1e-6f);
  EXPECT_EQ(out[1], 0.3f);
  EXPECT_EQ(out[2], 0.f);
  EXPECT_EQ(out[3], 1.f);
  GLint v = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v);
  EXPECT_EQ(v, 32);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_TYPE, &v);
  EXPECT_EQ(v, GL_FLOAT);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE, &v);
  EXPECT_EQ(v, GL_NONE);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
  EXPECT_EQ(v, GL_DEPTH_COMPONENT32F);
  // DEPTH32F_STENCIL8 through FLOAT_32_UNSIGNED_INT_24_8_REV both ways.
  const DepthStencilF ds_in[2] = {{1e-6f, 0x1234u}, {0.625f, 9u}};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 2, 1, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV,
               ds_in);
  DepthStencilF ds_out[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, ds_out);
  EXPECT_EQ(ds_out[0].depth, 1e-6f);
  EXPECT_EQ(ds_out[0].stencil, 0x34u);
  EXPECT_EQ(ds_out[1].depth, 0.625f);
  EXPECT_EQ(ds_out[1].stencil, 9u);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v);
  EXPECT_EQ(v, 8);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_TYPE, &v);
  EXPECT_EQ(v, GL_FLOAT);
  glDeleteTextures(1, &tex);
}

// Rendered into as a depth attachment, then sampled with shadow comparison: the texels hold
// the rendered depth (0.5 on the left, the clear's 1.0 on the right).
TEST_F(DepthBufferFloatTest, RenderToTextureThenShadowCompare) {
  const GLuint depth_tex = make_texture(GL_DEPTH_COMPONENT32F, 4, 4, GL_DEPTH_COMPONENT, GL_FLOAT);
  color_ = make_renderbuffer(GL_RGBA8, 4, 4);
  fb_ = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_tex, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(get_int(GL_DEPTH_BITS), 32);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  draw_rect(0, 0, 2, 4, 0.f);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, depth_tex);
  float texels[16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
  EXPECT_EQ(texels[0], 0.5f);
  EXPECT_EQ(texels[3], 1.f);
  // r = 0.75 against the texels with LEQUAL: fails at 0.5 (black), passes at 1.0 (white).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.75f); glVertex2f(0, 0);
  glTexCoord3f(1, 0, 0.75f); glVertex2f(4, 0);
  glTexCoord3f(1, 1, 0.75f); glVertex2f(4, 4);
  glTexCoord3f(0, 1, 0.75f); glVertex2f(0, 4);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  GLubyte px[2][4];
  glReadPixels(0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[0]);
  glReadPixels(3, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[1]);
  EXPECT_EQ(px[0][0], 0);
  EXPECT_EQ(px[1][0], 255);
  glDeleteTextures(1, &depth_tex);
}

}  // namespace
}  // namespace pineda::test
