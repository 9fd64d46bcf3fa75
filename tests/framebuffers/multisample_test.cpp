// Multisampled renderbuffers (EXT_framebuffer_multisample, ARB_framebuffer_object) and the
// multisample fragment operations: coverage at the standard 4x positions, depth per sample,
// SAMPLE_COVERAGE, SAMPLE_ALPHA_TO_COVERAGE, GL_MULTISAMPLE off, resolve by glBlitFramebuffer.
//
// Samples lie at (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875) of a pixel
// (from its lower-left corner). The resolve averages the 4 samples rounding to nearest:
// k of 4 samples at 255 over 0 give (255 k + 2) / 4 = 0, 64, 128, 191, 255.
#include <array>

#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

constexpr int kSize = 16;

class MultisampleTest : public FboTest {
 protected:
  void SetUp() override {
    FboTest::SetUp();
    ms_fb_ = make_fbo();
    ms_color_ = make_ms_renderbuffer(GL_RGBA8, 4);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ms_color_);
    ms_depth_ = make_ms_renderbuffer(GL_DEPTH_COMPONENT24, 4);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ms_depth_);
    resolve_fb_ = make_fbo();
    resolve_color_ = make_renderbuffer(GL_RGBA8, kSize, kSize);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color_);
    glBindFramebuffer(GL_FRAMEBUFFER, ms_fb_);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  void TearDown() override {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    GLuint fbs[] = {ms_fb_, resolve_fb_}, rbs[] = {ms_color_, ms_depth_, resolve_color_};
    glDeleteFramebuffers(2, fbs);
    glDeleteRenderbuffers(3, rbs);
    FboTest::TearDown();
  }

  GLuint make_ms_renderbuffer(GLenum format, int samples) {
    GLuint rb = 0;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, kSize, kSize);
    return rb;
  }

  static void rect(float x0, float y0, float x1, float y1, float z = 0.f) { draw_rect(x0, y0, x1, y1, z); }

  // Resolves the multisampled framebuffer into the single-sampled one and reads pixel (x, y).
  std::array<int, 4> resolved(int x, int y) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fb_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fb_);
    glBlitFramebuffer(0, 0, kSize, kSize, 0, 0, kSize, kSize, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fb_);
    uint8_t p[4] = {0, 0, 0, 0};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    glBindFramebuffer(GL_FRAMEBUFFER, ms_fb_);
    return {p[0], p[1], p[2], p[3]};
  }

  GLuint ms_fb_ = 0, ms_color_ = 0, ms_depth_ = 0, resolve_fb_ = 0, resolve_color_ = 0;
};

using Rgba = std::array<int, 4>;

TEST_F(MultisampleTest, StateDefaultsAndQueries) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  EXPECT_EQ(get_int(GL_MAX_SAMPLES), 4);
  EXPECT_EQ(get_int(GL_SAMPLE_BUFFERS), 0);  // the window's buffers are single-sampled
  EXPECT_EQ(get_int(GL_SAMPLES), 0);
  EXPECT_TRUE(glIsEnabled(GL_MULTISAMPLE));
  EXPECT_FALSE(glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE));
  EXPECT_FALSE(glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE));
  EXPECT_FALSE(glIsEnabled(GL_SAMPLE_COVERAGE));
  GLfloat value = -1;
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &value);
  EXPECT_EQ(value, 1.f);
  GLboolean invert = GL_TRUE;
  glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &invert);
  EXPECT_EQ(invert, GL_FALSE);
  glBindFramebuffer(GL_FRAMEBUFFER, ms_fb_);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(get_int(GL_SAMPLE_BUFFERS), 1);
  EXPECT_EQ(get_int(GL_SAMPLES), 4);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fb_);
  EXPECT_EQ(get_int(GL_SAMPLE_BUFFERS), 0);
  EXPECT_EQ(get_int(GL_SAMPLES), 0);
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_EXT_framebuffer_multisample "), std::string::npos);
}

TEST_F(MultisampleTest, SampleCountsRoundUpToFour) {
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  for (int asked : {0, 1, 2, 3, 4}) {
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, asked, GL_RGBA8, 4, 4);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GLint samples = -1;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
    EXPECT_EQ(samples, asked == 0 ? 0 : 4) << asked;
  }
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 5, GL_RGBA8, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, -1, GL_RGBA8, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint samples = -1;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
  EXPECT_EQ(samples, 4);  // the failed calls changed nothing
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
  EXPECT_EQ(samples, 0);
  glRenderbufferStorageMultisampleEXT(GL_RENDERBUFFER, 2, GL_DEPTH_COMPONENT24, 4, 4);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
  EXPECT_EQ(samples, 4);
  glDeleteRenderbuffers(1, &rb);
}

TEST_F(MultisampleTest, MixedSampleCountsAreIncomplete) {
  const GLuint depth = make_renderbuffer(GL_DEPTH_COMPONENT24, kSize, kSize);
  glBindFramebuffer(GL_FRAMEBUFFER, ms_fb_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE));
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  // A texture has no samples either.
  const GLuint tex = make_texture(GL_RGBA8, kSize, kSize);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ms_depth_);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glDeleteTextures(1, &tex);
  glDeleteRenderbuffers(1, &depth);
}

TEST_F(MultisampleTest, ReadsFromAMultisampledFramebufferAreErrors) {
  uint8_t p[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLuint tex = make_texture(GL_RGBA8, 4, 4);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDeleteTextures(1, &tex);
}

TEST_F(MultisampleTest, BlitErrors) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fb_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fb_);
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 16, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);  // scaled
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBlitFramebuffer(0, 0, 8, 8, 1, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);  // narrower
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBlitFramebuffer(0, 8, 8, 0, 0, 8, 8, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);  // mirrored alike: allowed
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A resolve may land elsewhere and mirrored, at the same size (EXT_framebuffer_multisample, as Mesa).
TEST_F(MultisampleTest, ResolveIntoAnotherPlace) {
  glColor3f(1, 0, 0);
  rect(0, 0, 1, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fb_);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fb_);
  glBlitFramebuffer(0, 0, 2, 2, 5, 3, 7, 5, GL_COLOR_BUFFER_BIT, GL_NEAREST);  // moved
  glBlitFramebuffer(0, 0, 2, 2, 12, 12, 10, 10, GL_COLOR_BUFFER_BIT, GL_NEAREST);  // moved and mirrored
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fb_);
  EXPECT_EQ(pixel(5, 3), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(6, 3), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(pixel(4, 3), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(pixel(11, 11), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(10, 10), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 255, 255}));
}

// Right edges at x = 2 + t cover the samples of pixel column 2 whose x is below t.
TEST_F(MultisampleTest, CoverageOfAnEdgeAcrossAPixel) {
  glColor3f(1, 1, 1);
  const float t[5] = {0.f, 0.25f, 0.5f, 0.75f, 1.f};
  for (int band = 0; band < 5; ++band) rect(0, 3 * band, 2 + t[band], 3 * band + 3);
  const int expected[5] = {0, 64, 128, 191, 255};
  for (int band = 0; band < 5; ++band) {
    EXPECT_EQ(resolved(2, 3 * band + 1), (Rgba{expected[band], expected[band], expected[band], expected[band]})) << band;
    EXPECT_EQ(resolved(1, 3 * band + 1), (Rgba{255, 255, 255, 255})) << band;
    EXPECT_EQ(resolved(3, 3 * band + 1), (Rgba{0, 0, 0, 0})) << band;
  }
}

// Several draw buffers of a multisampled framebuffer: every buffer gets the coverage per sample,
// in its own format (RGB565: 255 for the missing alpha of each sample).
TEST_F(MultisampleTest, CoverageInEveryDrawBuffer) {
  const GLuint second = make_ms_renderbuffer(GL_RGB565, 4);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, second);
  const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, both);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  rect(0, 0, 2.5f, 4);  // pixel 2: 2 of 4 samples
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fb_);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fb_);
  glBlitFramebuffer(0, 0, kSize, kSize, 0, 0, kSize, kSize, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fb_);
  uint8_t p[4] = {0, 0, 0, 0};
  glReadPixels(2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ((Rgba{p[0], p[1], p[2], p[3]}), (Rgba{128, 128, 128, 255}));
  glBindFramebuffer(GL_FRAMEBUFFER, ms_fb_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  EXPECT_EQ(resolved(2, 1), (Rgba{128, 128, 128, 128}));
  EXPECT_EQ(resolved(1, 1), (Rgba{255, 255, 255, 255}));
  glDeleteRenderbuffers(1, &second);
}

// Top edges at y = 2 + t: samples at y 0.125, 0.375, 0.625, 0.875. An edge through a sample:
// the top edge does not own it (the fill rule at samples as at pixel centres).
TEST_F(MultisampleTest, CoverageOfATopEdgeAndTheFillRule) {
  glColor3f(1, 1, 1);
  rect(0, 0, 3, 2.3f);     // samples below 0.3: one
  rect(4, 0, 7, 2.375f);   // through sample 1's y: one
  rect(8, 0, 11, 2.4f);    // above it (positions snap to 1/256 px): two
  EXPECT_EQ(resolved(1, 2)[0], 64);
  EXPECT_EQ(resolved(5, 2)[0], 64);
  EXPECT_EQ(resolved(9, 2)[0], 128);
}

// A triangle edge on the diagonal through pixel (2, 2)'s lower-left and upper-right corners:
// samples below it are (0.375, 0.125) and (0.875, 0.375).
TEST_F(MultisampleTest, CoverageOfADiagonalEdge) {
  glColor3f(1, 0, 0);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(16, 0);
  glVertex2f(16, 16);
  glEnd();
  EXPECT_EQ(resolved(2, 2), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(3, 2), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(2, 3), (Rgba{0, 0, 0, 0}));
}

// Each sample keeps its own depth: the far quad shows only where the near one left samples.
TEST_F(MultisampleTest, DepthIsTestedPerSample) {
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  rect(0, 0, 4.5f, 16, 0.5f);  // near: glOrtho(..., -1, 1) puts z = 0.5 at depth 0.25
  glColor3f(0, 1, 0);
  rect(0, 0, 16, 16, -0.4f);
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(resolved(4, 8), (Rgba{128, 128, 0, 255}));
  EXPECT_EQ(resolved(3, 8), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(5, 8), (Rgba{0, 255, 0, 255}));
}

TEST_F(MultisampleTest, SampleCoverage) {
  glEnable(GL_SAMPLE_COVERAGE);
  glSampleCoverage(0.5f, GL_FALSE);  // samples 0 and 1
  glColor3f(1, 0, 0);
  rect(0, 0, 16, 16);
  glSampleCoverage(0.5f, GL_TRUE);  // samples 2 and 3
  glColor3f(0, 1, 0);
  rect(0, 0, 16, 16);
  glSampleCoverage(0.25f, GL_FALSE);  // sample 0: blue over red
  glColor3f(0, 0, 1);
  rect(0, 0, 8, 16);
  glDisable(GL_SAMPLE_COVERAGE);
  EXPECT_EQ(resolved(12, 8), (Rgba{128, 128, 0, 255}));
  EXPECT_EQ(resolved(4, 8), (Rgba{64, 128, 64, 255}));
}

TEST_F(MultisampleTest, AlphaToCoverage) {
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  const float alpha[4] = {0.1f, 0.3f, 0.5f, 0.8f};  // round(alpha * 4) samples: 0, 1, 2, 3
  for (int band = 0; band < 4; ++band) {
    glColor4f(1, 1, 1, alpha[band]);
    rect(0, 4 * band, 16, 4 * band + 4);
  }
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  const int expected[4] = {0, 64, 128, 191};
  for (int band = 0; band < 4; ++band) EXPECT_EQ(resolved(8, 4 * band + 2)[0], expected[band]) << band;
}

// Alpha to coverage and the alpha test both apply, to the same alpha (GL 1.5 4.1.3, 4.1.4).
TEST_F(MultisampleTest, AlphaToCoverageWithAlphaTest) {
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEnable(GL_ALPHA_TEST);
  const float alpha[4] = {0.1f, 0.3f, 0.5f, 0.8f};  // alpha to coverage alone: 0, 1, 2, 3 samples
  const struct {
    GLenum func;
    float ref;
    int expected[4];  // resolved red of each band
  } cases[] = {{GL_GREATER, 0.2f, {0, 64, 128, 191}},
               {GL_LESS, 0.6f, {0, 64, 128, 0}},
               {GL_EQUAL, 0.5f, {0, 0, 128, 0}},
               {GL_NOTEQUAL, 0.3f, {0, 0, 128, 191}},
               {GL_NEVER, 0.0f, {0, 0, 0, 0}}};
  for (const auto& c : cases) {
    glClear(GL_COLOR_BUFFER_BIT);
    glAlphaFunc(c.func, c.ref);
    for (int band = 0; band < 4; ++band) {
      glColor4f(1, 1, 1, alpha[band]);
      rect(0, 4 * band, 16, 4 * band + 4);
    }
    for (int band = 0; band < 4; ++band)
      EXPECT_EQ(resolved(8, 4 * band + 2)[0], c.expected[band]) << "func " << c.func << ", band " << band;
  }
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
}

// GL 1.5 4.1.3: SAMPLE_ALPHA_TO_ONE sets alpha to 1 after alpha to coverage, before blending.
TEST_F(MultisampleTest, AlphaToOne) {
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glColor4f(1, 1, 1, 0.5f);  // 2 of 4 samples, with alpha 1
  rect(0, 0, 16, 8);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  EXPECT_EQ(resolved(8, 4), (Rgba{128, 128, 128, 128}));  // alpha 0.5 kept: 64
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1, 0, 0, 0.25f);
  rect(0, 8, 16, 12);  // alpha 1: the source replaces the destination
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  rect(0, 12, 16, 16);  // alpha 0.25
  glDisable(GL_BLEND);
  EXPECT_EQ(resolved(8, 10), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(8, 14), (Rgba{64, 0, 0, 16}));
}

// GL_MULTISAMPLE off: alpha to one is off with the other multisample operations.
TEST_F(MultisampleTest, AlphaToOneNeedsMultisample) {
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glDisable(GL_MULTISAMPLE);
  glColor4f(1, 1, 1, 0.5f);
  rect(0, 0, 16, 16);
  glEnable(GL_MULTISAMPLE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  EXPECT_EQ(resolved(8, 8), (Rgba{255, 255, 255, 128}));
}

// The fragment shader's alpha too.
TEST_F(MultisampleTest, AlphaToOneWithAFragmentShader) {
  const GLuint p = fragment_program("void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 0.25); }");
  glUseProgram(p);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  rect(0, 0, 16, 16);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  glUseProgram(0);
  glDeleteProgram(p);
  EXPECT_EQ(resolved(8, 8), (Rgba{0, 255, 0, 255}));
}

// A fragment shader's alpha decides both tests too.
TEST_F(MultisampleTest, AlphaToCoverageWithAlphaTestAndAFragmentShader) {
  const GLuint p = fragment_program("void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 0.5); }");
  glUseProgram(p);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_LESS, 0.6f);  // passes; alpha to coverage keeps 2 of 4 samples
  rect(0, 0, 16, 8);
  glAlphaFunc(GL_GREATER, 0.6f);  // fails
  rect(0, 8, 16, 16);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glUseProgram(0);
  glDeleteProgram(p);
  EXPECT_EQ(resolved(8, 4), (Rgba{0, 128, 0, 64}));
  EXPECT_EQ(resolved(8, 12), (Rgba{0, 0, 0, 0}));
}

// GL 1.5 3.4.4: a multisampled line covers the samples inside the rectangle of its width
// centred on the segment. Sample rows of the 4x pattern lie at y + 1/8, 3/8, 5/8, 7/8.
TEST_F(MultisampleTest, LinesCoverTheSamplesOfTheirRectangle) {
  const auto line = [](float x0, float y0, float x1, float y1) {
    glBegin(GL_LINES);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glEnd();
  };
  glColor3f(1, 0, 0);
  line(2, 2.5f, 14, 2.5f);  // width 1 on row 2's centre: [2, 3] holds its four samples
  line(2, 6.0f, 14, 6.0f);  // [5.5, 6.5]: the upper two samples of row 5, the lower two of row 6
  glLineWidth(2.0f);
  line(2, 11.0f, 14, 11.0f);  // [10, 12]: rows 10 and 11 whole
  glLineWidth(1.0f);
  line(8.5f, 13, 8.5f, 15);  // vertical, on column 8's centre: rows 13 and 14 whole
  EXPECT_EQ(resolved(8, 2), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(8, 1), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(resolved(8, 3), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(resolved(8, 5), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(8, 6), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(8, 10), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(8, 11), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(8, 12), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(resolved(8, 13), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(8, 14), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(7, 14), (Rgba{0, 0, 0, 0}));
  // The ends: x in [2, 14] holds column 1's samples at x + 7/8 and 5/8 not, column 2's all.
  EXPECT_EQ(resolved(1, 2), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(resolved(13, 2), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(14, 2), (Rgba{0, 0, 0, 0}));
}

void point(float x, float y) {
  glBegin(GL_POINTS);
  glVertex2f(x, y);
  glEnd();
}

// GL 1.5 3.3.3: a multisampled point covers the samples inside the circle of its size centred
// on it, whatever POINT_SMOOTH says. Samples lie 1/8 and 3/8 px from their pixel's centre.
TEST_F(MultisampleTest, PointsCoverTheSamplesOfTheirCircle) {
  glColor3f(1, 0, 0);
  glPointSize(3.0f);
  point(4.5f, 4.5f);  // radius 1.5 on pixel (4, 4)'s centre
  // A corner pixel keeps its two samples 1.08 and 1.29 px from the centre, not the ones 1.63
  // and 1.78 px away; the pixels beside the centre are covered whole.
  EXPECT_EQ(resolved(4, 4), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(5, 4), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(4, 3), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(3, 3), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(5, 5), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(3, 5), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(6, 4), (Rgba{0, 0, 0, 0}));
  // Off the pixel centre, at (11.25, 11.75): pixels with 1, 2 and 3 samples within 1.5 px.
  glEnable(GL_POINT_SMOOTH);  // no effect on a multisampled point
  point(11.25f, 11.75f);
  glDisable(GL_POINT_SMOOTH);
  EXPECT_EQ(resolved(11, 11), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(12, 11), (Rgba{191, 0, 0, 191}));  // all but (12.875, 11.375), 1.67 px away
  EXPECT_EQ(resolved(9, 11), (Rgba{64, 0, 0, 64}));     // (9.875, 11.375) only
  EXPECT_EQ(resolved(12, 12), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(10, 10), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(12, 10), (Rgba{64, 0, 0, 64}));
  EXPECT_EQ(resolved(11, 13), (Rgba{64, 0, 0, 64}));
  EXPECT_EQ(resolved(10, 13), (Rgba{0, 0, 0, 0}));
}

// A multisampled point sprite covers the samples of its square, [x - size/2, x + size/2) in x
// and in y (llvmpipe's rule too: a sample on the left or bottom side is covered).
TEST_F(MultisampleTest, PointSpritesCoverTheSamplesOfTheirSquare) {
  glEnable(GL_POINT_SPRITE);
  glColor3f(0, 1, 0);
  glPointSize(3.0f);
  point(4.5f, 4.5f);
  EXPECT_EQ(resolved(3, 3), (Rgba{0, 255, 0, 255}));  // the square's corner, not the circle's
  EXPECT_EQ(resolved(5, 5), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(resolved(6, 4), (Rgba{0, 0, 0, 0}));
  glPointSize(2.0f);
  point(11.375f, 11.125f);  // [10.375, 12.375) x [10.125, 12.125)
  glDisable(GL_POINT_SPRITE);
  EXPECT_EQ(resolved(10, 10), (Rgba{0, 191, 0, 191}));  // all but the sample at x + 1/8
  EXPECT_EQ(resolved(10, 11), (Rgba{0, 191, 0, 191}));
  EXPECT_EQ(resolved(11, 11), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(resolved(12, 10), (Rgba{0, 64, 0, 64}));  // the sample at x + 1/8 only
  EXPECT_EQ(resolved(11, 12), (Rgba{0, 0, 0, 0}));  // its lowest sample (y + 1/8) lies on the top side
}

// A multisampled sprite's replaced texture coordinates run across its square as single-sampled:
// each pixel's colour from its centre, its coverage from its samples.
TEST_F(MultisampleTest, PointSpriteCoordinatesAcrossItsSquare) {
  const GLuint tex = make_texture(GL_RGBA8, 2, 2);
  const uint8_t texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_POINT_SPRITE);
  glPointSize(4.0f);
  point(8.25f, 8.0f);  // [6.25, 10.25) x [6, 10): s = 1/2 + (x + 1/2 - 8.25) / 4
  glDisable(GL_POINT_SPRITE);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
  EXPECT_EQ(resolved(6, 6), (Rgba{191, 0, 0, 191}));  // s 1/16, t 1/8; 3 samples right of 6.25
  EXPECT_EQ(resolved(7, 9), (Rgba{0, 0, 255, 255}));  // s 5/16, t 7/8
  EXPECT_EQ(resolved(9, 9), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(resolved(10, 7), (Rgba{0, 64, 0, 64}));  // s 17/16 (clamped), t 3/8; the sample at 10.125
  EXPECT_EQ(resolved(8, 10), (Rgba{0, 0, 0, 0}));
}

// GL 1.4 3.3: with multisampling on, a point whose derived size is under
// POINT_FADE_THRESHOLD_SIZE is drawn at the threshold size with its alpha multiplied by
// (size / threshold)^2; with multisampling off it keeps its size and alpha.
TEST_F(MultisampleTest, PointFadeUnderTheThresholdSize) {
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 2.0f);
  glColor4f(1, 1, 1, 1);
  glPointSize(1.0f);
  point(4.5f, 4.5f);  // diameter 2, alpha 1/4 (64)
  EXPECT_EQ(resolved(4, 4), (Rgba{255, 255, 255, 64}));
  EXPECT_EQ(resolved(5, 4), (Rgba{128, 128, 128, 32}));  // 2 samples within 1 px
  EXPECT_EQ(resolved(4, 3), (Rgba{128, 128, 128, 32}));
  EXPECT_EQ(resolved(5, 5), (Rgba{0, 0, 0, 0}));
  glPointSize(3.0f);
  point(11.5f, 4.5f);  // above the threshold: no fade
  EXPECT_EQ(resolved(11, 4), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(resolved(10, 3), (Rgba{128, 128, 128, 128}));
  glPointSize(1.0f);
  glDisable(GL_MULTISAMPLE);
  point(4.5f, 11.5f);
  glEnable(GL_MULTISAMPLE);
  EXPECT_EQ(resolved(4, 11), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(resolved(5, 11), (Rgba{0, 0, 0, 0}));
}

// A point drawn right after a rectangle of the same state fades all the same: the rectangle's
// draw record (made without fading) does not serve it (Scene::repeat_of_current_draw).
TEST_F(MultisampleTest, APointAfterARectangleOfTheSameStateStillFades) {
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 2.0f);
  glColor4f(1, 1, 1, 1);
  glPointSize(1.0f);
  rect(0, 0, 2, 2);
  point(4.5f, 4.5f);  // diameter 2, alpha 1/4 (64)
  EXPECT_EQ(resolved(1, 1), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(resolved(4, 4), (Rgba{255, 255, 255, 64}));
}

// With GL_MULTISAMPLE off a fragment covers all samples or none, by its pixel centre, and
// SAMPLE_COVERAGE no longer applies.
TEST_F(MultisampleTest, MultisampleDisabledUsesPixelCentres) {
  glDisable(GL_MULTISAMPLE);
  glEnable(GL_SAMPLE_COVERAGE);
  glSampleCoverage(0.5f, GL_FALSE);
  glColor3f(1, 1, 1);
  rect(0, 0, 2.4f, 4);
  rect(0, 4, 2.6f, 8);
  glDisable(GL_SAMPLE_COVERAGE);
  glEnable(GL_MULTISAMPLE);
  EXPECT_EQ(resolved(2, 2)[0], 0);
  EXPECT_EQ(resolved(2, 6)[0], 255);
  EXPECT_EQ(resolved(1, 6)[0], 255);
}

TEST_F(MultisampleTest, ClearAndBlitBetweenSampleCounts) {
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(resolved(5, 5), (Rgba{51, 102, 153, 204}));
  // Single-sampled into multisampled: every sample takes the source pixel.
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fb_);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fb_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ms_fb_);
  glBlitFramebuffer(0, 0, 8, 16, 0, 0, 8, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(resolved(3, 3), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(12, 3), (Rgba{51, 102, 153, 204}));
  // Multisampled into multisampled: sample by sample.
  GLuint fb2 = make_fbo();
  GLuint rb2 = make_ms_renderbuffer(GL_RGBA8, 4);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb2);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0, 1, 0);
  rect(0, 0, 2.5f, 16);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb2);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ms_fb_);
  glBlitFramebuffer(0, 0, 16, 16, 0, 0, 16, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(resolved(2, 8), (Rgba{0, 128, 0, 128}));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fb2);
  glDeleteRenderbuffers(1, &rb2);
}

// A multisampled draw shades each pixel once, at its centre, and then tests and writes each
// sample on its own (raster/sample_targets.h). The tests below check the per-sample half.

// Draws of a fragment shader shade once per pixel for all samples; plain fixed-function draws
// (with a fill routine) run once per sample plane: the per-sample tests below take both.
class MultisampleBothPathsTest : public MultisampleTest, public ::testing::WithParamInterface<bool> {
 protected:
  void SetUp() override {
    MultisampleTest::SetUp();
    if (GetParam()) {
      program_ = fragment_program("void main() { gl_FragColor = gl_Color; }");
      glUseProgram(program_);
    }
  }
  void TearDown() override {
    glUseProgram(0);
    if (program_) glDeleteProgram(program_);
    MultisampleTest::TearDown();
  }
  GLuint program_ = 0;
};

INSTANTIATE_TEST_SUITE_P(FixedFunctionAndShader, MultisampleBothPathsTest, ::testing::Bool());

// Depth is interpolated at each sample, not at the pixel centre: the red plane is nearer than
// the green one left of x = 8.4, which splits pixel 8's samples (x 8.125, 8.375 | 8.625, 8.875).
TEST_P(MultisampleBothPathsTest, DepthIsInterpolatedAtEachSample) {
  glEnable(GL_DEPTH_TEST);
  glColor3f(0, 1, 0);
  rect(0, 0, 16, 16, 0.f);
  glColor3f(1, 0, 0);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, 0.42f);
  glVertex3f(16, 0, -0.38f);
  glVertex3f(16, 16, -0.38f);
  glVertex3f(0, 16, 0.42f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(resolved(7, 8), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(8, 8), (Rgba{128, 128, 0, 255}));
  EXPECT_EQ(resolved(9, 8), (Rgba{0, 255, 0, 255}));
}

// Stencil counts per sample: pixel 2's samples are covered 2, 0, 2 and 1 times by the two
// rectangles (sample x 2.375, 2.875, 2.125, 2.625).
TEST_P(MultisampleBothPathsTest, StencilIsUpdatedPerSample) {
  const GLuint ds = make_ms_renderbuffer(GL_DEPTH24_STENCIL8, 4);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  rect(0, 0, 2.5f, 8);
  rect(0, 0, 2.75f, 8);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_EQUAL, 2, 0xff);
  glColor3f(1, 0, 0);
  rect(0, 0, 16, 16);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glColor3f(0, 1, 0);
  rect(0, 0, 16, 16);
  glDisable(GL_STENCIL_TEST);
  EXPECT_EQ(resolved(1, 4), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(resolved(2, 4), (Rgba{128, 64, 0, 191}));
  EXPECT_EQ(resolved(3, 4), (Rgba{0, 0, 0, 0}));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ms_depth_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  glDeleteRenderbuffers(1, &ds);
}

// gl_FragCoord is the pixel centre for a pixel partly covered (pixel 3: 2 of 4 samples), and a
// discard drops every sample of the pixel.
TEST_F(MultisampleTest, OneShadeAtThePixelCentreDecidesEverySample) {
  const GLuint p = fragment_program(
      "void main() { if (gl_FragCoord.x != 3.5 || gl_FragCoord.y == 5.5) discard;"
      " gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }");
  glUseProgram(p);
  rect(0, 0, 3.5f, 16);
  glUseProgram(0);
  glDeleteProgram(p);
  EXPECT_EQ(resolved(3, 4), (Rgba{128, 0, 0, 128}));
  EXPECT_EQ(resolved(3, 5), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(resolved(2, 4), (Rgba{0, 0, 0, 0}));
}

// gl_FragCoord.z is the depth at the pixel centre too (the one shading serves every sample):
// window depth x / 16 here, 0.21875 at pixel 3's centre (red 56), where its two covered samples
// (x 3.125, 3.375) would give 50 and 54.
TEST_F(MultisampleTest, FragCoordDepthIsThePixelCentres) {
  const GLuint p = fragment_program("void main() { gl_FragColor = vec4(gl_FragCoord.z, 0.0, 0.0, 1.0); }");
  glUseProgram(p);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, 1.f);
  glVertex3f(3.5f, 0, 1.f - 3.5f / 8);
  glVertex3f(3.5f, 16, 1.f - 3.5f / 8);
  glVertex3f(0, 16, 1.f);
  glEnd();
  glUseProgram(0);
  glDeleteProgram(p);
  EXPECT_EQ(resolved(3, 8), (Rgba{28, 0, 0, 128}));  // (56 + 56 + 0 + 0 + 2) / 4
}

// A linearly filtered texture is sampled at the pixel centre, where texel 2 of a ramp lies
// exactly (at a sample's position it would blend two texels): pixel 2's two covered samples
// both take texel 2's red, 32.
TEST_F(MultisampleTest, TexturesAreSampledAtThePixelCentre) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  uint8_t ramp[16 * 4];
  for (int i = 0; i < 16; ++i) {
    ramp[4 * i] = static_cast<uint8_t>(16 * i);
    ramp[4 * i + 1] = ramp[4 * i + 2] = 0;
    ramp[4 * i + 3] = 255;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0.5f); glVertex2f(0, 0);
  glTexCoord2f(2.5f / 16, 0.5f); glVertex2f(2.5f, 0);
  glTexCoord2f(2.5f / 16, 0.5f); glVertex2f(2.5f, 16);
  glTexCoord2f(0, 0.5f); glVertex2f(0, 16);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
  EXPECT_EQ(resolved(1, 8), (Rgba{16, 0, 0, 255}));
  EXPECT_EQ(resolved(2, 8), (Rgba{16, 0, 0, 128}));  // (32 + 32 + 0 + 0 + 2) / 4
}

}  // namespace
}  // namespace pineda::test
