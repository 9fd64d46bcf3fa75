// Rendering into textures and renderbuffers, then reading and sampling what was rendered:
// exact pixel values.
#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

using RenderToTextureTest = FboTest;

// Left half red, right half green, drawn into an 8x8 texture; then the texture drawn on the
// window, magnified 2x.
TEST_F(RenderToTextureTest, RenderThenSample) {
  const GLuint tex = make_texture(GL_RGBA8, 8, 8);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 8, 8);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 8, 0, 8, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  clear_to(0, 0, 1, 1);
  glColor4f(1, 0, 0, 1);
  draw_window_quad(4, 8);
  glColor4f(0, 1, 0, 0.5f);
  glBegin(GL_QUADS);
  glVertex2f(4, 0); glVertex2f(8, 0); glVertex2f(8, 4); glVertex2f(4, 4);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(1, 1), {255, 0, 0, 255}));   // read from the framebuffer object
  EXPECT_TRUE(near_rgba(pixel(6, 1), {0, 255, 0, 128}));
  EXPECT_TRUE(near_rgba(pixel(6, 6), {0, 0, 255, 255}));

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 16, 16);
  pixel_projection();
  clear_to(0, 0, 0, 0);
  glColor4f(1, 1, 1, 1);
  draw_textured(tex, 16, 16);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(12, 3), {0, 255, 0, 128}));
  EXPECT_TRUE(near_rgba(pixel(12, 12), {0, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(3, 12), {255, 0, 0, 255}));

  // glGetTexImage sees the rendering too.
  std::vector<uint8_t> texels(8 * 8 * 4);
  glBindTexture(GL_TEXTURE_2D, tex);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(texels[0], 255);
  EXPECT_EQ(texels[(1 * 8 + 7) * 4 + 1], 255);
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
}

// Rendering again after the texture was sampled: the next sampling sees the new image.
TEST_F(RenderToTextureTest, RenderSampleRenderSample) {
  const GLuint tex = make_texture(GL_RGBA8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  for (int round = 0; round < 3; ++round) {
    const float v = 0.25f * float(round + 1);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    clear_to(v, 0, 0, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    clear_to(0, 0, 0, 0);
    draw_textured(tex, 16, 16);
    EXPECT_TRUE(near_rgba(pixel(8, 8), {to_byte(v), 0, 0, 255})) << round;
  }
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
}

// A draw into the framebuffer object that samples the texture it renders into takes the
// texture as it was before the draw (a defined result for a feedback loop).
TEST_F(RenderToTextureTest, FeedbackLoopSamplesThePreviousImage) {
  const GLuint tex = make_texture(GL_RGBA8, 16, 16);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  clear_to(0, 1, 0, 1);
  glColor4f(1, 1, 1, 1);
  draw_textured(tex, 16, 16);
  EXPECT_TRUE(near_rgba(pixel(5, 5), {0, 255, 0, 255}));
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
}

// The same with two draws and no call between them: the second samples what the first rendered
// (a draw keeps what it worked out from the state while no call changes it, the texture's image
// included: a draw into a texture counts as a change).
TEST_F(RenderToTextureTest, FeedbackLoopDrawsOfAnUnchangedStateSampleWhatTheDrawBeforeRendered) {
  const GLuint tex = make_texture(GL_RGBA8, 2, 1);
  const GLubyte red_blue[] = {255, 0, 0, 255, 0, 0, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, red_blue);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 2, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 2, 0, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  // Pixel 0 takes texel 1 (blue); then pixel 1 takes texel 0, which the first draw made blue.
  GLfloat positions[] = {0, 0, 1, 0, 1, 1, 0, 1};
  GLfloat texcoords[] = {0.75f, 0.5f, 0.75f, 0.5f, 0.75f, 0.5f, 0.75f, 0.5f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glTexCoordPointer(2, GL_FLOAT, 0, texcoords);
  glDrawArrays(GL_QUADS, 0, 4);
  for (int i = 0; i < 4; ++i) {
    positions[2 * i] += 1;
    texcoords[2 * i] = 0.25f;
  }
  glDrawArrays(GL_QUADS, 0, 4);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisable(GL_TEXTURE_2D);
  EXPECT_TRUE(near_rgba(pixel(0, 0), {0, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(1, 0), {0, 0, 255, 255}));
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
}

TEST_F(RenderToTextureTest, CubeFaceAnd3DLayerAndLevel) {
  GLuint cube = 0;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLuint vol = 0;
  glGenTextures(1, &vol);
  glBindTexture(GL_TEXTURE_3D, vol);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint tex = make_texture(GL_RGBA8, 8, 8);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint fb = make_fbo();

  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, cube, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  clear_to(1, 0, 1, 1);
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, vol, 0, 2);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  clear_to(0, 1, 1, 1);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, vol, 0, 3);  // past the depth
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 1);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  clear_to(1, 1, 0, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  std::vector<uint8_t> texels(4 * 4 * 4);
  glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(std::vector<uint8_t>(texels.begin(), texels.begin() + 4), (std::vector<uint8_t>{255, 0, 255, 255}));
  glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(texels[0], 0);  // another face: untouched
  std::vector<uint8_t> volume(2 * 2 * 3 * 4);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, volume.data());
  EXPECT_EQ(volume[4 * 4 * 2 + 1], 255);  // slice 2
  EXPECT_EQ(volume[4 * 4 * 1 + 1], 0);    // slice 1
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(std::vector<uint8_t>(texels.begin() + 60, texels.end()), (std::vector<uint8_t>{255, 255, 0, 255}));
  glDeleteFramebuffers(1, &fb);
  const GLuint texs[3] = {cube, vol, tex};
  glDeleteTextures(3, texs);
}

TEST_F(RenderToTextureTest, DepthRenderbuffer) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 16, 16);
  const GLuint depth = make_renderbuffer(GL_DEPTH_COMPONENT16, 16, 16);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  draw_window_quad(16, 16, -0.25f);  // window depth 0.625 (glOrtho's z is negated)
  glColor3f(0, 1, 0);
  draw_window_quad(8, 16, 0.5f);     // window depth 0.25, nearer: wins on the left
  glColor3f(0, 0, 1);
  draw_window_quad(16, 8, -0.75f);   // window depth 0.875, farther: loses everywhere
  glDisable(GL_DEPTH_TEST);
  EXPECT_TRUE(near_rgba(pixel(2, 2), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(12, 2), {255, 0, 0, 255}));
  GLushort z[2] = {0, 0};
  glReadPixels(2, 2, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &z[0]);
  glReadPixels(12, 2, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &z[1]);
  EXPECT_EQ(z[0], 16384);  // 0.25 * 65535 = 16383.75
  EXPECT_EQ(z[1], 40959);  // 0.625 * 65535 = 40959.375
  glDeleteFramebuffers(1, &fb);
  const GLuint rbs[2] = {color, depth};
  glDeleteRenderbuffers(2, rbs);
}

TEST_F(RenderToTextureTest, StencilRenderbuffer) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 16, 16);
  const GLuint stencil = make_renderbuffer(GL_STENCIL_INDEX8, 16, 16);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearStencil(0);
  clear_to(0, 0, 0, 1);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  draw_window_quad(4, 16);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilFunc(GL_EQUAL, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glColor3f(1, 1, 1);
  draw_window_quad(16, 16);
  glDisable(GL_STENCIL_TEST);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(10, 1), {0, 0, 0, 255}));
  GLubyte s[2] = {0, 0};
  glReadPixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[0]);
  glReadPixels(10, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[1]);
  EXPECT_EQ(s[0], 6);
  EXPECT_EQ(s[1], 0);
  glDeleteFramebuffers(1, &fb);
  const GLuint rbs[2] = {color, stencil};
  glDeleteRenderbuffers(2, rbs);
}

// Rendering into a depth texture, then sampling it with the shadow comparison.
TEST_F(RenderToTextureTest, DepthTextureRenderedThenCompared) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 16, 16);
  const GLuint depth = make_texture(GL_DEPTH_COMPONENT24, 16, 16, GL_DEPTH_COMPONENT, GL_FLOAT);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(get_int(GL_DEPTH_BITS), 24);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  draw_window_quad(8, 16, 0.f);  // left half at depth 0.5
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<float> z(16 * 16);
  glBindTexture(GL_TEXTURE_2D, depth);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, z.data());
  EXPECT_NEAR(z[3], 0.5f, 1e-6);
  EXPECT_EQ(z[12], 1.f);
  // r = 0.75 passes LEQUAL only where the texture holds 1.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  clear_to(0, 0, 0, 0);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.75f); glVertex2f(0, 0);
  glTexCoord3f(1, 0, 0.75f); glVertex2f(16, 0);
  glTexCoord3f(1, 1, 0.75f); glVertex2f(16, 16);
  glTexCoord3f(0, 1, 0.75f); glVertex2f(0, 16);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {0, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(12, 3), {255, 255, 255, 255}));
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &color);
  glDeleteTextures(1, &depth);
}

// Attaching the attached depth texture again (as glmark2's shadow scene does every frame) keeps
// what was rendered into it, queued or finished, and what is rendered after.
TEST_F(RenderToTextureTest, AttachingTheSameDepthTextureAgainKeepsItsDepths) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 16, 16);
  const GLuint depth = make_texture(GL_DEPTH_COMPONENT24, 16, 16, GL_DEPTH_COMPONENT, GL_FLOAT);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  const auto attach = [&] { glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0); };
  attach();
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  draw_rect(0, 0, 8, 16, 0.f);  // left half at depth 0.5, still queued when attached again
  attach();
  draw_rect(8, 0, 16, 16, 0.5f);  // right half at 0.25 (the fixture's glOrtho turns z)
  std::vector<float> z(16 * 16);
  glBindTexture(GL_TEXTURE_2D, depth);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, z.data());
  EXPECT_NEAR(z[3], 0.5f, 1e-6);
  EXPECT_NEAR(z[12], 0.25f, 1e-6);
  attach();
  draw_rect(0, 0, 16, 8, -0.5f);  // depth 0.75: fails the test everywhere
  draw_rect(0, 0, 4, 16, 1.f);  // depth 0 at the left edge
  glDisable(GL_DEPTH_TEST);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, z.data());
  EXPECT_EQ(z[1], 0.f);
  EXPECT_NEAR(z[5], 0.5f, 1e-6);
  EXPECT_NEAR(z[12], 0.25f, 1e-6);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &color);
  glDeleteTextures(1, &depth);
}

// Formats with fewer bits than 8: each pixel is stored as the format keeps it.
TEST_F(RenderToTextureTest, ReducedColourFormats) {
  struct Case { GLenum format; Rgba expected; } cases[] = {
      {GL_RGB565, {132, 130, 132, 255}},
      {GL_RGBA4, {136, 136, 136, 136}},
      {GL_RGB5_A1, {132, 132, 132, 255}},
      {GL_RGB8, {128, 128, 128, 255}},
      {GL_RGBA8, {128, 128, 128, 128}},
  };
  for (const Case& c : cases) {
    const GLuint rb = make_renderbuffer(c.format, 16, 16);
    const GLuint fb = make_fbo();
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE)) << std::hex << c.format;
    clear_to(0.5f, 0.5f, 0.5f, 0.5f);
    EXPECT_TRUE(near_rgba(pixel(1, 1), c.expected)) << "clear " << std::hex << c.format;
    glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
    draw_window_quad(16, 16);
    EXPECT_TRUE(near_rgba(pixel(3, 3), c.expected)) << "draw " << std::hex << c.format;
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &rb);
  }
  // A luminance texture keeps red in all three colour channels.
  const GLuint lum = make_texture(GL_LUMINANCE8, 4, 4, GL_LUMINANCE);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, lum, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(get_int(GL_RED_BITS), 0);
  clear_to(0.2f, 0.6f, 1.f, 0.f);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {51, 0, 0, 255}));  // read back as red, as Mesa
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<uint8_t> texels(4 * 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(texels[0], 51);
  clear_to(0, 0, 0, 0);
  draw_textured(lum, 16, 16);  // sampled as luminance; REPLACE keeps the colour's alpha (0.5)
  EXPECT_TRUE(near_rgba(pixel(3, 3), {51, 51, 51, 128}));
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &lum);
}

TEST_F(RenderToTextureTest, GenerateMipmap) {
  const GLuint tex = make_texture(GL_RGBA8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  clear_to(0, 0, 0, 1);
  glColor4f(1, 1, 1, 1);
  draw_window_quad(2, 4);  // the left half white
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glGenerateMipmap(GL_TEXTURE_2D);
  GLint w = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 1);
  uint8_t level1[2 * 2 * 4], level2[4];
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, level1);
  glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, level2);
  EXPECT_EQ(level1[0], 255);
  EXPECT_EQ(level1[4], 0);
  EXPECT_EQ(level2[0], 128);
  EXPECT_EQ(level2[3], 255);
  glGenerateMipmap(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLuint cube = 0;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // not cube complete
  glDeleteFramebuffers(1, &fb);
  const GLuint texs[2] = {tex, cube};
  glDeleteTextures(2, texs);
}

// glCopyPixels and glCopyTexSubImage read the read framebuffer; glDrawPixels draws into the
// draw framebuffer.
TEST_F(RenderToTextureTest, PixelCopiesBetweenFramebuffers) {
  const GLuint src = make_renderbuffer(GL_RGBA8, 16, 16);
  const GLuint dst = make_texture(GL_RGBA8, 16, 16);
  GLuint fb[2];
  glGenFramebuffers(2, fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, src);
  clear_to(0, 0, 1, 1);
  const uint8_t yellow[4] = {255, 255, 0, 255};
  glRasterPos2i(2, 3);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, yellow);
  EXPECT_TRUE(near_rgba(pixel(2, 3), {255, 255, 0, 255}));
  glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, dst, 0);
  clear_to(0, 0, 0, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  glRasterPos2i(10, 10);
  glCopyPixels(2, 3, 1, 1, GL_COLOR);  // from fb[0] into fb[1]
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
  EXPECT_TRUE(near_rgba(pixel(10, 10), {255, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(2, 3), {0, 0, 0, 0}));
  // glCopyTexSubImage2D from fb[0] into the window's bound texture.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  const GLuint copy = make_texture(GL_RGBA8, 2, 2);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 3, 2, 2);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  uint8_t texels[16];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  EXPECT_EQ(std::vector<uint8_t>(texels, texels + 8), (std::vector<uint8_t>{255, 255, 0, 255, 0, 0, 255, 255}));
  glDeleteFramebuffers(2, fb);
  glDeleteRenderbuffers(1, &src);
  const GLuint texs[2] = {dst, copy};
  glDeleteTextures(2, texs);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// Each slice of a 3D texture in turn, drawn with client arrays (as piglit's fbo-3d).
TEST_F(RenderToTextureTest, EverySliceOfA3DTexture) {
  GLuint vol = 0;
  glGenTextures(1, &vol);
  glBindTexture(GL_TEXTURE_3D, vol);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint fb = make_fbo();
  const float quad[] = {-2, -2, 0, 1, 10, -2, 0, 1, -2, 10, 0, 1, 10, 10, 0, 1};
  for (int z = 0; z < 4; ++z) {
    glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, vol, 0, z);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << z;
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glColor4f(0.25f * float(z), 1, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(4, GL_FLOAT, 0, quad);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << z;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<uint8_t> volume(8 * 8 * 4 * 4);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, volume.data());
  for (int z = 0; z < 4; ++z) EXPECT_EQ(volume[size_t(z) * 8 * 8 * 4], to_byte(0.25 * z)) << z;
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &vol);
}

}  // namespace
}  // namespace pineda::test
