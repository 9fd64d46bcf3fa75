// GL 1.3 compressed textures with no specific compressed format (NUM_COMPRESSED_TEXTURE_FORMATS
// 0): the compressed-image calls give the spec's errors (in Mesa's order), and the generic
// compressed internal formats are stored uncompressed.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class CompressedTextureTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  GLint level_param(GLenum target, GLenum pname) {
    GLint v = -7777;
    glGetTexLevelParameteriv(target, 0, pname, &v);
    return v;
  }
};

// The S3TC DXT1 format: a real compressed format, but not one Pineda supports.
constexpr GLenum kDxt1 = 0x83F0;  // GL_COMPRESSED_RGB_S3TC_DXT1_EXT

TEST_F(CompressedTextureTest, NoSpecificFormats) {
  EXPECT_EQ(get_int(GL_NUM_COMPRESSED_TEXTURE_FORMATS), 0);
  GLint sentinel[2] = {-7, -7};
  glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, sentinel);  // writes nothing
  EXPECT_EQ(sentinel[0], -7);
  EXPECT_EQ(get_int(GL_TEXTURE_COMPRESSION_HINT), GL_DONT_CARE);
}

TEST_F(CompressedTextureTest, CompressedTexImageErrors) {
  const std::vector<uint8_t> data(64, 0);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1, 4, 4, 0, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));  // unsupported format
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));  // generic formats are never accepted here
  glCompressedTexImage2D(GL_TEXTURE_1D, 0, kDxt1, 4, 4, 0, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));  // target of another dimension
  glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, kDxt1, 4, 4, 0, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, kDxt1, 4, 4, 0, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexImage1D(GL_TEXTURE_1D, 0, kDxt1, 4, 0, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexImage3D(GL_TEXTURE_3D, 0, kDxt1, 4, 4, 4, 0, 32, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexImage2DARB(GL_TEXTURE_2D, 0, kDxt1, 4, 4, 0, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  // Nothing was defined.
  EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_WIDTH), 0);
}

TEST_F(CompressedTextureTest, CompressedTexSubImageErrors) {
  const uint8_t texels[4 * 4 * 4] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  const std::vector<uint8_t> data(64, 0);
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, kDxt1, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 4, 4, kDxt1, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, kDxt1, 8, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 4, kDxt1, 32, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(CompressedTextureTest, GetCompressedTexImageErrors) {
  std::vector<uint8_t> out(256, 0);
  glGetCompressedTexImage(GL_PROXY_TEXTURE_2D, 0, out.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP, 0, out.data());  // a face is needed
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetCompressedTexImage(GL_TEXTURE_2D, -1, out.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, out.data());  // no image
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const uint8_t texels[4 * 4 * 4] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glGetCompressedTexImageARB(GL_TEXTURE_2D, 0, out.data());  // stored uncompressed
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(out, std::vector<uint8_t>(256, 0));
}

TEST_F(CompressedTextureTest, GenericFormatsAreStoredUncompressed) {
  struct Case { GLenum generic, base; };
  const Case cases[] = {{GL_COMPRESSED_ALPHA, GL_ALPHA}, {GL_COMPRESSED_LUMINANCE, GL_LUMINANCE},
                        {GL_COMPRESSED_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA}, {GL_COMPRESSED_INTENSITY, GL_INTENSITY},
                        {GL_COMPRESSED_RGB, GL_RGB}, {GL_COMPRESSED_RGBA, GL_RGBA}};
  const uint8_t texels[2 * 2 * 4] = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150, 160};
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(c.generic), 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << c.generic;
    EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_COMPRESSED), GL_FALSE) << c.generic;
    EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), GLint(c.base)) << c.generic;
    GLint size = -7;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION)) << c.generic;  // only compressed images have one
    EXPECT_EQ(size, -7);
  }
  // The RGBA one reads back exactly.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  uint8_t back[2 * 2 * 4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(back[i], texels[i]) << i;
  EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_RED_SIZE), 8);
}

TEST_F(CompressedTextureTest, UndefinedLevelHasNoCompressedSize) {
  EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_COMPRESSED_IMAGE_SIZE), 0);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_COMPRESSED), GL_FALSE);
}

TEST_F(CompressedTextureTest, GenericFormatTexturesDraw) {
  pixel_projection();
  const uint8_t texel[4] = {200, 100, 50, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  clear_to(0, 0, 0, 0);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(0, 0);
  glTexCoord2f(1, 0);
  glVertex2f(4, 0);
  glTexCoord2f(1, 1);
  glVertex2f(4, 4);
  glTexCoord2f(0, 1);
  glVertex2f(0, 4);
  glEnd();
  EXPECT_EQ(pixel(1, 1), (Rgba{200, 100, 50, 255}));
}

TEST_F(CompressedTextureTest, DisplayListsRecordTheErrorForExecution) {
  const std::vector<uint8_t> data(8, 0);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, kDxt1, 4, 4, 0, 8, data.data());
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));  // compiled, not executed
  glCallList(list);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test
