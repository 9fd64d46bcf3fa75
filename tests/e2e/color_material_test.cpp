// GL_COLOR_MATERIAL with glMaterial calls and vertex arrays, immediately and in display lists
// (piglit dlist-color-material, gl-1.1-color-material-array).
#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {
namespace {

const GLfloat kBlack[4] = {0, 0, 0, 0}, kWhite[4] = {1, 1, 1, 1};
const GLfloat kRed[4] = {1, 0, 0, 1}, kGreen[4] = {0, 1, 0, 1};

class ColorMaterialTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {16, 16, 24, 0}; }
  void SetUp() override {
    GlTest::SetUp();
    clear_to(0.5f, 0.5f, 0.5f, 0.5f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, kBlack);
  }
  // Only `coef` of light 0 is white, so the lit colour is that material property alone.
  void light_only(GLenum coef) {
    for (GLenum p : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR}) {
      glMaterialfv(GL_FRONT_AND_BACK, p, kBlack);
      glLightfv(GL_LIGHT0, p, p == coef ? kWhite : kBlack);
    }
  }
  void full_quad() {
    pixel_projection();
    glNormal3f(0, 0, 1);
    draw_window_quad(float(width()), float(height()));
  }
  static Rgba material(GLenum coef) {
    GLfloat m[4] = {};
    glGetMaterialfv(GL_FRONT, coef, m);
    return {to_byte(m[0]), to_byte(m[1]), to_byte(m[2]), to_byte(m[3])};
  }
};

// Mesa (the tie-breaker; the spec does not say) ignores glMaterial for a property that follows
// the colour: the property keeps the current colour.
TEST_F(ColorMaterialTest, MaterialCallDoesNotOverrideATrackedProperty) {
  for (GLenum coef : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR}) {
    light_only(coef);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, coef);
    glColor4fv(kGreen);
    glMaterialfv(GL_FRONT_AND_BACK, coef, kRed);
    EXPECT_EQ(material(coef), Rgba({0, 255, 0, 255})) << "coef 0x" << std::hex << coef;
    glDisable(GL_COLOR_MATERIAL);
  }
}

TEST_F(ColorMaterialTest, MaterialCallInAListDoesNotOverrideATrackedProperty) {
  for (GLenum coef : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR}) {
    light_only(coef);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, coef);
    glColor4fv(kGreen);
    glNewList(1, GL_COMPILE);
    glMaterialfv(GL_FRONT_AND_BACK, coef, kRed);
    glEndList();
    glCallList(1);
    full_quad();
    EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 255, 0, 255})) << "coef 0x" << std::hex << coef;
    EXPECT_EQ(material(coef), Rgba({0, 255, 0, 255})) << "coef 0x" << std::hex << coef;
    glDisable(GL_COLOR_MATERIAL);
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The material follows the colour array per vertex, drawn at once and from a list; the
// arrays are switched with glEnable, as piglit does (Mesa's compatibility profile accepts it).
TEST_F(ColorMaterialTest, ColorArrayDrivesTheMaterialInAList) {
  glLightfv(GL_LIGHT0, GL_AMBIENT, kWhite);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, kWhite);
  glLightfv(GL_LIGHT0, GL_SPECULAR, kBlack);
  static const GLfloat pos[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  static const GLfloat color[4][4] = {
      {0, 0.4f, 0, 0.8f}, {0, 0.4f, 0, 0.8f}, {0, 0.4f, 0, 0.8f}, {0, 0.4f, 0, 0.8f}};
  const Rgba almostGreen = {0, 204, 0, 204};  // ambient 0.4 + diffuse 0.4; alpha of the diffuse
  for (bool list : {false, true}) {
    clear_to(0.5f, 0.5f, 0.5f, 0.5f);
    if (list) glNewList(1, GL_COMPILE);
    glColorPointer(4, GL_FLOAT, 0, color);
    glEnable(GL_COLOR_ARRAY);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glEnable(GL_VERTEX_ARRAY);
    glNormal3f(0, 0, 1);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    if (list) {
      glEndList();
      glCallList(1);
    }
    EXPECT_EQ(count_pixels(almostGreen), width() * height()) << (list ? "list" : "immediate");
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// glEnable of a client array compiled into a list switches the array when the list runs.
TEST_F(ColorMaterialTest, ClientArrayEnableInAListActsOnReplay) {
  glNewList(1, GL_COMPILE);
  glEnable(GL_COLOR_ARRAY);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_FALSE);
  glCallList(1);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
