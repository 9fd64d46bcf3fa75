// GL 1.4 depth textures (ARB_depth_texture) and shadow comparison (ARB_shadow,
// EXT_shadow_funcs): exact colours for every compare function, the three depth texture modes,
// r / q as the reference, comparison before filtering; in the normal and the reference mode.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr Rgba kPass = {255, 255, 255, 255};
constexpr Rgba kFail = {0, 0, 0, 255};

class DepthTextureTest : public GlTest, public ::testing::WithParamInterface<bool> {
 protected:
  void SetUp() override {
    if (GetParam()) setenv("PINEDA_REFERENCE", "1", 1);
    GlTest::SetUp();
    unsetenv("PINEDA_REFERENCE");
    pixel_projection();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }

  // A width x 1 depth texture of these depths, NEAREST or LINEAR.
  void depth_texture(const std::vector<float>& depths, GLenum filter = GL_NEAREST,
                     GLint internal_format = GL_DEPTH_COMPONENT24) {
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, GLsizei(depths.size()), 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 depths.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }

  void compare(GLenum func) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GLint(func));
  }

  // A 16x16 quad at the origin with s, t from 0 to 1 and the given r and q (s, t, r scaled by q).
  Rgba draw(float r, float q = 1.f) {
    clear_to(0.5f, 0.5f, 0.5f, 0.5f);
    glBegin(GL_QUADS);
    const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& c : corners) {
      glTexCoord4f(c[0] * q, c[1] * q, r * q, q);
      glVertex2f(c[0] * 16, c[1] * 16);
    }
    glEnd();
    return pixel(8, 8);
  }
};

TEST_P(DepthTextureTest, EveryCompareFunction) {
  depth_texture({0.5f});
  struct Case {
    GLenum func;
    bool below, above;  // r = 0.25 and r = 0.75 against the texel's 0.5
  };
  const Case cases[] = {{GL_NEVER, false, false},  {GL_LESS, true, false},    {GL_EQUAL, false, false},
                        {GL_LEQUAL, true, false},  {GL_GREATER, false, true}, {GL_NOTEQUAL, true, true},
                        {GL_GEQUAL, false, true},  {GL_ALWAYS, true, true}};
  for (const Case& c : cases) {
    compare(c.func);
    EXPECT_EQ(draw(0.25f), c.below ? kPass : kFail) << std::hex << c.func;
    EXPECT_EQ(draw(0.75f), c.above ? kPass : kFail) << std::hex << c.func;
  }
}

TEST_P(DepthTextureTest, EqualityAndTheClampedReference) {
  depth_texture({1.f});  // exactly 1 in any depth format
  struct Case {
    GLenum func;
    bool equal;
  };
  const Case cases[] = {{GL_EQUAL, true},    {GL_NOTEQUAL, false}, {GL_LEQUAL, true}, {GL_GEQUAL, true},
                        {GL_LESS, false},    {GL_GREATER, false}};
  for (const Case& c : cases) {
    compare(c.func);
    EXPECT_EQ(draw(1.f), c.equal ? kPass : kFail) << std::hex << c.func;
    EXPECT_EQ(draw(1.5f), c.equal ? kPass : kFail) << std::hex << c.func;  // r is clamped to 1
  }
}

TEST_P(DepthTextureTest, ReferenceIsRDividedByQ) {
  depth_texture({0.5f});
  compare(GL_GREATER);
  EXPECT_EQ(draw(0.75f, 2.f), kPass);  // r = 1.5, q = 2: 0.75 > 0.5
  EXPECT_EQ(draw(0.25f, 4.f), kFail);  // r = 1.0, q = 4: 0.25
}

TEST_P(DepthTextureTest, DepthTextureModes) {
  depth_texture({0.6f});
  glColor4f(1.f, 0.f, 0.f, 1.f);
  EXPECT_EQ(draw(0.f), (Rgba{153, 153, 153, 255}));  // LUMINANCE, the initial mode
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  EXPECT_EQ(draw(0.f), (Rgba{153, 153, 153, 153}));
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
  EXPECT_EQ(draw(0.f), (Rgba{255, 0, 0, 153}));  // REPLACE keeps the fragment's colour
  compare(GL_LEQUAL);  // the comparison result takes the depth's place
  EXPECT_EQ(draw(0.25f), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(draw(0.75f), (Rgba{255, 0, 0, 0}));
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  EXPECT_EQ(draw(0.75f), (Rgba{0, 0, 0, 0}));
}

TEST_P(DepthTextureTest, ComparesEachTexelBeforeFiltering) {
  // Texels 0.25 and 0.75, LINEAR: pixel 5 of the 16-pixel quad has s = 5.5 / 16, so the
  // first texel weighs 0.8125 and the second 0.1875. With r = 0.5 and LEQUAL only the second
  // passes: 0.1875 * 255 = 47.8 -> 48. (Filtering the depths first would give 0.34: a fail.)
  depth_texture({0.25f, 0.75f}, GL_LINEAR);
  compare(GL_LEQUAL);
  draw(0.5f);
  EXPECT_EQ(pixel(5, 8), (Rgba{48, 48, 48, 255}));
  EXPECT_EQ(pixel(1, 8), kFail);  // clamped to the first texel
  EXPECT_EQ(pixel(15, 8), kPass);
}

TEST_P(DepthTextureTest, CompareModeOffReadsTheDepth) {
  depth_texture({0.2f, 0.6f});
  compare(GL_NEVER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  draw(0.5f);
  EXPECT_EQ(pixel(2, 8), (Rgba{51, 51, 51, 255}));
  EXPECT_EQ(pixel(13, 8), (Rgba{153, 153, 153, 255}));
}

TEST_P(DepthTextureTest, CopiedFromTheDepthBuffer) {
  // Depth 0.25 on the left half, 0.75 on the right (glOrtho's z: window depth (1 - z) / 2).
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glClear(GL_DEPTH_BUFFER_BIT);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, 0.5f), glVertex3f(8, 0, 0.5f), glVertex3f(8, 16, 0.5f), glVertex3f(0, 16, 0.5f);
  glVertex3f(8, 0, -0.5f), glVertex3f(16, 0, -0.5f), glVertex3f(16, 16, -0.5f), glVertex3f(8, 16, -0.5f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 16, 16, 0);
  GLint depth_size = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &depth_size);
  EXPECT_EQ(depth_size, 24);
  std::vector<float> back(16 * 16, -1.f);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back.data());
  EXPECT_NEAR(back[0], 0.25f, 1e-6f);
  EXPECT_NEAR(back[15], 0.75f, 1e-6f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  compare(GL_LEQUAL);
  draw(0.5f);
  EXPECT_EQ(pixel(3, 8), kFail);   // 0.5 <= 0.25 fails
  EXPECT_EQ(pixel(12, 8), kPass);  // 0.5 <= 0.75
  // glCopyTexSubImage2D into the depth texture also reads depth: now 0.25 everywhere.
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 8, 0, 0, 0, 8, 16);
  draw(0.5f);
  EXPECT_EQ(pixel(12, 8), kFail);
}

INSTANTIATE_TEST_SUITE_P(Modes, DepthTextureTest, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "Reference" : "Fast"; });

// State and errors (one mode is enough).
class DepthTextureStateTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  GLint level_param(GLenum pname) {
    GLint v = -7;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pname, &v);
    return v;
  }
  GLint tex_param(GLenum pname) {
    GLint v = -7;
    glGetTexParameteriv(GL_TEXTURE_2D, pname, &v);
    return v;
  }
};

TEST_F(DepthTextureStateTest, FormatsAndSizes) {
  float d[16];  // 2x2 RGBA floats at most
  std::fill(d, d + 16, 0.5f);
  struct Case { GLenum format; GLint bits; };
  for (const Case c : {Case{GL_DEPTH_COMPONENT, 24}, Case{GL_DEPTH_COMPONENT16, 16}, Case{GL_DEPTH_COMPONENT24, 24},
                       Case{GL_DEPTH_COMPONENT32, 32}}) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(c.format), 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
    EXPECT_EQ(level_param(GL_TEXTURE_DEPTH_SIZE), c.bits);
    EXPECT_EQ(level_param(GL_TEXTURE_INTERNAL_FORMAT), GLint(c.format));
    EXPECT_EQ(level_param(GL_TEXTURE_LUMINANCE_SIZE), 0);
    EXPECT_EQ(level_param(GL_TEXTURE_RED_SIZE), 0);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_FLOAT, nullptr);  // d holds 4 floats, not 16
  EXPECT_EQ(level_param(GL_TEXTURE_DEPTH_SIZE), 0);
}

TEST_F(DepthTextureStateTest, ValuesAreTruncatedToTheFormatsBits) {
  // As Mesa: 0.5 in 16 bits is 32767 (0.5 * 65535 truncated), in 24 bits 8388607 / 16777215.
  const float d[1] = {0.5f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  GLushort us = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &us);
  EXPECT_EQ(us, 32767);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  float f = 0.f;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
  EXPECT_EQ(f, float(8388607.0 / 16777215.0));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
  EXPECT_EQ(f, 0.5f);
}

TEST_F(DepthTextureStateTest, ParametersAndTheirErrors) {
  EXPECT_EQ(tex_param(GL_DEPTH_TEXTURE_MODE), GL_LUMINANCE);
  EXPECT_EQ(tex_param(GL_TEXTURE_COMPARE_MODE), GL_NONE);
  EXPECT_EQ(tex_param(GL_TEXTURE_COMPARE_FUNC), GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_NOTEQUAL);
  EXPECT_EQ(tex_param(GL_DEPTH_TEXTURE_MODE), GL_ALPHA);
  EXPECT_EQ(tex_param(GL_TEXTURE_COMPARE_MODE), GL_COMPARE_R_TO_TEXTURE);
  EXPECT_EQ(tex_param(GL_TEXTURE_COMPARE_FUNC), GL_NOTEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGBA);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_LEQUAL);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_COMPARE_R_TO_TEXTURE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(tex_param(GL_TEXTURE_COMPARE_FUNC), GL_NOTEQUAL);
  // GL_TEXTURE_BIT saves them.
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  glPopAttrib();
  EXPECT_EQ(tex_param(GL_DEPTH_TEXTURE_MODE), GL_ALPHA);
}

TEST_F(DepthTextureStateTest, FormatMismatchesAreInvalidOperations) {
  const float d[16] = {};  // 2x2 RGBA floats at most
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_RGBA, GL_FLOAT, d);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 1, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_BITMAP, d);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, d);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  float out[16];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_FLOAT, nullptr);  // d holds 4 floats, not 16
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(DepthTextureStateTest, SubImageAndOneDimensional) {
  const float d[4] = {0.f, 0.f, 0.f, 0.f};
  glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT32, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  const GLuint ones[2] = {0xffffffffu, 0x80000000u};
  glTexSubImage1D(GL_TEXTURE_1D, 0, 1, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, ones);
  float back[4] = {-1, -1, -1, -1};
  glGetTexImage(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  EXPECT_EQ(back[0], 0.f);
  EXPECT_EQ(back[1], 1.f);
  EXPECT_NEAR(back[2], 0.5f, 1e-7f);
  EXPECT_EQ(back[3], 0.f);
}

}  // namespace
}  // namespace pineda::test
