// Per-fragment operations: stencil, alpha test, blending, logic op.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class FragmentOpsTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
  GLubyte stencil_at(int x, int y) {
    GLubyte s = 0xEE;
    glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
    return s;
  }
};

TEST_F(FragmentOpsTest, StencilMasksALaterDraw) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glRecti(0, 0, 10, 32);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  EXPECT_EQ(stencil_at(5, 5), 1);
  EXPECT_EQ(stencil_at(15, 5), 0);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(1, 1, 1);
  glRecti(0, 0, 32, 32);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 10 * 32);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glColor3f(1, 0, 0);
  glRecti(0, 0, 32, 32);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 22 * 32);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FragmentOpsTest, StencilOperations) {
  glClearStencil(5);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glRecti(0, 0, 4, 4);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 7);
  glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 6);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 0xf9);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);  // saturates at 255
  for (int i = 0; i < 8; ++i) glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 0);
  glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);  // saturates at 0
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 0);
  // The write mask keeps the masked-off bits.
  glStencilMask(0xf0);
  glStencilFunc(GL_ALWAYS, 0xab, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 0xa0);
  EXPECT_EQ(stencil_at(10, 10), 5);
}

TEST_F(FragmentOpsTest, StencilFailAndDepthFailOperations) {
  glClearStencil(0);
  glClearDepth(0.5);
  glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glStencilFunc(GL_NEVER, 3, 0xff);
  glStencilOp(GL_REPLACE, GL_KEEP, GL_KEEP);
  glRectf(-1, -1, 0, 0);  // z = 0: window depth 0.5, fails GL_LESS against 0.5
  EXPECT_EQ(stencil_at(4, 4), 3);
  glStencilFunc(GL_ALWAYS, 9, 0xff);
  glStencilOp(GL_KEEP, GL_REPLACE, GL_ZERO);
  glRectf(-1, -1, 0, 0);
  EXPECT_EQ(stencil_at(4, 4), 9);
  EXPECT_TRUE(near_rgba(pixel(4, 4), {0, 0, 0, 0}));
}

TEST_F(FragmentOpsTest, StencilValueMask) {
  glClearStencil(0x35);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0x05, 0x0f);  // (ref & mask) == (stencil & mask)
  glColor3f(1, 1, 1);
  glRecti(0, 0, 2, 2);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 4);
  glStencilFunc(GL_EQUAL, 0x05, 0xff);
  glColor3f(1, 0, 0);
  glRecti(0, 0, 2, 2);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 0);
}

TEST_F(FragmentOpsTest, AlphaTest) {
  glEnable(GL_ALPHA_TEST);
  glColor4f(1, 1, 1, 0.4f);
  glAlphaFunc(GL_GREATER, 0.5f);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  glAlphaFunc(GL_LESS, 0.5f);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(count_pixels({255, 255, 255, 102}), 16);
  glAlphaFunc(GL_NEVER, 0.f);
  glColor4f(1, 0, 0, 1);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(count_pixels({255, 255, 255, 102}), 16);
  // A smooth alpha ramp: only the half above the reference passes.
  clear_to(0, 0, 0, 0);
  glAlphaFunc(GL_GEQUAL, 0.5f);
  glBegin(GL_QUADS);
  glColor4f(0, 1, 0, 0);
  glVertex2f(0, 0);
  glColor4f(0, 1, 0, 1);
  glVertex2f(32, 0);
  glVertex2f(32, 1);
  glColor4f(0, 1, 0, 0);
  glVertex2f(0, 1);
  glEnd();
  for (int x = 0; x < 32; ++x) {
    if (x == 15 || x == 16) continue;  // within rounding of the reference
    const Rgba p = pixel(x, 0);
    EXPECT_EQ(p[1], x > 16 ? 255 : 0) << x;
  }
}

struct BlendCase {
  GLenum src, dst;
};

class BlendTest : public FragmentOpsTest, public ::testing::WithParamInterface<BlendCase> {};

double factor(GLenum f, int channel, const double s[4], const double d[4], const double c[4]) {
  switch (f) {
    case GL_ZERO: return 0;
    case GL_ONE: return 1;
    case GL_SRC_COLOR: return s[channel];
    case GL_ONE_MINUS_SRC_COLOR: return 1 - s[channel];
    case GL_DST_COLOR: return d[channel];
    case GL_ONE_MINUS_DST_COLOR: return 1 - d[channel];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 1 - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 1 - d[3];
    case GL_CONSTANT_COLOR: return c[channel];
    case GL_ONE_MINUS_CONSTANT_COLOR: return 1 - c[channel];
    case GL_CONSTANT_ALPHA: return c[3];
    case GL_ONE_MINUS_CONSTANT_ALPHA: return 1 - c[3];
    case GL_SRC_ALPHA_SATURATE: return channel == 3 ? 1 : std::min(s[3], 1 - d[3]);
  }
  return -1;
}

TEST_P(BlendTest, FactorsMatchTheEquation) {
  const BlendCase b = GetParam();
  const int src_bytes[4] = {255, 128, 64, 153}, dst_bytes[4] = {51, 204, 102, 77};
  const double constant[4] = {0.2, 0.4, 0.6, 0.8};
  double s[4], d[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = src_bytes[i] / 255.0;
    d[i] = dst_bytes[i] / 255.0;
  }
  clear_to(float(d[0]), float(d[1]), float(d[2]), float(d[3]));
  glEnable(GL_BLEND);
  glBlendFunc(b.src, b.dst);
  glBlendColor(float(constant[0]), float(constant[1]), float(constant[2]), float(constant[3]));
  glColor4ub(GLubyte(src_bytes[0]), GLubyte(src_bytes[1]), GLubyte(src_bytes[2]), GLubyte(src_bytes[3]));
  glRecti(0, 0, 4, 4);
  Rgba expected;
  for (int i = 0; i < 4; ++i) {
    const double v = s[i] * factor(b.src, i, s, d, constant) + d[i] * factor(b.dst, i, s, d, constant);
    expected[i] = to_byte(std::clamp(v, 0.0, 1.0));
  }
  EXPECT_TRUE(near_rgba(pixel(2, 2), expected, 1)) << std::hex << b.src << " " << b.dst;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

INSTANTIATE_TEST_SUITE_P(
    Factors, BlendTest,
    ::testing::Values(BlendCase{GL_ONE, GL_ZERO}, BlendCase{GL_ZERO, GL_ONE}, BlendCase{GL_ONE, GL_ONE},
                      BlendCase{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}, BlendCase{GL_DST_COLOR, GL_ZERO},
                      BlendCase{GL_ONE_MINUS_DST_COLOR, GL_SRC_COLOR}, BlendCase{GL_ZERO, GL_ONE_MINUS_SRC_COLOR},
                      BlendCase{GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA}, BlendCase{GL_SRC_ALPHA_SATURATE, GL_ONE},
                      BlendCase{GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR},
                      BlendCase{GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA}));

TEST_F(FragmentOpsTest, BlendEquations) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  struct Case {
    GLenum eq;
    Rgba expected;
  };
  // source (200, 100, 50, 255) over destination (100, 150, 50, 0)
  const Case cases[] = {{GL_FUNC_ADD, {255, 250, 100, 255}},
                        {GL_FUNC_SUBTRACT, {100, 0, 0, 255}},
                        {GL_FUNC_REVERSE_SUBTRACT, {0, 50, 0, 0}},
                        {GL_MIN, {100, 100, 50, 0}},
                        {GL_MAX, {200, 150, 50, 255}}};
  for (const Case& c : cases) {
    clear_to(100 / 255.f, 150 / 255.f, 50 / 255.f, 0);
    glBlendEquation(c.eq);
    glColor4ub(200, 100, 50, 255);
    glRecti(0, 0, 2, 2);
    EXPECT_TRUE(near_rgba(pixel(1, 1), c.expected, 1)) << std::hex << c.eq;
  }
}

// GL_EXT_blend_equation_separate: the alpha equation apart from the colour one; a negative
// reverse-subtract result clamps to 0 (piglit gl-1.0-blend-func uses the EXT name at GL 1.1).
TEST_F(FragmentOpsTest, BlendEquationSeparateEXT) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  clear_to(100 / 255.f, 150 / 255.f, 50 / 255.f, 60 / 255.f);
  glBlendEquationSeparateEXT(GL_FUNC_ADD, GL_FUNC_REVERSE_SUBTRACT);
  glColor4ub(20, 30, 40, 80);
  glRecti(0, 0, 2, 2);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {120, 180, 90, 0}));
  GLint rgb = 0, alpha = 0;
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &rgb);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &alpha);
  EXPECT_EQ(rgb, GL_FUNC_ADD);
  EXPECT_EQ(alpha, GL_FUNC_REVERSE_SUBTRACT);
  glBlendEquationSeparateEXT(GL_FUNC_ADD, GL_FUNC_SUBTRACT);
  clear_to(100 / 255.f, 150 / 255.f, 50 / 255.f, 60 / 255.f);
  glRecti(0, 0, 2, 2);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {120, 180, 90, 20}));
  glBlendEquationSeparateEXT(GL_FUNC_ADD, GL_LINE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(FragmentOpsTest, LogicOps) {
  const uint8_t s = 0xF0 ^ 0x3C, d = 0xAA;
  struct Case {
    GLenum op;
    uint8_t result;
  };
  const Case cases[] = {
      {GL_CLEAR, 0},           {GL_AND, uint8_t(s & d)},          {GL_AND_REVERSE, uint8_t(s & ~d)},
      {GL_COPY, s},            {GL_AND_INVERTED, uint8_t(~s & d)}, {GL_NOOP, d},
      {GL_XOR, uint8_t(s ^ d)}, {GL_OR, uint8_t(s | d)},          {GL_NOR, uint8_t(~(s | d))},
      {GL_EQUIV, uint8_t(~(s ^ d))}, {GL_INVERT, uint8_t(~d)},    {GL_OR_REVERSE, uint8_t(s | ~d)},
      {GL_COPY_INVERTED, uint8_t(~s)}, {GL_OR_INVERTED, uint8_t(~s | d)}, {GL_NAND, uint8_t(~(s & d))},
      {GL_SET, 0xff}};
  glEnable(GL_COLOR_LOGIC_OP);
  for (const Case& c : cases) {
    glDisable(GL_COLOR_LOGIC_OP);
    clear_to(d / 255.f, d / 255.f, d / 255.f, d / 255.f);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(c.op);
    glColor4ub(s, s, s, s);
    glRecti(0, 0, 2, 2);
    EXPECT_TRUE(near_rgba(pixel(0, 0), {c.result, c.result, c.result, c.result})) << std::hex << c.op;
    EXPECT_TRUE(near_rgba(pixel(3, 3), {d, d, d, d})) << std::hex << c.op;
  }
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(FragmentOpsTest, StencilReferenceIsClampedToTheStencilRange) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 300, 0xff);
  GLint ref = 0;
  glGetIntegerv(GL_STENCIL_REF, &ref);
  EXPECT_EQ(ref, 255);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glRecti(0, 0, 2, 2);
  EXPECT_EQ(stencil_at(1, 1), 255);
  glStencilFunc(GL_ALWAYS, -5, 0xff);
  glRecti(0, 0, 2, 2);
  EXPECT_EQ(stencil_at(1, 1), 0);
  clear_to(0, 0, 0, 0);
  glStencilFunc(GL_EQUAL, 1000, 0xff);  // compares 255 with the stored 0: fails
  glColor3f(1, 1, 1);
  glRecti(0, 0, 2, 2);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {0, 0, 0, 0}));
}

}  // namespace
}  // namespace pineda::test
