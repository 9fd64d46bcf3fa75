// The application's floating-point modes (an MXCSR it set after creating its context: rounding
// up, flush to zero) do not change which pixels a thread count gives: every tile rasterizes
// under the default modes, whichever thread takes it.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>
#include <xmmintrin.h>

#include <cstdlib>
#include <vector>

#include "tests/e2e/support/gl_program.h"
#include "tests/e2e/support/gl_surface.h"

namespace pineda::test {
namespace {

constexpr int kSize = 128;
constexpr int kGrid = 24;  // 1152 triangles: enough commands for the tiles to go to the threads

// Float arithmetic per fragment whose last bits the rounding mode decides.
const char* const kFragmentShader = R"(#version 110
varying vec4 v_color;
void main() {
  vec3 c = fract(v_color.rgb * 7.31 + v_color.bgr * 0.173) / 3.0;
  gl_FragColor = vec4(c, v_color.a);
})";
const char* const kVertexShader = R"(#version 110
varying vec4 v_color;
void main() { v_color = gl_Color; gl_Position = gl_Vertex; })";

// A grid of smoothly coloured quads, fogged on the left half and shaded by a program on the
// right, blended over a grey background; the colour buffer.
std::vector<uint8_t> render(const char* threads, unsigned app_modes) {
  setenv("PINEDA_THREADS", threads, 1);
  GlSurface surface({kSize, kSize, 24, 8});
  unsetenv("PINEDA_THREADS");
  EXPECT_TRUE(surface.ok()) << surface.error();
  if (!surface.ok()) return {};
  const unsigned saved = _mm_getcsr();
  _mm_setcsr(app_modes);
  glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, -1.0f);
  glFogf(GL_FOG_END, 1.5f);
  const GLuint program = link_gl_program(kVertexShader, kFragmentShader);
  glBegin(GL_QUADS);
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      if (i == kGrid / 2 && j == 0) {
        glEnd();
        glUseProgram(program);
        glBegin(GL_QUADS);
      }
      const float x0 = -1.0f + 2.0f * float(i) / kGrid, y0 = -1.0f + 2.0f * float(j) / kGrid, d = 2.0f / kGrid;
      const float corners[4][2] = {{x0, y0}, {x0 + d, y0}, {x0 + d, y0 + d}, {x0, y0 + d}};
      for (const auto& c : corners) {
        glColor4f(0.5f + 0.49f * c[0], 0.5f - 0.37f * c[1], 0.2f + 0.3f * c[0] * c[1], 0.37f);
        glVertex3f(c[0], c[1], 0.6f * c[0]);
      }
    }
  glEnd();
  glUseProgram(0);
  glDeleteProgram(program);
  std::vector<uint8_t> out(kSize * kSize * 4);
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  _mm_setcsr(saved);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  surface.release();
  return out;
}

TEST(FloatModesThreads, ApplicationModesDoNotSplitTilesByThread) {
  constexpr unsigned kRoundUpFlushToZero = (0x1F80u & ~0x6000u) | 0x4000u | 0x8040u;
  const std::vector<uint8_t> one = render("1", kRoundUpFlushToZero);
  const std::vector<uint8_t> two = render("2", kRoundUpFlushToZero);
  ASSERT_EQ(one.size(), size_t(kSize * kSize * 4));
  ASSERT_EQ(two.size(), one.size());
  int differing = 0;
  for (size_t i = 0; i < one.size(); ++i) differing += one[i] != two[i];
  EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace pineda::test
