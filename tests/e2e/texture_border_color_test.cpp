// The texture border colour (GL 1.5 3.8.8) is taken as a texel of the texture's base format:
// no alpha reads 1, luminance spreads R, intensity fills all four, alpha alone has no colour.
// A 1D texture has no t: its row is read whatever t is, even under CLAMP_TO_BORDER (piglit
// texwrap 1D bordercolor).
#include "tests/e2e/support/pixel_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

class TextureBorderColorTest : public PixelTest {
 protected:
  void SetUp() override {
    PixelTest::SetUp();
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const GLfloat border[4] = {0.2f, 0.6f, 1.0f, 0.4f};  // 51, 153, 255, 102
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  }
  // The colour REPLACE draws where s lies entirely outside a 2x2 texture of `internal_format`.
  Rgba border_of(GLint internal_format) {
    const uint8_t texels[4 * 4] = {};
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    clear_to(0, 0, 0, 0);
    glBegin(GL_QUADS);
    glTexCoord2f(2, 0.5f), glVertex2f(0, 0);
    glTexCoord2f(3, 0.5f), glVertex2f(4, 0);
    glTexCoord2f(3, 0.5f), glVertex2f(4, 4);
    glTexCoord2f(2, 0.5f), glVertex2f(0, 4);
    glEnd();
    return pixel(2, 2);
  }
};

TEST_F(TextureBorderColorTest, BorderColourFollowsTheBaseFormat) {
  // REPLACE takes the colour of RGB, luminance and intensity textures and the fragment's
  // (white) colour where the format has none; alpha likewise.
  EXPECT_EQ(border_of(GL_RGBA8), (Rgba{51, 153, 255, 102}));
  EXPECT_EQ(border_of(GL_RGB8), (Rgba{51, 153, 255, 255}));
  EXPECT_EQ(border_of(GL_R3_G3_B2), (Rgba{51, 153, 255, 255}));
  EXPECT_EQ(border_of(GL_LUMINANCE8), (Rgba{51, 51, 51, 255}));
  EXPECT_EQ(border_of(GL_LUMINANCE8_ALPHA8), (Rgba{51, 51, 51, 102}));
  EXPECT_EQ(border_of(GL_INTENSITY8), (Rgba{51, 51, 51, 51}));
  EXPECT_EQ(border_of(GL_ALPHA8), (Rgba{255, 255, 255, 102}));
}

// A 4x1 1D texture drawn with t far outside [0, 1]: every pixel still reads its texel along s;
// only s outside [0, 1] reads the border.
TEST_F(TextureBorderColorTest, OneDimensionalTexturesIgnoreT) {
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_1D, 2);
  const uint8_t texels[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const GLfloat border[4] = {0.2f, 0.6f, 1.0f, 0.4f};
  glTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  for (GLenum filter : {GL_NEAREST, GL_LINEAR}) {
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, filter);
    clear_to(0, 0, 0, 0);
    glBegin(GL_QUADS);  // s from -0.5 to 1.5 over 8 pixels, t from -3 to 5
    glTexCoord2f(-0.5f, -3), glVertex2f(0, 0);
    glTexCoord2f(1.5f, -3), glVertex2f(8, 0);
    glTexCoord2f(1.5f, 5), glVertex2f(8, 8);
    glTexCoord2f(-0.5f, 5), glVertex2f(0, 8);
    glEnd();
    for (int y : {0, 4, 7}) {
      EXPECT_EQ(pixel(0, y), (Rgba{51, 153, 255, 102})) << filter << " " << y;  // s < 0: border
      EXPECT_EQ(pixel(7, y), (Rgba{51, 153, 255, 102})) << filter << " " << y;  // s > 1
    }
    if (filter == GL_NEAREST) {
      EXPECT_EQ(pixel(2, 4), (Rgba{255, 0, 0, 255}));  // s = 0.125: texel 0
      EXPECT_EQ(pixel(5, 0), (Rgba{255, 255, 0, 255}));  // s = 0.875: texel 3
    }
  }
}

}  // namespace
}  // namespace pineda::test
