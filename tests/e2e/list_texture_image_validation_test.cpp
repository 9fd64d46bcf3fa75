// glTexImage*D and glTexSubImage*D compiled into display lists: the arguments are checked as
// the immediate calls check them before any pixel is copied, so sizes above the limits copy
// nothing (the client buffers here are a few bytes) and the list records the immediate error.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/guarded_memory.h"

namespace pineda::test {
namespace {

class ListTextureImageValidationTest : public GlTest {
 protected:
  // The error of `call` compiled into list 1 (no error while compiling) and then called.
  template <typename Call>
  GLenum compiled_error(Call call) {
    glNewList(1, GL_COMPILE);
    call();
    glEndList();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glCallList(1);
    return glGetError();
  }

  template <typename Call>
  GLenum immediate_error(Call call) {
    call();
    return glGetError();
  }

  std::vector<uint8_t> small_ = std::vector<uint8_t>(16, 0x5a);
};

TEST_F(ListTextureImageValidationTest, CubeFaceAboveLimitsCompiledAndExecutedIsInvalidValue) {
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_LUMINANCE16, 1185050933, 4099, 0, GL_RGBA,
               GL_UNSIGNED_INT_10_10_10_2, small_.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ListTextureImageValidationTest, TexImagesAboveMaxSizeAreInvalidValueAsImmediate) {
  const void* p = small_.data();
  auto image1d = [&] { glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1 << 30, 0, GL_RGBA, GL_UNSIGNED_BYTE, p); };
  auto image2d = [&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8193, 1 << 20, 0, GL_RGBA, GL_FLOAT, p); };
  auto image3d = [&] { glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 100000, 0, GL_RGBA, GL_UNSIGNED_BYTE, p); };
  auto level5 = [&] { glTexImage2D(GL_TEXTURE_2D, 5, GL_RGBA, 8192, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, p); };
  auto square32k = [&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32768, 32768, 0, GL_RGBA, GL_FLOAT, p); };
  EXPECT_EQ(immediate_error(image1d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(image1d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(immediate_error(image2d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(image2d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(immediate_error(image3d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(image3d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(immediate_error(level5), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(level5), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(immediate_error(square32k), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(square32k), GLenum(GL_INVALID_VALUE));
}

TEST_F(ListTextureImageValidationTest, InvalidTypeCopiesNothingAndIsInvalidEnum) {
  // GL_TEXTURE_2D is no pixel type.
  auto call = [&] {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1 << 14, 1 << 14, 0, GL_RGBA, GL_TEXTURE_2D, small_.data());
  };
  EXPECT_EQ(immediate_error(call), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(compiled_error(call), GLenum(GL_INVALID_ENUM));
}

TEST_F(ListTextureImageValidationTest, TexSubImagesLargerThanAnyLevelAreInvalidValueAsImmediate) {
  const uint8_t texels[4 * 4 * 4] = {};
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const void* p = small_.data();
  auto sub1d = [&] { glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 1 << 30, GL_RGBA, GL_UNSIGNED_BYTE, p); };
  auto sub2d = [&] { glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 100000, 100000, GL_RGBA, GL_UNSIGNED_BYTE, p); };
  auto sub3d = [&] { glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 2, 1 << 24, GL_RGBA, GL_UNSIGNED_BYTE, p); };
  EXPECT_EQ(immediate_error(sub1d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(sub1d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(immediate_error(sub2d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(sub2d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(immediate_error(sub3d), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(sub3d), GLenum(GL_INVALID_VALUE));
}

TEST_F(ListTextureImageValidationTest, TexSubImageOfUndefinedLevelIsInvalidOperationAsImmediate) {
  auto call = [&] { glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, small_.data()); };
  EXPECT_EQ(immediate_error(call), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(compiled_error(call), GLenum(GL_INVALID_OPERATION));
}

// SKIP_IMAGES given as 3.4e38 is stored as the largest integer; a valid 3D image then starts
// 32 GiB past the pointer, and only its 16 bytes there may be read.
TEST_F(ListTextureImageValidationTest, HugeSkipImagesReadsOnlyTheSkippedToImage) {
  glPixelStoref(GL_UNPACK_SKIP_IMAGES, 3.4e38f);
  GLint skip = 0;
  glGetIntegerv(GL_UNPACK_SKIP_IMAGES, &skip);
  ASSERT_EQ(skip, 2147483647);
  const size_t image_bytes = 2 * 2 * 4, offset = size_t(skip) * image_bytes;
  GuardedMemory memory(offset + 4096, offset, image_bytes);
  ASSERT_TRUE(memory.ok());
  for (size_t i = 0; i < image_bytes; ++i) memory.base()[offset + i] = uint8_t(10 * i + 1);
  const std::vector<uint8_t> expected(memory.base() + offset, memory.base() + offset + image_bytes);

  glNewList(1, GL_COMPILE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, memory.base());
  glEndList();
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  glCallList(1);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> listed(image_bytes);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, listed.data());
  EXPECT_EQ(listed, expected);

  glPixelStorei(GL_UNPACK_SKIP_IMAGES, skip);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, memory.base());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> immediate(image_bytes);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, immediate.data());
  EXPECT_EQ(immediate, expected);
}

TEST_F(ListTextureImageValidationTest, HugeSkipImagesWithDepthAboveMaxReadsNothing) {
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 2147483647);
  auto call = [&] { glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 8, 257, 0, GL_RGBA, GL_UNSIGNED_BYTE, small_.data()); };
  EXPECT_EQ(immediate_error(call), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(compiled_error(call), GLenum(GL_INVALID_VALUE));
}

}  // namespace
}  // namespace pineda::test
