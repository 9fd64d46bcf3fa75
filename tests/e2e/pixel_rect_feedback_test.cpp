// glBitmap, glDrawPixels and glCopyPixels in GL_FEEDBACK mode write GL_BITMAP_TOKEN,
// GL_DRAW_PIXEL_TOKEN and GL_COPY_PIXEL_TOKEN with the current raster position as the vertex
// (GL 1.1 5.3), and draw nothing; in GL_SELECT mode a valid raster position is a hit and the
// pixel commands add none (GL 1.1 5.2, appendix B corollary 6).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class PixelRectFeedbackTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();  // glOrtho(0, w, 0, h, -1, 1): window z = (1 - z) / 2
    clear_to(0, 0, 0, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  std::vector<float> feedback(GLenum type, void (*commands)()) {
    std::vector<float> buffer(64, -99.f);
    glFeedbackBuffer(64, type, buffer.data());
    glRenderMode(GL_FEEDBACK);
    commands();
    buffer.resize(size_t(glRenderMode(GL_RENDER)));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return buffer;
  }
};

TEST_F(PixelRectFeedbackTest, EachCommandWritesItsTokenAndTheRasterPosition) {
  const std::vector<float> got = feedback(GL_3D_COLOR, [] {
    static const GLubyte bits[1] = {0xff};
    static const GLubyte rgba[4] = {255, 255, 255, 255};
    glColor4f(0.25f, 0.5f, 0.75f, 1.f);
    glRasterPos3f(3, 4, 0.5f);  // window z 0.25
    glBitmap(8, 1, 0, 0, 2, 1, bits);  // moves the raster position to (5, 5)
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glCopyPixels(0, 0, 1, 1, GL_COLOR);
  });
  const std::vector<float> want = {
      GL_BITMAP_TOKEN,     3, 4, 0.25f, 0.25f, 0.5f, 0.75f, 1.f,
      GL_DRAW_PIXEL_TOKEN, 5, 5, 0.25f, 0.25f, 0.5f, 0.75f, 1.f,
      GL_COPY_PIXEL_TOKEN, 5, 5, 0.25f, 0.25f, 0.5f, 0.75f, 1.f,
  };
  EXPECT_EQ(got, want);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());  // nothing was drawn
  GLfloat position[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, position);
  EXPECT_EQ(position[0], 5.f);
  EXPECT_EQ(position[1], 5.f);
}

TEST_F(PixelRectFeedbackTest, FourDColorTextureWritesWAndTheRasterTexCoords) {
  const std::vector<float> got = feedback(GL_4D_COLOR_TEXTURE, [] {
    glColor3f(1, 0, 0);
    glTexCoord4f(0.5f, 0.25f, 0.f, 1.f);
    glWindowPos2i(7, 9);
    glBitmap(0, 0, 0, 0, 0, 0, nullptr);  // an empty bitmap still reports the position
  });
  const std::vector<float> want = {GL_BITMAP_TOKEN, 7, 9, 0, 1, 1, 0, 0, 1, 0.5f, 0.25f, 0, 1};
  EXPECT_EQ(got, want);
}

TEST_F(PixelRectFeedbackTest, AnInvalidRasterPositionWritesNothing) {
  const std::vector<float> got = feedback(GL_2D, [] {
    static const GLubyte rgba[4] = {255, 255, 255, 255};
    glRasterPos2f(-100, -100);  // outside the view volume: invalid
    glBitmap(0, 0, 0, 0, 1, 1, nullptr);
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glCopyPixels(0, 0, 1, 1, GL_COLOR);
    glPassThrough(42.f);
  });
  EXPECT_EQ(got, (std::vector<float>{GL_PASS_THROUGH_TOKEN, 42.f}));
}

TEST_F(PixelRectFeedbackTest, SelectionHitsTheRasterPositionAndDrawsNothing) {
  GLuint buffer[16] = {};
  glSelectBuffer(16, buffer);
  glRenderMode(GL_SELECT);
  glPushName(5);
  glRasterPos3f(2, 2, 0.5f);  // window z 0.25: a hit
  static const GLubyte rgba[4] = {255, 255, 255, 255};
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glLoadName(6);
  glRasterPos2f(-100, -100);  // invalid: no hit
  glLoadName(7);
  glWindowPos3f(1, 1, 1.f);  // window z 1 (llvmpipe records 0 for this hit; the position's z is 1)
  EXPECT_EQ(glRenderMode(GL_RENDER), 2);
  const GLuint quarter = 1073741824u;  // 0.25 * (2^32 - 1), rounded
  const GLuint want[] = {1, quarter, quarter, 5, 1, 0xffffffffu, 0xffffffffu, 7};
  for (size_t i = 0; i < std::size(want); ++i) EXPECT_EQ(buffer[i], want[i]) << i;
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
}

}  // namespace
}  // namespace pineda::test
