// EXT_draw_buffers2: a colour write mask and a blend enable per draw buffer, for fixed-function
// draws, fragment shaders, clears and window-system draw buffers; glColorMask and
// glEnable(GL_BLEND) set every draw buffer's; the indexed queries, their errors, the attribute
// stack and display lists.
#include <array>
#include <string>

#include "tests/framebuffers/four_draw_buffers.h"

namespace pineda::test {
namespace {

class DrawBuffers2Test : public FourDrawBuffersTest {
 protected:
  // Draw buffer i's mask: what a masked write of kDrawn over kCleared leaves.
  static Rgba masked(const std::array<bool, 4>& write) {
    Rgba out = kCleared;
    for (size_t c = 0; c < 4; ++c)
      if (write[c]) out[c] = kDrawn[c];
    return out;
  }

  std::array<GLboolean, 4> mask_of(GLuint i) {
    std::array<GLboolean, 4> v{9, 9, 9, 9};
    glGetBooleanIndexedvEXT(GL_COLOR_WRITEMASK, i, v.data());
    return v;
  }
};

constexpr std::array<std::array<bool, 4>, 4> kMasks = {{
    {true, true, true, true},
    {false, true, true, true},
    {true, false, false, false},
    {false, false, false, false},
}};

void set_masks() {
  for (GLuint i = 0; i < 4; ++i) {
    const std::array<bool, 4>& m = kMasks[i];
    glColorMaskIndexedEXT(i, m[0], m[1], m[2], m[3]);
  }
}

TEST_F(DrawBuffers2Test, Advertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_EXT_draw_buffers2 "), std::string::npos);
}

TEST_F(DrawBuffers2Test, FixedFunctionWritesEachBufferThroughItsMask) {
  set_masks();
  draw_quad(kDrawn);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(attachment_pixel(i, 3, 3), masked(kMasks[size_t(i)])) << "draw buffer " << i;
    EXPECT_EQ(attachment_pixel(i, 12, 12), kCleared) << "draw buffer " << i;
  }
}

TEST_F(DrawBuffers2Test, FragDataWritesEachBufferThroughItsMask) {
  const GLuint p = fragment_program(
      "void main() {\n"
      "  for (int i = 0; i < 4; ++i) gl_FragData[i] = vec4(200.0, 100.0, 50.0, 150.0) / 255.0;\n"
      "}\n");
  glUseProgram(p);
  set_masks();
  draw_quad(kDrawn);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(attachment_pixel(i, 3, 3), masked(kMasks[size_t(i)])) << "draw buffer " << i;
  glDeleteProgram(p);
}

TEST_F(DrawBuffers2Test, ClearClearsEachBufferThroughItsMask) {
  set_masks();
  glClearColor(200 / 255.f, 100 / 255.f, 50 / 255.f, 150 / 255.f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(attachment_pixel(i, 5, 9), masked(kMasks[size_t(i)])) << "draw buffer " << i;
}

// ONE, ONE: blended buffers get the sum, the others the drawn colour.
TEST_F(DrawBuffers2Test, FixedFunctionBlendsOnlyTheEnabledBuffers) {
  glBlendFunc(GL_ONE, GL_ONE);
  glEnableIndexedEXT(GL_BLEND, 1);
  glEnableIndexedEXT(GL_BLEND, 3);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);  // draw buffer 0's
  draw_quad(kDrawn);
  const Rgba sum{210, 120, 80, 190};
  EXPECT_EQ(attachment_pixel(0, 3, 3), kDrawn);
  EXPECT_EQ(attachment_pixel(1, 3, 3), sum);
  EXPECT_EQ(attachment_pixel(2, 3, 3), kDrawn);
  EXPECT_EQ(attachment_pixel(3, 3, 3), sum);
}

TEST_F(DrawBuffers2Test, ShaderBlendsOnlyTheEnabledBuffers) {
  const GLuint p = fragment_program(
      "void main() {\n"
      "  gl_FragData[0] = gl_Color;\n"
      "  gl_FragData[1] = gl_Color;\n"
      "  gl_FragData[2] = gl_Color.bgra;\n"
      "  gl_FragData[3] = gl_Color.bgra;\n"
      "}\n");
  glUseProgram(p);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_BLEND);
  glDisableIndexedEXT(GL_BLEND, 0);
  glDisableIndexedEXT(GL_BLEND, 2);
  draw_quad(kDrawn);
  EXPECT_EQ(attachment_pixel(0, 3, 3), kDrawn);
  EXPECT_EQ(attachment_pixel(1, 3, 3), (Rgba{210, 120, 80, 190}));
  EXPECT_EQ(attachment_pixel(2, 3, 3), (Rgba{50, 100, 200, 150}));
  EXPECT_EQ(attachment_pixel(3, 3, 3), (Rgba{60, 120, 230, 190}));
  glDeleteProgram(p);
}

// SRC_ALPHA, ONE_MINUS_SRC_ALPHA with source alpha 0 (the "over" routines): a blended buffer
// keeps its colour, an unblended one takes the drawn colour.
TEST_F(DrawBuffers2Test, OverBlendingOnlyInTheEnabledBuffer) {
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnableIndexedEXT(GL_BLEND, 2);
  draw_quad({200, 100, 50, 0});
  EXPECT_EQ(attachment_pixel(0, 3, 3), (Rgba{200, 100, 50, 0}));
  EXPECT_EQ(attachment_pixel(2, 3, 3), kCleared);
}

TEST_F(DrawBuffers2Test, UnindexedCallsSetEveryBuffer) {
  set_masks();
  glEnableIndexedEXT(GL_BLEND, 2);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glEnable(GL_BLEND);
  for (GLuint i = 0; i < 4; ++i) {
    EXPECT_EQ(mask_of(i), (std::array<GLboolean, 4>{GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE})) << i;
    EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, i), GL_TRUE) << i;
  }
  glDisable(GL_BLEND);
  for (GLuint i = 0; i < 4; ++i) EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, i), GL_FALSE) << i;
}

TEST_F(DrawBuffers2Test, QueriesReturnEachBuffersState) {
  set_masks();
  glEnableIndexedEXT(GL_BLEND, 3);
  for (GLuint i = 0; i < 4; ++i) {
    const std::array<bool, 4>& m = kMasks[i];
    EXPECT_EQ(mask_of(i), (std::array<GLboolean, 4>{m[0], m[1], m[2], m[3]})) << i;
    std::array<GLint, 4> ints{9, 9, 9, 9};
    glGetIntegerIndexedvEXT(GL_COLOR_WRITEMASK, i, ints.data());
    EXPECT_EQ(ints, (std::array<GLint, 4>{m[0], m[1], m[2], m[3]})) << i;
    GLint blend = 9;
    glGetIntegerIndexedvEXT(GL_BLEND, i, &blend);
    EXPECT_EQ(blend, i == 3 ? 1 : 0) << i;
    GLboolean b = 9;
    glGetBooleanIndexedvEXT(GL_BLEND, i, &b);
    EXPECT_EQ(b, i == 3 ? GL_TRUE : GL_FALSE) << i;
  }
  // The unindexed queries return draw buffer 0's.
  glColorMaskIndexedEXT(0, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  GLboolean mask[4] = {9, 9, 9, 9};
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  EXPECT_EQ((std::array<GLboolean, 4>{mask[0], mask[1], mask[2], mask[3]}),
            (std::array<GLboolean, 4>{GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE}));
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  glEnableIndexedEXT(GL_BLEND, 0);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_TRUE);
}

TEST_F(DrawBuffers2Test, Errors) {
  glColorMaskIndexedEXT(8, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glEnableIndexedEXT(GL_BLEND, 8);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDisableIndexedEXT(GL_BLEND, 0xffffffffu);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, 8), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLboolean b[4] = {9, 9, 9, 9};
  glGetBooleanIndexedvEXT(GL_COLOR_WRITEMASK, 8, b);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(b[0], 9);  // untouched
  GLint v = 9;
  glGetIntegerIndexedvEXT(GL_BLEND, 8, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(v, 9);
  // Only BLEND is indexed (and COLOR_WRITEMASK for the queries).
  glEnableIndexedEXT(GL_DEPTH_TEST, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  glEnableIndexedEXT(GL_COLOR_WRITEMASK, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glIsEnabledIndexedEXT(GL_SCISSOR_TEST, 0), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetIntegerIndexedvEXT(GL_DEPTH_WRITEMASK, 0, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v, 9);
  // Nothing changed.
  for (GLuint i = 0; i < 4; ++i) {
    EXPECT_EQ(mask_of(i), (std::array<GLboolean, 4>{GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE})) << i;
    EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, i), GL_FALSE) << i;
  }
  // Not between glBegin and glEnd.
  glBegin(GL_POINTS);
  glColorMaskIndexedEXT(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(mask_of(1)[0], GL_TRUE);
}

TEST_F(DrawBuffers2Test, AttribStackRestoresEveryBuffer) {
  set_masks();
  glEnableIndexedEXT(GL_BLEND, 1);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_BLEND);
  glPopAttrib();
  for (GLuint i = 0; i < 4; ++i) {
    const std::array<bool, 4>& m = kMasks[i];
    EXPECT_EQ(mask_of(i), (std::array<GLboolean, 4>{m[0], m[1], m[2], m[3]})) << i;
    EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, i), i == 1 ? GL_TRUE : GL_FALSE) << i;
  }
  // GL_ENABLE_BIT: the blend enables, not the masks.
  glPushAttrib(GL_ENABLE_BIT);
  glDisableIndexedEXT(GL_BLEND, 1);
  glEnableIndexedEXT(GL_BLEND, 2);
  glColorMaskIndexedEXT(3, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPopAttrib();
  for (GLuint i = 0; i < 4; ++i) EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, i), i == 1 ? GL_TRUE : GL_FALSE) << i;
  EXPECT_EQ(mask_of(3), (std::array<GLboolean, 4>{GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE}));
}

TEST_F(DrawBuffers2Test, DisplayListsCompileTheIndexedCalls) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glColorMaskIndexedEXT(2, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glEnableIndexedEXT(GL_BLEND, 1);
  glEndList();
  EXPECT_EQ(mask_of(2), (std::array<GLboolean, 4>{GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE}));
  EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, 1), GL_FALSE);
  glCallList(list);
  EXPECT_EQ(mask_of(2), (std::array<GLboolean, 4>{GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE}));
  EXPECT_EQ(glIsEnabledIndexedEXT(GL_BLEND, 1), GL_TRUE);
  EXPECT_EQ(mask_of(1), (std::array<GLboolean, 4>{GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE}));
  glDeleteLists(list, 1);
}

// On the window-system framebuffer each selected buffer is drawn as the draw buffer that
// selects it, with that draw buffer's mask.
TEST_F(DrawBuffers2Test, WindowBufferTakesItsDrawBuffersMask) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const GLenum window = get_int(GL_DRAW_BUFFER) == GL_BACK ? GL_BACK_LEFT : GL_FRONT_LEFT;
  glDrawBuffer(window);
  clear_all();
  const GLenum second[] = {GL_NONE, window};
  glDrawBuffers(2, second);
  glColorMaskIndexedEXT(1, GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
  draw_quad(kDrawn);
  glClearColor(1, 1, 1, 1);
  glColorMaskIndexedEXT(1, GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadBuffer(window);
  EXPECT_EQ(pixel(3, 3), (Rgba{200, 20, 255, 150}));
  EXPECT_EQ(pixel(12, 12), (Rgba{10, 20, 255, 40}));
  glDrawBuffer(window);
}

}  // namespace
}  // namespace pineda::test
