// glGet of the GL 1.2-1.4 values that need no new rendering: aliased ranges, DrawRangeElements
// recommendations, separate blend factors and the 1.3/1.4 hints.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class Gl14GetsTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

TEST_F(Gl14GetsTest, AliasedRangesMatchTheSizesDrawn) {
  EXPECT_EQ(get_floats(GL_ALIASED_POINT_SIZE_RANGE, 2), get_floats(GL_POINT_SIZE_RANGE, 2));
  EXPECT_EQ(get_floats(GL_ALIASED_LINE_WIDTH_RANGE, 2), get_floats(GL_LINE_WIDTH_RANGE, 2));
  const auto points = get_floats(GL_ALIASED_POINT_SIZE_RANGE, 2);
  EXPECT_EQ(points[0], 1.f);
  // The largest size is drawn as a square of that many pixels (clipped to the surface).
  pixel_projection();
  clear_to(0, 0, 0, 0);
  glPointSize(points[1] + 100.f);  // clamped to the range
  glBegin(GL_POINTS);
  glVertex2f(16.5f, 16.5f);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), width() * height());
}

TEST_F(Gl14GetsTest, DrawRangeElementsRecommendations) {
  EXPECT_GT(get_int(GL_MAX_ELEMENTS_VERTICES), 0);
  EXPECT_GT(get_int(GL_MAX_ELEMENTS_INDICES), 0);
}

TEST_F(Gl14GetsTest, SeparateBlendFactors) {
  EXPECT_EQ(get_int(GL_BLEND_SRC_RGB), GL_ONE);
  EXPECT_EQ(get_int(GL_BLEND_DST_RGB), GL_ZERO);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_DST_ALPHA);
  EXPECT_EQ(get_int(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
  EXPECT_EQ(get_int(GL_BLEND_DST_RGB), GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(get_int(GL_BLEND_SRC_ALPHA), GL_ONE);
  EXPECT_EQ(get_int(GL_BLEND_DST_ALPHA), GL_DST_ALPHA);
  EXPECT_EQ(get_int(GL_BLEND_SRC), GL_SRC_ALPHA);  // the 1.1 names read the RGB factors
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  EXPECT_EQ(get_int(GL_BLEND_SRC_RGB), GL_DST_COLOR);
  EXPECT_EQ(get_int(GL_BLEND_SRC_ALPHA), GL_DST_COLOR);
  EXPECT_EQ(get_int(GL_BLEND_DST_RGB), GL_ZERO);
}

TEST_F(Gl14GetsTest, BlendColorAndEquation) {
  glBlendColor(0.25f, 0.5f, 0.75f, 1.f);
  const auto c = get_floats(GL_BLEND_COLOR, 4);
  EXPECT_EQ(c, (std::vector<GLfloat>{0.25f, 0.5f, 0.75f, 1.f}));
  glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION), GL_FUNC_REVERSE_SUBTRACT);
}

TEST_F(Gl14GetsTest, MipmapAndCompressionHints) {
  EXPECT_EQ(get_int(GL_GENERATE_MIPMAP_HINT), GL_DONT_CARE);
  EXPECT_EQ(get_int(GL_TEXTURE_COMPRESSION_HINT), GL_DONT_CARE);
  glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
  glHint(GL_TEXTURE_COMPRESSION_HINT, GL_FASTEST);
  EXPECT_EQ(get_int(GL_GENERATE_MIPMAP_HINT), GL_NICEST);
  EXPECT_EQ(get_int(GL_TEXTURE_COMPRESSION_HINT), GL_FASTEST);
  glPushAttrib(GL_HINT_BIT);
  glHint(GL_GENERATE_MIPMAP_HINT, GL_FASTEST);
  glHint(GL_TEXTURE_COMPRESSION_HINT, GL_NICEST);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_GENERATE_MIPMAP_HINT), GL_NICEST);
  EXPECT_EQ(get_int(GL_TEXTURE_COMPRESSION_HINT), GL_FASTEST);
  glHint(GL_GENERATE_MIPMAP_HINT, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_GENERATE_MIPMAP_HINT), GL_NICEST);
}

// The GL 1.3/1.4 extensions whose behaviour the tests of this branch check.
TEST_F(Gl14GetsTest, AdvertisesTheExtensions) {
  const std::string ext = " " + std::string(reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS))) + " ";
  for (const char* name : {"GL_ARB_transpose_matrix", "GL_ARB_multisample", "GL_ARB_point_parameters",
                           "GL_EXT_point_parameters", "GL_ARB_texture_compression", "GL_ARB_depth_texture",
                           "GL_ARB_shadow", "GL_EXT_shadow_funcs"})
    EXPECT_NE(ext.find(std::string(" ") + name + " "), std::string::npos) << name;
}

}  // namespace
}  // namespace pineda::test
