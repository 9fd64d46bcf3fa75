// ARB_texture_storage: glTexStorage1D/2D/3D make every level at once and freeze the storage;
// the levels' sizes, TEXTURE_IMMUTABLE_FORMAT, each error, the calls refused afterwards, the
// clamped base and maximum levels, proxies, sampling the levels, display lists.
#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/window_quad.h"
#include "tests/state/get_helpers.h"

// Its own namespace: a unity batch holds other texture tests' helpers.
namespace pineda::test::texture_storage {
namespace {

class TextureStorageTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glGenTextures(1, &tex_);
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glDeleteTextures(1, &tex_);
    GlTest::TearDown();
  }
  static GLint level_param(GLenum target, GLint level, GLenum pname) {
    GLint v = -1;
    glGetTexLevelParameteriv(target, level, pname, &v);
    return v;
  }
  static GLint tex_param(GLenum target, GLenum pname) {
    GLint v = -1;
    glGetTexParameteriv(target, pname, &v);
    return v;
  }
  // The error the call left, and none after it.
  static GLenum error() {
    const GLenum e = glGetError();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return e;
  }
  GLuint tex_ = 0;
};

TEST_F(TextureStorageTest, Advertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_texture_storage "), std::string::npos);
}

TEST_F(TextureStorageTest, EveryLevelOfA2DTexture) {
  glBindTexture(GL_TEXTURE_2D, tex_);
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT), GL_FALSE);
  glTexStorage2D(GL_TEXTURE_2D, 4, GL_RGBA8, 32, 8);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT), GL_TRUE);
  const int sizes[4][2] = {{32, 8}, {16, 4}, {8, 2}, {4, 1}};
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(level_param(GL_TEXTURE_2D, l, GL_TEXTURE_WIDTH), sizes[l][0]) << l;
    EXPECT_EQ(level_param(GL_TEXTURE_2D, l, GL_TEXTURE_HEIGHT), sizes[l][1]) << l;
    EXPECT_EQ(level_param(GL_TEXTURE_2D, l, GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA8) << l;
  }
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 4, GL_TEXTURE_WIDTH), 0);  // no fifth level
  GLfloat f = -1.f;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, &f);
  EXPECT_EQ(f, 1.f);
}

TEST_F(TextureStorageTest, OneAndThreeDimensionsAndCubeFaces) {
  glBindTexture(GL_TEXTURE_1D, tex_);
  glTexStorage1D(GL_TEXTURE_1D, 3, GL_LUMINANCE8, 16);
  EXPECT_EQ(level_param(GL_TEXTURE_1D, 2, GL_TEXTURE_WIDTH), 4);
  EXPECT_EQ(level_param(GL_TEXTURE_1D, 2, GL_TEXTURE_LUMINANCE_SIZE), 8);
  GLuint more[2];
  glGenTextures(2, more);
  glBindTexture(GL_TEXTURE_3D, more[0]);
  glTexStorage3D(GL_TEXTURE_3D, 3, GL_RGB8, 8, 4, 16);
  EXPECT_EQ(level_param(GL_TEXTURE_3D, 2, GL_TEXTURE_WIDTH), 2);
  EXPECT_EQ(level_param(GL_TEXTURE_3D, 2, GL_TEXTURE_HEIGHT), 1);
  EXPECT_EQ(level_param(GL_TEXTURE_3D, 2, GL_TEXTURE_DEPTH), 4);
  glBindTexture(GL_TEXTURE_CUBE_MAP, more[1]);
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, 2, GL_RGBA8, 8, 8);
  for (GLenum face = GL_TEXTURE_CUBE_MAP_POSITIVE_X; face <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z; ++face) {
    EXPECT_EQ(level_param(face, 0, GL_TEXTURE_WIDTH), 8) << face;
    EXPECT_EQ(level_param(face, 1, GL_TEXTURE_HEIGHT), 4) << face;
  }
  EXPECT_EQ(tex_param(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_IMMUTABLE_FORMAT), GL_TRUE);
  glDeleteTextures(2, more);
}

TEST_F(TextureStorageTest, ErrorsLeaveTheTextureMutable) {
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexStorage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 1, GL_RGBA8, 4, 4);  // a face is no target
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  glTexStorage2D(GL_TEXTURE_3D, 1, GL_RGBA8, 4, 4);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  glTexStorage1D(GL_TEXTURE_2D, 1, GL_RGBA8, 4);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  for (GLenum unsized : {GLenum(GL_RGBA), GLenum(GL_RGB), GLenum(GL_LUMINANCE), GLenum(GL_DEPTH_COMPONENT),
                         GLenum(GL_COMPRESSED_RGBA), GLenum(GL_SRGB_ALPHA), GLenum(4), GLenum(0x1234)}) {
    glTexStorage2D(GL_TEXTURE_2D, 1, unsized, 4, 4);
    EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM)) << std::hex << unsized;
  }
  glTexStorage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 0, 4);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 4, -1);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glTexStorage2D(GL_TEXTURE_2D, 4, GL_RGBA8, 4, 2);  // 4x2 has three levels
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 16384, 4);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glTexStorage3D(GL_TEXTURE_3D, 1, GL_DEPTH_COMPONENT24, 4, 4, 4);  // the default texture: 0
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  GLuint cube = 0, volume = 0;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA8, 8, 4);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glGenTextures(1, &volume);
  glBindTexture(GL_TEXTURE_3D, volume);
  glTexStorage3D(GL_TEXTURE_3D, 1, GL_DEPTH_COMPONENT24, 4, 4, 4);  // no 3D depth textures
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT), GL_FALSE);
  EXPECT_EQ(tex_param(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_IMMUTABLE_FORMAT), GL_FALSE);
  EXPECT_EQ(tex_param(GL_TEXTURE_3D, GL_TEXTURE_IMMUTABLE_FORMAT), GL_FALSE);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, GL_TRUE);  // read only
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  glDeleteTextures(1, &cube);
  glDeleteTextures(1, &volume);
}

// The spec's "even if it does not affect the dimensions or format": glTexImage*,
// glCopyTexImage* and glTexStorage* are refused; the sub-image calls still write.
TEST_F(TextureStorageTest, ImmutableStorageRefusesNewImages) {
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexStorage2D(GL_TEXTURE_2D, 2, GL_RGBA8, 4, 4);
  std::vector<uint8_t> texels(4 * 4 * 4, 200);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 5, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 4, 4, 0);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glTexStorage2D(GL_TEXTURE_2D, 2, GL_RGBA8, 4, 4);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 5, GL_TEXTURE_WIDTH), 0);
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> back(2 * 2 * 4, 0);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  EXPECT_EQ(back, std::vector<uint8_t>(2 * 2 * 4, 200));
  glTexSubImage2D(GL_TEXTURE_2D, 2, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());  // no level 2
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(TextureStorageTest, BaseAndMaxLevelsAreClampedIntoTheLevels) {
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 5);
  glTexStorage2D(GL_TEXTURE_2D, 3, GL_RGBA8, 256, 256);
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL), 2);
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL), 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4);
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL), 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL), 1);  // not below the base level
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 9);
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL), 2);
}

// A proxy takes the levels when they fit, zeros when not; neither is an error or immutable.
TEST_F(TextureStorageTest, Proxies) {
  glTexStorage2D(GL_PROXY_TEXTURE_2D, 3, GL_RGBA4, 64, 16);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, 2, GL_TEXTURE_WIDTH), 16);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, 2, GL_TEXTURE_HEIGHT), 4);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, 2, GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA4);
  glTexStorage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA8, 16384, 16);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT), 0);
  glTexStorage2D(GL_PROXY_TEXTURE_CUBE_MAP, 2, GL_RGBA8, 16, 16);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_CUBE_MAP, 1, GL_TEXTURE_WIDTH), 8);
  glTexStorage3D(GL_PROXY_TEXTURE_3D, 1, GL_RGBA8, 512, 4, 4);  // above MAX_3D_TEXTURE_SIZE
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH), 0);
  glTexStorage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA, 4, 4);  // the format is still checked
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
}

// Each level filled with its own colour and drawn alone through BASE/MAX_LEVEL, then
// glGenerateMipmap, which fills the levels there are and adds none.
TEST_F(TextureStorageTest, LevelsAreSampledAndGeneratedInPlace) {
  pixel_projection();
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexStorage2D(GL_TEXTURE_2D, 3, GL_RGBA8, 8, 8);
  const Rgba colours[3] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
  for (int l = 0; l < 3; ++l) {
    const int size = 8 >> l;
    std::vector<uint8_t> texels;
    for (int i = 0; i < size * size; ++i)
      for (int c = 0; c < 4; ++c) texels.push_back(uint8_t(colours[l][size_t(c)]));
    glTexSubImage2D(GL_TEXTURE_2D, l, 0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  for (int l = 0; l < 3; ++l) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, l);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, l);
    draw_textured_rect(0, 0, 8, 8, 0, 0, 1, 1);
    EXPECT_TRUE(near_rgba(pixel(4, 4), colours[l])) << l;
  }
  // The whole chain (base 0, max clamped to 2) is complete: minified 8x, level 2 is sampled.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
  draw_textured_rect(0, 0, 1, 1, 0, 0, 1, 1);
  EXPECT_TRUE(near_rgba(pixel(0, 0), colours[2]));
  glGenerateMipmap(GL_TEXTURE_2D);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH), 0);
  draw_textured_rect(0, 0, 1, 1, 0, 0, 1, 1);
  EXPECT_TRUE(near_rgba(pixel(0, 0), colours[0]));  // level 2 now averages the red level 0
}

TEST_F(TextureStorageTest, DisplayListsExecuteItAtOnce) {
  glBindTexture(GL_TEXTURE_2D, tex_);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 4, 4);
  glEndList();
  EXPECT_EQ(tex_param(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT), GL_TRUE);
  glCallList(list);  // nothing recorded: no second glTexStorage2D and no error
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test::texture_storage
