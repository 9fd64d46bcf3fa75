// GENERATE_MIPMAP with a base image that has a zero width, height or depth: a valid call that
// defines an image without texels, from which no level is derived.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class GenerateMipmapEmptyImageTest : public GlTest {
 protected:
  GLint level_size(GLenum target, GLint level, GLenum pname) {
    GLint v = -1;
    glGetTexLevelParameteriv(target, level, pname, &v);
    return v;
  }
  std::vector<uint8_t> data_ = std::vector<uint8_t>(13 * 13 * 4, 0x80);
};

TEST_F(GenerateMipmapEmptyImageTest, ZeroHeight2DImageDerivesNoLevels) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 13, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, data_.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_size(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 13);
  EXPECT_EQ(level_size(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT), 0);
  EXPECT_EQ(level_size(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH), 0);
}

TEST_F(GenerateMipmapEmptyImageTest, ZeroWidth2DImageDerivesNoLevels) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 13, 0, GL_RGBA, GL_UNSIGNED_BYTE, data_.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_size(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH), 0);
}

TEST_F(GenerateMipmapEmptyImageTest, ZeroHeight3DImageDerivesNoLevels) {
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 13, 0, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, data_.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_size(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH), 4);
  EXPECT_EQ(level_size(GL_TEXTURE_3D, 1, GL_TEXTURE_WIDTH), 0);
}

// A later non-empty base image derives its levels as usual.
TEST_F(GenerateMipmapEmptyImageTest, NonEmptyImageAfterEmptyOneDerivesLevels) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 13, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, data_.data());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, data_.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_size(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH), 2);
  EXPECT_EQ(level_size(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH), 1);
  EXPECT_EQ(level_size(GL_TEXTURE_2D, 2, GL_TEXTURE_HEIGHT), 1);
}

}  // namespace
}  // namespace pineda::test
