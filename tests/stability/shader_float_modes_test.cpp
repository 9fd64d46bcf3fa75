// Shaders compute under round to nearest with denormals flushed, whatever floating-point modes
// the application set (here: rounding down): a vertex shader's floor of -0.0 gives +0, as the
// interpreter's lane routines give it, on the compiled tier too (which turns -0 into +0 by
// adding +0: -0 under rounding down).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>
#include <xmmintrin.h>

#include <vector>

#include "tests/e2e/support/gl_program.h"
#include "tests/e2e/support/gl_surface.h"

namespace pineda::test {
namespace {

constexpr int kModesSize = 16;

const char* const kFloorOfNegativeZero = R"(#version 110
attribute vec2 position;
attribute float negative_zero;
varying vec4 v_color;
void main() {
  // 1 / +0 is +inf and 1 / -0 is -inf: red tells the sign of floor's zero.
  v_color = vec4(step(0.0, 1.0 / floor(negative_zero)), 0.0, 0.0, 1.0);
  gl_Position = vec4(position, 0.0, 1.0);
})";
const char* const kPassColor = R"(#version 110
varying vec4 v_color;
void main() { gl_FragColor = v_color; })";

TEST(ShaderFloatModes, ApplicationRoundingDownDoesNotReachAVertexShader) {
  GlSurface surface({kModesSize, kModesSize, 0, 0});
  ASSERT_TRUE(surface.ok()) << surface.error();
  const GLuint program = link_gl_program(kFloorOfNegativeZero, kPassColor, {{0, "position"}, {1, "negative_zero"}});
  glUseProgram(program);
  static const GLfloat positions[] = {-1, -1, 1, -1, 1, 1, -1, 1};
  static const GLfloat zeros[] = {-0.0f, -0.0f, -0.0f, -0.0f};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, positions);
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, zeros);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  constexpr unsigned kRoundDown = (0x1F80u & ~0x6000u) | 0x2000u;
  const unsigned saved = _mm_getcsr();
  _mm_setcsr(kRoundDown);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  glFinish();
  EXPECT_EQ(_mm_getcsr() & ~0x3Fu, kRoundDown);  // the application's modes are back
  _mm_setcsr(saved);
  std::vector<uint8_t> pixels(kModesSize * kModesSize * 4);
  glReadPixels(0, 0, kModesSize, kModesSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  int red = 0;
  for (int i = 0; i < kModesSize * kModesSize; ++i) red += pixels[4 * i] == 255 && pixels[4 * i + 1] == 0;
  EXPECT_EQ(red, kModesSize * kModesSize);
  glDeleteProgram(program);
  surface.release();
}

}  // namespace
}  // namespace pineda::test
