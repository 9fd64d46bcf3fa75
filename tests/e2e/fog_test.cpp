// Fog (GL 1.5 section 3.10): linear, exp and exp2 from the eye distance |z_eye| or the fog
// coordinate, computed per fragment, applied to RGB only; state, errors, attributes, lists.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

class FogTest : public PixelTest {
 protected:
  void SetUp() override {
    PixelTest::SetUp();
    const float blue[4] = {0, 0, 1, 1};
    glFogfv(GL_FOG_COLOR, blue);
    glEnable(GL_FOG);
    glColor3f(1, 0, 0);
  }
  // A full-window quad at object (= eye) depth z.
  void quad(float z) { draw_window_quad(16, 16, z); }
  // Red fogged towards blue with factor f.
  static Rgba fogged(double f) { return {to_byte(f), 0, to_byte(1.0 - f), 255}; }
};

TEST_F(FogTest, LinearUsesTheEyeDistance) {
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.f);
  glFogf(GL_FOG_END, 1.f);
  quad(-0.25f);  // |z_eye| = 0.25: f = 0.75
  EXPECT_TRUE(near_rgba(pixel(8, 8), {191, 0, 64, 255}));
  quad(0.25f);  // the distance is absolute: the same f on the other side of the eye
  EXPECT_TRUE(near_rgba(pixel(3, 12), {191, 0, 64, 255}));
}

TEST_F(FogTest, LinearIsInterpolatedPerFragment) {
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.f);
  glFogf(GL_FOG_END, 1.f);
  glBegin(GL_QUADS);  // z from 0 at the left edge to -1 at the right one
  glVertex3f(0, 0, 0);
  glVertex3f(16, 0, -1);
  glVertex3f(16, 16, -1);
  glVertex3f(0, 16, 0);
  glEnd();
  for (int x : {0, 3, 8, 15}) {
    const double f = 1.0 - (x + 0.5) / 16.0;
    EXPECT_TRUE(near_rgba(pixel(x, 5), fogged(f))) << "x = " << x;
  }
}

TEST_F(FogTest, ExpAndExp2) {
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 1.f);
  quad(-0.5f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), fogged(std::exp(-0.5))));  // (155, 0, 100)
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 2.f);
  quad(-0.25f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), fogged(std::exp(-0.25))));  // (199, 0, 56)
}

TEST_F(FogTest, DefaultModeIsExpWithDensityOne) {
  quad(-0.5f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), fogged(std::exp(-0.5))));
}

TEST_F(FogTest, AlphaIsNotFogged) {
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 1.f);
  glColor4f(1, 0, 0, 0.25f);
  quad(-0.25f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {191, 0, 64, 64}));
}

TEST_F(FogTest, DisabledFogLeavesTheColour) {
  glDisable(GL_FOG);
  quad(-0.5f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {255, 0, 0, 255}));
}

TEST_F(FogTest, FogCoordinateSource) {
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 1.f);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glFogCoordf(0.25f);
  quad(-0.9f);  // the depth no longer matters
  EXPECT_TRUE(near_rgba(pixel(8, 8), {191, 0, 64, 255}));
  GLfloat current = 0;
  glGetFloatv(GL_CURRENT_FOG_COORD, &current);
  EXPECT_EQ(current, 0.25f);
}

TEST_F(FogTest, FogCoordinateArray) {
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 1.f);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  const GLfloat pos[] = {0, 0, 16, 0, 16, 16, 0, 16};
  const GLfloat fog[] = {0.75f, 0.75f, 0.75f, 0.75f};
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glFogCoordPointer(GL_FLOAT, 0, fog);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  EXPECT_TRUE(glIsEnabled(GL_FOG_COORD_ARRAY));
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_TRUE(near_rgba(pixel(8, 8), fogged(0.25)));  // (64, 0, 191)
  void* p = nullptr;
  glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
  EXPECT_EQ(p, fog);
  GLint type = 0;
  glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &type);
  EXPECT_EQ(type, GL_FLOAT);
  glFogCoordPointer(GL_INT, 0, fog);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFogCoordPointer(GL_FLOAT, -1, fog);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(FogTest, FogIsAppliedAfterTexturing) {
  const GLubyte green[4] = {0, 255, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 1.f);
  quad(-0.25f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 191, 64, 255}));
}

// GL 2.1 section 3.9: the colour sum is clamped to [0, 1] before fog. (llvmpipe fogs the
// unclamped sum, which would give 255 here.)
TEST_F(FogTest, ColorSumIsClampedBeforeFog) {
  glEnable(GL_COLOR_SUM);
  glSecondaryColor3f(1, 0, 0);  // red 1 + 1 = 2, clamped to 1
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 1.f);
  quad(-0.25f);  // f = 0.75
  EXPECT_TRUE(near_rgba(pixel(8, 8), {191, 0, 64, 255}));
}

TEST_F(FogTest, QueriesAndErrors) {
  GLint mode = 0;
  glGetIntegerv(GL_FOG_MODE, &mode);
  EXPECT_EQ(mode, GL_EXP);
  GLfloat color[4];
  glGetFloatv(GL_FOG_COLOR, color);
  EXPECT_EQ(color[2], 1.f);
  glFogf(GL_FOG_DENSITY, -1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFogi(GL_FOG_MODE, GL_LINE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFogf(GL_FOG_COLOR, 0.5f);  // a vector parameter: (0.5, 0, 0, 0), as in Mesa
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetFloatv(GL_FOG_COLOR, color);
  EXPECT_EQ(std::vector<GLfloat>(color, color + 4), (std::vector<GLfloat>{0.5f, 0, 0, 0}));
  glFogi(GL_FOG_COORD_SRC, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFogf(GL_FOG_START, 2.f);
  glFogf(GL_FOG_END, 5.f);
  glFogf(GL_FOG_INDEX, 3.f);
  const GLfloat over[4] = {2.f, -1.f, 0.5f, 1.f};
  glFogfv(GL_FOG_COLOR, over);  // clamped to [0, 1]
  GLfloat v = 0;
  glGetFloatv(GL_FOG_START, &v);
  EXPECT_EQ(v, 2.f);
  glGetFloatv(GL_FOG_END, &v);
  EXPECT_EQ(v, 5.f);
  glGetFloatv(GL_FOG_INDEX, &v);
  EXPECT_EQ(v, 3.f);
  glGetFloatv(GL_FOG_COLOR, color);
  EXPECT_EQ(color[0], 1.f);
  EXPECT_EQ(color[1], 0.f);
  GLint src = 0;
  glGetIntegerv(GL_FOG_COORD_SRC, &src);
  EXPECT_EQ(src, GL_FRAGMENT_DEPTH);
  glHint(GL_FOG_HINT, GL_NICEST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FogTest, ExtensionsAdvertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  for (const char* name : {"GL_EXT_fog_coord", "GL_EXT_secondary_color", "GL_EXT_separate_specular_color"})
    EXPECT_NE((" " + ext + " ").find(std::string(" ") + name + " "), std::string::npos) << name;
}

TEST_F(FogTest, PushPopFogBit) {
  glPushAttrib(GL_FOG_BIT);
  glDisable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_DENSITY, 3.f);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(GL_FOG));
  GLint mode = 0;
  glGetIntegerv(GL_FOG_MODE, &mode);
  EXPECT_EQ(mode, GL_EXP);
  GLfloat density = 0;
  glGetFloatv(GL_FOG_DENSITY, &density);
  EXPECT_EQ(density, 1.f);
  quad(-0.5f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), fogged(std::exp(-0.5))));
}

TEST_F(FogTest, CompiledIntoDisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_END, 1.f);
  const GLfloat green[4] = {0, 1, 0, 1};
  glFogfv(GL_FOG_COLOR, green);
  glEndList();
  GLint mode = 0;
  glGetIntegerv(GL_FOG_MODE, &mode);
  EXPECT_EQ(mode, GL_EXP);  // compiled, not executed
  glCallList(list);
  quad(-0.25f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {191, 64, 0, 255}));
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test
