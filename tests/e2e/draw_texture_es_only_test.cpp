// OES_draw_texture is OpenGL ES 1.1's only: a desktop context refuses its calls and its
// texture parameter (tests/es1/draw_texture_test.cpp has the extension itself).
#include <GL/gl.h>

#include "tests/e2e/support/gl_test.h"

extern "C" void glDrawTexiOES(GLint x, GLint y, GLint z, GLint width, GLint height);

namespace pineda::test {
namespace {

constexpr GLenum kTextureCropRect = 0x8B9D;  // GL_TEXTURE_CROP_RECT_OES

using DrawTextureEsOnlyTest = GlTest;

TEST_F(DrawTextureEsOnlyTest, RefusedByDesktopContexts) {
  clear_to(0, 0, 0, 0);
  glDrawTexiOES(0, 0, 0, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  const GLint rect[] = {0, 0, 4, 4};
  glTexParameteriv(GL_TEXTURE_2D, kTextureCropRect, rect);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint got[4] = {-1, -1, -1, -1};
  glGetTexParameteriv(GL_TEXTURE_2D, kTextureCropRect, got);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(got[0], -1);
}

}  // namespace
}  // namespace pineda::test
