// State of the GL 1.2/1.3 texture targets: limits, bindings, enables, TEXTURE_WRAP_R, the 3D
// pixel store parameters, and what the server and client attribute stacks save of them.
#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class TextureTargetsStateTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

TEST_F(TextureTargetsStateTest, Limits) {
  EXPECT_EQ(get_int(GL_MAX_3D_TEXTURE_SIZE), 256);
  EXPECT_EQ(get_int(GL_MAX_CUBE_MAP_TEXTURE_SIZE), 4096);
}

TEST_F(TextureTargetsStateTest, BindingsPerUnit) {
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_3D), 0);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_CUBE_MAP), 0);
  glBindTexture(GL_TEXTURE_3D, 7);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 8);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_3D), 7);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_CUBE_MAP), 8);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 0);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_3D), 0);
  glActiveTexture(GL_TEXTURE0);
  // A name keeps the target it was first bound to.
  glBindTexture(GL_TEXTURE_2D, 7);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBindTexture(GL_TEXTURE_CUBE_MAP, 7);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBindTexture(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 9);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  // Deleting a bound texture binds 0.
  const GLuint names[] = {7, 8};
  glDeleteTextures(2, names);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_3D), 0);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_CUBE_MAP), 0);
}

TEST_F(TextureTargetsStateTest, EnablesAndWrapR) {
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_3D), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_CUBE_MAP), GL_FALSE);
  glEnable(GL_TEXTURE_3D);
  glEnable(GL_TEXTURE_CUBE_MAP);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_3D), GL_TRUE);
  EXPECT_EQ(get_bool(GL_TEXTURE_CUBE_MAP), GL_TRUE);
  GLint wrap = 0;
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &wrap);
  EXPECT_EQ(wrap, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, &wrap);
  EXPECT_EQ(wrap, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, GL_TEXTURE_WRAP_S, GL_REPEAT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(TextureTargetsStateTest, PixelStoreImageParameters) {
  const GLenum pnames[] = {GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES};
  for (GLenum p : pnames) EXPECT_EQ(get_int(p), 0);
  GLint value = 3;
  for (GLenum p : pnames) glPixelStorei(p, value++);
  value = 3;
  for (GLenum p : pnames) EXPECT_EQ(get_int(p), value++) << std::hex << p;
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelStoref(GL_PACK_IMAGE_HEIGHT, -2.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_PACK_IMAGE_HEIGHT), 3);
}

TEST_F(TextureTargetsStateTest, ClientAttribStackSavesImageParameters) {
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 4);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 2);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 9);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 5);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 6);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_PACK_IMAGE_HEIGHT), 4);
  EXPECT_EQ(get_int(GL_UNPACK_SKIP_IMAGES), 2);
  EXPECT_EQ(get_int(GL_UNPACK_IMAGE_HEIGHT), 0);
}

TEST_F(TextureTargetsStateTest, AttribStackSavesEnablesBindingsAndParameters) {
  glBindTexture(GL_TEXTURE_3D, 3);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 4);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_3D);
  glPushAttrib(GL_TEXTURE_BIT);
  glDisable(GL_TEXTURE_3D);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_3D, 5);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 6);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_3D), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_CUBE_MAP), GL_FALSE);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_3D), 3);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_CUBE_MAP), 4);
  GLint v = 0;
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v);
  EXPECT_EQ(v, GL_MIRRORED_REPEAT);
  glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(v, GL_LINEAR);

  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_3D);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_3D), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_CUBE_MAP), GL_FALSE);
}

}  // namespace
}  // namespace pineda::test
