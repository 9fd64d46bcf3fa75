// Several draw buffers of a framebuffer object written at once (glDrawBuffers with colour
// attachments, GL 2.0 / ARB_draw_buffers): fixed-function colour into every draw buffer,
// gl_FragData[i] into draw buffer i, each buffer in its own format, one depth and stencil
// update, blending, logic op and masks per buffer, clears, blits and pixel rectangles; the
// errors and state of glDrawBuffers on a framebuffer object.
#include <array>
#include <vector>

#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

constexpr int kSize = 16;

// glColor4ub(200, 100, 50, 150) as each format stores it (rounded to its bits, widened back
// to 8; a missing alpha reads 1).
constexpr Rgba kRgba8{200, 100, 50, 150};
constexpr Rgba kRgb565{197, 101, 49, 255};
constexpr Rgba kRgba4{204, 102, 51, 153};
constexpr Rgba kRgb8{200, 100, 50, 255};

class DrawBuffersFboTest : public FboTest {
 protected:
  void SetUp() override {
    FboTest::SetUp();
    fb_ = make_fbo();
    rbs_[0] = make_renderbuffer(GL_RGBA8, kSize, kSize);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbs_[0]);
    rbs_[1] = make_renderbuffer(GL_RGB565, kSize, kSize);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, rbs_[1]);
    texs_[0] = make_texture(GL_RGBA4, kSize, kSize);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, texs_[0], 0);
    texs_[1] = make_texture(GL_RGB8, kSize, kSize);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, texs_[1], 0);
    rbs_[2] = make_renderbuffer(GL_DEPTH24_STENCIL8, kSize, kSize);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rbs_[2]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rbs_[2]);
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
    all_four();  // the 16x16 window's pixel projection and viewport fit the attachments
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }
  void TearDown() override {
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb_);
    glDeleteRenderbuffers(3, rbs_.data());
    glDeleteTextures(2, texs_.data());
    FboTest::TearDown();
  }

  static void all_four() {
    const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    glDrawBuffers(4, bufs);
  }

  // Pixel (x, y) of colour attachment i.
  Rgba attachment_pixel(int i, int x, int y) {
    glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
    return pixel(x, y);
  }

  std::array<GLenum, 4> draw_buffers() {
    std::array<GLenum, 4> v{};
    for (int i = 0; i < 4; ++i) v[size_t(i)] = GLenum(get_int(GL_DRAW_BUFFER0 + i));
    return v;
  }

  GLuint fb_ = 0;
  std::array<GLuint, 3> rbs_{};
  std::array<GLuint, 2> texs_{};
};

TEST_F(DrawBuffersFboTest, Limits) {
  EXPECT_EQ(get_int(GL_MAX_DRAW_BUFFERS), 8);
  EXPECT_EQ(get_int(GL_MAX_COLOR_ATTACHMENTS), 8);
}

TEST_F(DrawBuffersFboTest, FixedFunctionColourGoesToEveryDrawBufferInItsFormat) {
  glColor4ub(200, 100, 50, 150);
  draw_rect(2, 2, 6, 6);
  EXPECT_EQ(attachment_pixel(0, 3, 3), kRgba8);
  EXPECT_EQ(attachment_pixel(1, 3, 3), kRgb565);
  EXPECT_EQ(attachment_pixel(2, 3, 3), kRgba4);
  EXPECT_EQ(attachment_pixel(3, 3, 3), kRgb8);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(attachment_pixel(i, 8, 8)[0], 0) << i;  // outside the rectangle
  EXPECT_EQ(attachment_pixel(1, 8, 8), (Rgba{0, 0, 0, 255}));  // no alpha: reads 1
}

TEST_F(DrawBuffersFboTest, ClearClearsEveryDrawBuffer) {
  glClearColor(200 / 255.f, 100 / 255.f, 50 / 255.f, 150 / 255.f);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(attachment_pixel(0, 9, 9), kRgba8);
  EXPECT_EQ(attachment_pixel(1, 9, 9), kRgb565);
  EXPECT_EQ(attachment_pixel(2, 9, 9), kRgba4);
  EXPECT_EQ(attachment_pixel(3, 9, 9), kRgb8);
  // Only the selected draw buffers.
  const GLenum one[] = {GL_NONE, GL_COLOR_ATTACHMENT3};
  glDrawBuffers(2, one);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(attachment_pixel(0, 9, 9), kRgba8);
  EXPECT_EQ(attachment_pixel(3, 9, 9), (Rgba{0, 255, 0, 255}));
}

TEST_F(DrawBuffersFboTest, FragDataGoesToItsDrawBuffer) {
  const GLuint p = fragment_program(
      "void main() {\n"
      "  gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);\n"
      "  gl_FragData[1] = vec4(0.0, 1.0, 0.0, 1.0);\n"
      "  gl_FragData[2] = vec4(0.0, 0.0, 1.0, 1.0);\n"
      "  gl_FragData[3] = vec4(1.0, 1.0, 1.0, 0.0);\n"
      "}\n");
  glUseProgram(p);
  draw_rect(0, 0, 8, 8);
  EXPECT_EQ(attachment_pixel(0, 4, 4), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(attachment_pixel(1, 4, 4), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(attachment_pixel(2, 4, 4), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(attachment_pixel(3, 4, 4), (Rgba{255, 255, 255, 255}));  // RGB8: alpha reads 1
  // Draw buffer i names any attachment; NONE skips an output.
  const GLenum shuffled[] = {GL_COLOR_ATTACHMENT3, GL_NONE, GL_COLOR_ATTACHMENT0};
  glDrawBuffers(3, shuffled);
  glClearColor(0.2f, 0.2f, 0.2f, 0.2f);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_rect(8, 8, 16, 16);
  EXPECT_EQ(attachment_pixel(3, 12, 12), (Rgba{255, 0, 0, 255}));  // gl_FragData[0]
  EXPECT_EQ(attachment_pixel(0, 12, 12), (Rgba{0, 0, 255, 255}));  // gl_FragData[2]
  EXPECT_EQ(attachment_pixel(1, 12, 12), (Rgba{0, 0, 0, 255}));    // not a draw buffer: not drawn
  EXPECT_EQ(attachment_pixel(2, 12, 12), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(attachment_pixel(0, 4, 4), (Rgba{51, 51, 51, 51}));  // cleared
  glDeleteProgram(p);
}

TEST_F(DrawBuffersFboTest, FragColorGoesToEveryDrawBuffer) {
  const GLuint p = fragment_program("void main() { gl_FragColor = vec4(200.0, 100.0, 50.0, 150.0) / 255.0; }");
  glUseProgram(p);
  draw_rect(0, 0, 4, 4);
  EXPECT_EQ(attachment_pixel(0, 1, 1), kRgba8);
  EXPECT_EQ(attachment_pixel(1, 1, 1), kRgb565);
  EXPECT_EQ(attachment_pixel(2, 1, 1), kRgba4);
  EXPECT_EQ(attachment_pixel(3, 1, 1), kRgb8);
  glDeleteProgram(p);
}

// Each fragment is depth- and stencil-tested once: with GL_LESS a second buffer would fail
// against the depth the first one wrote, and INCR would count twice.
void draw_depth_stencil_scene() {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
  glColor3f(1, 0, 0);
  draw_rect(0, 0, 8, 8, -0.5f);  // window depth 0.75
  glColor3f(0, 1, 0);
  draw_rect(4, 4, 12, 12, 0.0f);  // 0.5, nearer: wins where it overlaps
  glColor3f(0, 0, 1);
  draw_rect(0, 0, 12, 12, -0.9f);  // 0.95, farther: fails everywhere but the empty corners
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
}

TEST_F(DrawBuffersFboTest, DepthAndStencilAreUpdatedOnce) {
  for (const bool shader : {false, true}) {
    SCOPED_TRACE(shader ? "fragment shader" : "fixed function");
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    const GLuint p = shader ? fragment_program("void main() { gl_FragData[0] = gl_Color; gl_FragData[1] = gl_Color;"
                                               " gl_FragData[2] = gl_Color; gl_FragData[3] = gl_Color; }")
                            : 0;
    glUseProgram(p);
    draw_depth_stencil_scene();
    glUseProgram(0);
    glDeleteProgram(p);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(attachment_pixel(i, 1, 1)[0], 255) << i;
      EXPECT_EQ(attachment_pixel(i, 6, 6)[1], 255) << i;
      EXPECT_EQ(attachment_pixel(i, 10, 10)[1], 255) << i;
      EXPECT_EQ(attachment_pixel(i, 10, 1)[2], 255) << i;
    }
    GLubyte stencil[3] = {};
    glReadPixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil[0]);
    glReadPixels(6, 6, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil[1]);
    glReadPixels(10, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil[2]);
    EXPECT_EQ(stencil[0], 2);  // red passed, blue failed depth: each INCR once
    EXPECT_EQ(stencil[1], 3);
    EXPECT_EQ(stencil[2], 1);
    GLfloat depth = -1;
    glReadPixels(6, 6, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    EXPECT_NEAR(depth, 0.5, 1e-6);
  }
}

TEST_F(DrawBuffersFboTest, OcclusionQueryCountsEachFragmentOnce) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  draw_rect(0, 0, 5, 3);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint n = 0;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &n);
  EXPECT_EQ(n, 15u);
  glDeleteQueries(1, &q);
}

TEST_F(DrawBuffersFboTest, BlendingReadsEachBuffersOwnColour) {
  const float clear[2][4] = {{0.2f, 0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.4f, 0.0f}};
  const GLenum two[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT3};
  for (int i = 0; i < 2; ++i) {
    glDrawBuffer(two[i]);
    glClearColor(clear[i][0], clear[i][1], clear[i][2], clear[i][3]);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glDrawBuffers(2, two);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(0, 0.6f, 0, 1);
  draw_rect(0, 0, 4, 4);
  glDisable(GL_BLEND);
  EXPECT_EQ(attachment_pixel(0, 1, 1), (Rgba{51, 153, 0, 255}));
  EXPECT_EQ(attachment_pixel(3, 1, 1), (Rgba{0, 153, 102, 255}));
  // Logic op and the colour mask apply to each buffer too.
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glColor4ub(0xff, 0xff, 0x0f, 0xff);
  draw_rect(0, 0, 4, 4);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_COLOR_LOGIC_OP);
  EXPECT_EQ(attachment_pixel(0, 1, 1), (Rgba{51 ^ 0xff, 153, 0x0f, 255}));
  EXPECT_EQ(attachment_pixel(3, 1, 1), (Rgba{0xff, 153, 102 ^ 0x0f, 255}));
}

// A target without alpha reads alpha 1 as the destination, even where its texture level was
// made without data and never cleared (piglit's fbo-blending-format-quirks "alpha expand").
TEST_F(DrawBuffersFboTest, DestinationAlphaOfAnRgbTargetIsOne) {
  const GLuint tex = make_texture(GL_RGB, kSize, kSize, GL_RGBA, GL_FLOAT);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex, 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_ALPHA, GL_ZERO);
  glColor4f(1, 1, 1, 1);
  draw_rect(0, 0, 4, 4);
  glDisable(GL_BLEND);
  EXPECT_EQ(attachment_pixel(0, 1, 1), (Rgba{0, 0, 0, 0}));  // RGBA8 cleared to alpha 0
  EXPECT_EQ(attachment_pixel(1, 1, 1), (Rgba{255, 255, 255, 255}));
  glDeleteTextures(1, &tex);
}

// GL 3.0 4.1.4: with several draw buffers the alpha test takes colour 0's alpha.
TEST_F(DrawBuffersFboTest, AlphaTestUsesColourZero) {
  const GLuint p = fragment_program(
      "void main() {\n"
      "  gl_FragData[0] = vec4(1.0, 0.0, 0.0, gl_FragCoord.x < 4.0 ? 0.0 : 1.0);\n"
      "  gl_FragData[1] = vec4(0.0, 1.0, 0.0, gl_FragCoord.x < 4.0 ? 1.0 : 0.0);\n"
      "}\n");
  glUseProgram(p);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  draw_rect(0, 0, 8, 8);
  glDisable(GL_ALPHA_TEST);
  EXPECT_EQ(attachment_pixel(0, 1, 1), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(attachment_pixel(1, 1, 1), (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(attachment_pixel(0, 6, 1), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(attachment_pixel(1, 6, 1), (Rgba{0, 255, 0, 255}));
  glDeleteProgram(p);
}

TEST_F(DrawBuffersFboTest, BlitAndDrawPixelsWriteEveryDrawBuffer) {
  const GLuint src = make_renderbuffer(GL_RGBA8, kSize, kSize);
  GLuint src_fb = 0;
  glGenFramebuffers(1, &src_fb);
  glBindFramebuffer(GL_FRAMEBUFFER, src_fb);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, src);
  glClearColor(200 / 255.f, 100 / 255.f, 50 / 255.f, 150 / 255.f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb_);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, fb_);
  EXPECT_EQ(attachment_pixel(0, 1, 1), kRgba8);
  EXPECT_EQ(attachment_pixel(1, 1, 1), kRgb565);
  EXPECT_EQ(attachment_pixel(2, 1, 1), kRgba4);
  EXPECT_EQ(attachment_pixel(3, 1, 1), kRgb8);
  const GLubyte px[4] = {200, 100, 50, 150};
  glWindowPos2i(10, 10);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(attachment_pixel(0, 10, 10), kRgba8);
  EXPECT_EQ(attachment_pixel(1, 10, 10), kRgb565);
  EXPECT_EQ(attachment_pixel(2, 10, 10), kRgba4);
  EXPECT_EQ(attachment_pixel(3, 10, 10), kRgb8);
  glDeleteFramebuffers(1, &src_fb);
  glDeleteRenderbuffers(1, &src);
}

TEST_F(DrawBuffersFboTest, TextureAttachmentShowsTheRendering) {
  glColor4ub(200, 100, 50, 150);
  draw_rect(0, 0, kSize, kSize);
  std::vector<GLubyte> texels(kSize * kSize * 4);
  glBindTexture(GL_TEXTURE_2D, texs_[0]);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ((Rgba{texels[0], texels[1], texels[2], texels[3]}), kRgba4);
}

TEST_F(DrawBuffersFboTest, StateIsPerFramebuffer) {
  EXPECT_EQ(draw_buffers(), (std::array<GLenum, 4>{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                                   GL_COLOR_ATTACHMENT3}));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  EXPECT_EQ(draw_buffers()[1], GLenum(GL_NONE));
  glBindFramebuffer(GL_FRAMEBUFFER, fb_);
  EXPECT_EQ(draw_buffers()[3], GLenum(GL_COLOR_ATTACHMENT3));
  glDrawBuffer(GL_COLOR_ATTACHMENT1);  // the other outputs become NONE
  EXPECT_EQ(draw_buffers(), (std::array<GLenum, 4>{GL_COLOR_ATTACHMENT1, GL_NONE, GL_NONE, GL_NONE}));
  glColor3f(1, 1, 1);
  draw_rect(0, 0, 2, 2);
  EXPECT_EQ(attachment_pixel(1, 0, 0), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(attachment_pixel(0, 0, 0), (Rgba{0, 0, 0, 0}));
  glDrawBuffers(0, nullptr);
  EXPECT_EQ(draw_buffers(), (std::array<GLenum, 4>{GL_NONE, GL_NONE, GL_NONE, GL_NONE}));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_rect(0, 0, 4, 4);
  EXPECT_EQ(attachment_pixel(1, 3, 3), (Rgba{0, 0, 0, 255}));
}

TEST_F(DrawBuffersFboTest, Errors) {
  struct Case {
    GLenum buffer;
    GLenum error;
  };
  const Case cases[] = {
      {GL_BACK, GL_INVALID_OPERATION},        // a window-system buffer
      {GL_FRONT_LEFT, GL_INVALID_OPERATION},
      {GL_BACK_LEFT, GL_INVALID_OPERATION},
      {GL_AUX0, GL_INVALID_OPERATION},
      {GL_COLOR_ATTACHMENT8, GL_INVALID_OPERATION},  // past MAX_COLOR_ATTACHMENTS
      {GL_FRONT, GL_INVALID_ENUM},                   // names of several buffers
      {GL_FRONT_AND_BACK, GL_INVALID_ENUM},
      {GL_LEFT, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, GL_INVALID_ENUM},
  };
  for (const Case& c : cases) {
    const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, c.buffer};
    glDrawBuffers(2, bufs);
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.buffer;
  }
  const GLenum nine[9] = {GL_COLOR_ATTACHMENT0};  // more than MAX_DRAW_BUFFERS, the rest NONE
  glDrawBuffers(9, nine);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDrawBuffers(-1, nine);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLenum twice[] = {GL_COLOR_ATTACHMENT1, GL_NONE, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(3, twice);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  // Failed calls changed nothing.
  EXPECT_EQ(draw_buffers(), (std::array<GLenum, 4>{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                                   GL_COLOR_ATTACHMENT3}));
  // An attachment without an image is allowed (its output is dropped).
  const GLenum empty[] = {GL_COLOR_ATTACHMENT7};
  glDrawBuffers(1, empty);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// A draw buffer naming an empty attachment point leaves the framebuffer complete, whichever
// draw buffer it is, through the EXT entry point too (GL_ARB_ES2_compatibility, as Mesa).
TEST_F(FboTest, ExtStatusIgnoresDrawBuffersWithoutImages) {
  const GLuint depth = make_renderbuffer(GL_DEPTH_COMPONENT24, 8, 8);
  const GLuint fb = make_fbo();
  glDrawBuffer(GL_COLOR_ATTACHMENT7);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  const GLenum second[] = {GL_NONE, GL_COLOR_ATTACHMENT2};
  glDrawBuffers(2, second);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &depth);
}

}  // namespace
}  // namespace pineda::test
