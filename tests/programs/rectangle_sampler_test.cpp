// GLSL rectangle samplers (ARB_texture_rectangle): sampler2DRect and sampler2DRectShadow with
// texture2DRect, texture2DRectProj and shadow2DRect at texel coordinates, with or without an
// #extension line (as Mesa, which enables the extension in every desktop shader).
#include "tests/programs/program_test.h"
#include "tests/e2e/support/texel_images.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {
namespace {

constexpr int kWidth = kRectWidth, kHeight = kRectHeight;
Rgba texel(int i, int j) { return rect_texel(i, j); }

class RectangleSamplerTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
    load_rect_image();
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE0);
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  // A program of `fs` whose sampler `tex` reads unit 1; the vertex shader passes the window
  // position on as `pos`.
  GLuint use(const char* fs) {
    const char* vs = "varying vec2 pos;\n"
                     "void main() { pos = gl_Vertex.xy; gl_Position = ftransform(); }\n";
    const GLuint p = link(vs, fs);
    EXPECT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "tex"), 1);
    return p;
  }
  void expect_image_at_origin() {
    for (int j = 0; j < kHeight; ++j)
      for (int i = 0; i < kWidth; ++i) EXPECT_EQ(pixel(i, j), texel(i, j)) << i << "," << j;
    EXPECT_EQ(pixel(kWidth + 1, 0), (Rgba{0, 0, 0, 0}));
  }
};

TEST_F(RectangleSamplerTest, Texture2DRectAtWindowPositions) {
  use("#extension GL_ARB_texture_rectangle : require\n"
      "uniform sampler2DRect tex; varying vec2 pos;\n"
      "void main() { gl_FragColor = texture2DRect(tex, pos); }\n");
  draw_rect(0, 0, kWidth, kHeight);
  expect_image_at_origin();
}

TEST_F(RectangleSamplerTest, WithoutExtensionLineAndWithLinearFilterAtTexelCentres) {
  glActiveTexture(GL_TEXTURE1);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glActiveTexture(GL_TEXTURE0);
  const GLuint p = use("uniform sampler2DRect tex; varying vec2 pos;\n"
                       "void main() { gl_FragColor = texture2DRect(tex, pos); }\n");
  GLint size = 0;
  GLenum type = 0;
  char name[16];
  glGetActiveUniform(p, 0, sizeof name, nullptr, &size, &type, name);
  EXPECT_EQ(type, GLenum(GL_SAMPLER_2D_RECT_ARB));
  draw_rect(0, 0, kWidth, kHeight);
  expect_image_at_origin();
}

TEST_F(RectangleSamplerTest, ProjectedForms) {
  use("#extension GL_ARB_texture_rectangle : enable\n"
      "uniform sampler2DRect tex; varying vec2 pos;\n"
      "void main() {\n"
      "  vec4 a = texture2DRectProj(tex, vec3(2.0 * pos, 2.0));\n"
      "  vec4 b = texture2DRectProj(tex, vec4(4.0 * pos, 7.0, 4.0));\n"
      "  gl_FragColor = a == b ? a : vec4(1.0, 0.0, 1.0, 1.0);\n"
      "}\n");
  draw_rect(0, 0, kWidth, kHeight);
  expect_image_at_origin();
}

TEST_F(RectangleSamplerTest, Shadow2DRect) {
  const float depths[2] = {0.25f, 0.75f};
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 2);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_DEPTH_COMPONENT, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glActiveTexture(GL_TEXTURE0);
  use("uniform sampler2DRectShadow tex; varying vec2 pos;\n"
      "void main() {\n"
      "  vec4 a = shadow2DRect(tex, vec3(pos, 0.5));\n"
      "  vec4 b = shadow2DRectProj(tex, vec4(2.0 * pos, 1.0, 2.0));\n"
      "  gl_FragColor = a == b ? a : vec4(1.0, 0.0, 1.0, 1.0);\n"
      "}\n");
  draw_rect(0, 0, 2, 1);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 255}));  // 0.5 <= 0.25 fails
  EXPECT_EQ(pixel(1, 0), (Rgba{255, 255, 255, 255}));  // 0.5 <= 0.75 passes
}

}  // namespace
}  // namespace pineda::test
