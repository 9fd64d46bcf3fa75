// glRasterPos and glWindowPos: the transformed position, its validity, colour, texture
// coordinates and distance, and their glGet values.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class RasterPosTest : public GlTest {
 protected:
  std::array<float, 4> position() {
    std::array<float, 4> p{};
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p.data());
    return p;
  }
  bool valid() {
    GLboolean v = GL_FALSE;
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &v);
    return v == GL_TRUE;
  }
};

TEST_F(RasterPosTest, InitialState) {
  EXPECT_EQ(position(), (std::array<float, 4>{0, 0, 0, 1}));
  EXPECT_TRUE(valid());
  float c[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  EXPECT_EQ(c[0], 1.f);
  EXPECT_EQ(c[3], 1.f);
  float d = -1;
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_EQ(d, 0.f);
}

TEST_F(RasterPosTest, TransformedByModelviewProjectionAndViewport) {
  pixel_projection();
  glTranslatef(3, 4, 0);
  glRasterPos3f(5, 6, 0.5f);
  // z: ortho near -1, far 1 maps 0.5 to -0.5 in NDC ... window z = 0.5 * (-0.5) + 0.5 = 0.25
  EXPECT_EQ(position(), (std::array<float, 4>{8, 10, 0.25f, 1}));
  EXPECT_TRUE(valid());
  GLint ip[4];
  glGetIntegerv(GL_CURRENT_RASTER_POSITION, ip);
  EXPECT_EQ(ip[0], 8);
  EXPECT_EQ(ip[1], 10);
  float d = 0;
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_FLOAT_EQ(d, std::sqrt(8.f * 8 + 10 * 10 + 0.5f * 0.5f));

  glViewport(10, 20, 8, 4);
  glLoadIdentity();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glRasterPos4f(0.5f, -0.5f, 0.f, 1.f);
  EXPECT_EQ(position(), (std::array<float, 4>{16, 21, 0.5f, 1}));
  glRasterPos4i(1, 1, 0, 2);  // divided by w
  EXPECT_EQ(position(), (std::array<float, 4>{16, 23, 0.5f, 2}));
}

TEST_F(RasterPosTest, OutsideTheClipVolumeIsInvalidAndKeepsTheOldValues) {
  glRasterPos2f(0.5f, 0.5f);
  const auto before = position();
  glRasterPos2f(1.5f, 0.f);
  EXPECT_FALSE(valid());
  EXPECT_EQ(position(), before);
  glRasterPos3f(0, 0, -1.01f);
  EXPECT_FALSE(valid());
  glRasterPos2f(-1.f, 1.f);  // on the boundary: inside
  EXPECT_TRUE(valid());
}

TEST_F(RasterPosTest, ColourAndTextureCoordinatesAreLatched) {
  glColor4f(0.25f, 0.5f, 0.75f, 1.f);
  glTexCoord4f(1, 2, 3, 4);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 2, 2);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos2i(0, 0);
  glColor3f(0, 0, 0);
  float c[4], t[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, t);
  EXPECT_EQ(c[0], 0.25f);
  EXPECT_EQ(c[1], 0.5f);
  EXPECT_EQ(c[2], 0.75f);
  EXPECT_EQ(c[3], 1.f);
  EXPECT_EQ(t[0], 2.f);
  EXPECT_EQ(t[1], 4.f);
  EXPECT_EQ(t[2], 6.f);
  EXPECT_EQ(t[3], 4.f);
}

TEST_F(RasterPosTest, LightingAppliesToTheRasterColour) {
  glEnable(GL_LIGHTING);
  const float ambient[4] = {0.5f, 0.25f, 0.f, 1.f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  const float material[4] = {1.f, 1.f, 1.f, 0.5f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, material);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, material);
  glRasterPos2i(0, 0);
  float c[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  EXPECT_EQ(c[0], 0.5f);
  EXPECT_EQ(c[1], 0.25f);
  EXPECT_EQ(c[2], 0.f);
  EXPECT_EQ(c[3], 0.5f);  // the diffuse alpha
}

TEST_F(RasterPosTest, WindowPosSetsWindowCoordinatesDirectly) {
  pixel_projection();
  glTranslatef(100, 100, 0);  // ignored
  glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
  glDepthRange(0.25, 0.75);
  glWindowPos3f(7.5f, -3.f, 0.5f);
  EXPECT_EQ(position(), (std::array<float, 4>{7.5f, -3.f, 0.5f, 1}));
  EXPECT_TRUE(valid());  // even off the window
  glWindowPos3i(1, 2, 2);  // z clamped to 1, then mapped to the depth range
  EXPECT_EQ(position(), (std::array<float, 4>{1, 2, 0.75f, 1}));
  const GLshort sv[2] = {4, 5};
  glWindowPos2svARB(sv);
  EXPECT_EQ(position(), (std::array<float, 4>{4, 5, 0.25f, 1}));
  glRasterPos2f(1e6f, 0);
  EXPECT_FALSE(valid());
  glWindowPos2d(0, 0);
  EXPECT_TRUE(valid());
  float c[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  EXPECT_EQ(c[3], 0.5f);
}

TEST_F(RasterPosTest, UserClipPlanesAndFogCoordinate) {
  const GLdouble keep_x_below_half[4] = {-1, 0, 0, 0.5};
  glClipPlane(GL_CLIP_PLANE0, keep_x_below_half);
  glEnable(GL_CLIP_PLANE0);
  glRasterPos2f(0.25f, 0.f);
  EXPECT_TRUE(valid());
  glRasterPos2f(0.75f, 0.f);
  EXPECT_FALSE(valid());
  glDisable(GL_CLIP_PLANE0);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glFogCoordf(3.5f);
  glRasterPos3f(0.f, 0.f, 0.5f);
  float d = 0;
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_EQ(d, 3.5f);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
  glRasterPos3f(0.f, 0.f, 0.5f);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  EXPECT_EQ(d, 0.5f);
}

TEST_F(RasterPosTest, SavedWithCurrentBit) {
  glWindowPos2i(3, 4);
  glPushAttrib(GL_CURRENT_BIT);
  glWindowPos2i(5, 6);
  glPopAttrib();
  EXPECT_EQ(position(), (std::array<float, 4>{3, 4, 0, 1}));
  glPushAttrib(GL_LIGHTING_BIT);
  glWindowPos2i(5, 6);
  glPopAttrib();
  EXPECT_EQ(position(), (std::array<float, 4>{5, 6, 0, 1}));
}

TEST_F(RasterPosTest, InsideBeginEndIsAnError) {
  glBegin(GL_POINTS);
  glRasterPos2i(1, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(position(), (std::array<float, 4>{0, 0, 0, 1}));
}

TEST_F(RasterPosTest, CompiledIntoDisplayLists) {
  glNewList(1, GL_COMPILE);
  glWindowPos2i(9, 8);
  glEndList();
  EXPECT_EQ(position(), (std::array<float, 4>{0, 0, 0, 1}));
  glCallList(1);
  EXPECT_EQ(position(), (std::array<float, 4>{9, 8, 0, 1}));
}

// GL 2.1: CURRENT_RASTER_SECONDARY_COLOR, (0, 0, 0, 1) at first; unlit, the current
// secondary colour (clamped) at RasterPos and WindowPos.
TEST_F(RasterPosTest, SecondaryColor) {
  std::array<float, 4> c{};
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, c.data());
  EXPECT_EQ(c, (std::array<float, 4>{0, 0, 0, 1}));
  glSecondaryColor3f(0.25f, 0.5f, 2.f);
  glRasterPos2f(0, 0);
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, c.data());
  EXPECT_EQ(c, (std::array<float, 4>{0.25f, 0.5f, 1.f, 1.f}));
  glSecondaryColor3f(0.75f, 0.f, 0.f);
  glWindowPos2i(1, 1);
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, c.data());
  EXPECT_EQ(c, (std::array<float, 4>{0.75f, 0.f, 0.f, 1.f}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
