// Texture objects: names, binding, deletion, level and object parameters, their errors.
#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class TextureObjectTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  GLint level_param(GLenum target, GLint level, GLenum pname) {
    GLint v = -1;
    glGetTexLevelParameteriv(target, level, pname, &v);
    return v;
  }
  GLint tex_param(GLenum pname) {
    GLint v = -1;
    glGetTexParameteriv(GL_TEXTURE_2D, pname, &v);
    return v;
  }
};

TEST_F(TextureObjectTest, GenBindDeleteLifeCycle) {
  GLuint names[3] = {0, 0, 0};
  glGenTextures(3, names);
  EXPECT_NE(names[0], 0u);
  EXPECT_NE(names[0], names[1]);
  EXPECT_NE(names[1], names[2]);
  EXPECT_NE(names[0], names[2]);
  // A generated name is not a texture until it is bound.
  EXPECT_EQ(glIsTexture(names[0]), GL_FALSE);
  glBindTexture(GL_TEXTURE_2D, names[0]);
  EXPECT_EQ(glIsTexture(names[0]), GL_TRUE);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), GLint(names[0]));
  glBindTexture(GL_TEXTURE_1D, names[1]);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_1D), GLint(names[1]));
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), GLint(names[0]));
  // Deleting a bound texture reverts the binding to 0.
  glDeleteTextures(2, names);
  EXPECT_EQ(glIsTexture(names[0]), GL_FALSE);
  EXPECT_EQ(glIsTexture(names[1]), GL_FALSE);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 0);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_1D), 0);
  EXPECT_EQ(glIsTexture(0), GL_FALSE);
  // Deleting 0 and unused names is silently ignored.
  const GLuint odd[2] = {0, 123456};
  glDeleteTextures(2, odd);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // Generated names are not reused while still in use.
  GLuint more[2];
  glGenTextures(2, more);
  EXPECT_NE(more[0], names[2]);
  EXPECT_NE(more[1], names[2]);
}

TEST_F(TextureObjectTest, BindingAnUngeneratedNameCreatesIt) {
  glBindTexture(GL_TEXTURE_2D, 77);
  EXPECT_EQ(glIsTexture(77), GL_TRUE);
  GLuint name = 0;
  glGenTextures(1, &name);
  EXPECT_NE(name, 77u);
}

TEST_F(TextureObjectTest, Errors) {
  GLuint name;
  glGenTextures(-1, &name);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteTextures(-1, &name);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBindTexture(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 5);  // a face, not a binding target
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glIsTexture(5), GL_FALSE);
  // A texture keeps the dimensionality it was first bound with.
  glBindTexture(GL_TEXTURE_2D, 9);
  glBindTexture(GL_TEXTURE_1D, 9);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_1D), 0);
}

TEST_F(TextureObjectTest, InitialParameters) {
  GLuint name;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  EXPECT_EQ(tex_param(GL_TEXTURE_MAG_FILTER), GL_LINEAR);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_S), GL_REPEAT);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_T), GL_REPEAT);
  GLfloat border[4] = {-1, -1, -1, -1};
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  for (float c : border) EXPECT_EQ(c, 0.f);
  GLfloat priority = -1;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &priority);
  EXPECT_EQ(priority, 1.f);
  EXPECT_EQ(tex_param(GL_TEXTURE_RESIDENT), GL_TRUE);
}

TEST_F(TextureObjectTest, ParametersAreStoredPerObject) {
  GLuint names[2];
  glGenTextures(2, names);
  glBindTexture(GL_TEXTURE_2D, names[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  const GLint wrap = GL_CLAMP_TO_EDGE;
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &wrap);
  const GLfloat border[4] = {0.25f, 0.5f, 2.f, -1.f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glBindTexture(GL_TEXTURE_2D, names[1]);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  glBindTexture(GL_TEXTURE_2D, names[0]);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_NEAREST);
  EXPECT_EQ(tex_param(GL_TEXTURE_MAG_FILTER), GL_NEAREST);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_S), GL_CLAMP);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_T), GL_CLAMP_TO_EDGE);
  GLfloat got[4];
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  EXPECT_EQ(got[0], 0.25f);
  EXPECT_EQ(got[1], 0.5f);
  EXPECT_EQ(got[2], 1.f);  // clamped
  EXPECT_EQ(got[3], 0.f);
  GLint ints[4];
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, ints);
  EXPECT_NEAR(double(ints[0]), 0.25 * kIntColorScale, 1.0);
  EXPECT_EQ(ints[2], 2147483647);
  EXPECT_EQ(ints[3], 0);
}

TEST_F(TextureObjectTest, ParameterErrorsChangeNothing) {
  glBindTexture(GL_TEXTURE_2D, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, 0x1234, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1.f);  // a vector parameter
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(tex_param(GL_TEXTURE_MAG_FILTER), GL_LINEAR);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_S), GL_REPEAT);
  GLint v = 99;
  glGetTexParameteriv(GL_TEXTURE_2D, 0x1234, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v, 99);
}

TEST_F(TextureObjectTest, LevelParametersOfAnImage) {
  glBindTexture(GL_TEXTURE_2D, 4);
  std::vector<uint8_t> pixels(8 * 4 * 4, 0x80);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glTexImage2D(GL_TEXTURE_2D, 1, GL_LUMINANCE_ALPHA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 8);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT), 4);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_BORDER), 0);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA8);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE), 8);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE), 8);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE), 0);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH), 4);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 1, GL_TEXTURE_HEIGHT), 2);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 1, GL_TEXTURE_INTERNAL_FORMAT), GL_LUMINANCE_ALPHA);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 1, GL_TEXTURE_RED_SIZE), 0);
  EXPECT_GT(level_param(GL_TEXTURE_2D, 1, GL_TEXTURE_LUMINANCE_SIZE), 0);
  EXPECT_GT(level_param(GL_TEXTURE_2D, 1, GL_TEXTURE_ALPHA_SIZE), 0);
  // An undefined level has size 0 and the initial internal format 1.
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH), 0);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 2, GL_TEXTURE_INTERNAL_FORMAT), 1);
  GLfloat f = -1;
  glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &f);
  EXPECT_EQ(f, 8.f);
}

TEST_F(TextureObjectTest, LevelParametersWithBorderAnd1D) {
  glBindTexture(GL_TEXTURE_1D, 6);
  std::vector<uint8_t> pixels(18 * 3, 0);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 18, 1, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  EXPECT_EQ(level_param(GL_TEXTURE_1D, 0, GL_TEXTURE_WIDTH), 18);
  EXPECT_EQ(level_param(GL_TEXTURE_1D, 0, GL_TEXTURE_HEIGHT), 1);
  EXPECT_EQ(level_param(GL_TEXTURE_1D, 0, GL_TEXTURE_BORDER), 1);
  EXPECT_EQ(level_param(GL_TEXTURE_1D, 0, GL_TEXTURE_ALPHA_SIZE), 0);
  EXPECT_EQ(level_param(GL_TEXTURE_1D, 0, GL_TEXTURE_BLUE_SIZE), 8);
}

TEST_F(TextureObjectTest, LevelParameterErrorsWriteNothing) {
  GLint v = 55;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, 0x1234, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetTexLevelParameteriv(GL_TEXTURE_ENV, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v, 55);
  GLfloat f = 55.f;
  glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, 0x1234, &f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(f, 55.f);
}

TEST_F(TextureObjectTest, TexImageErrorsDefineNothing) {
  glBindTexture(GL_TEXTURE_2D, 8);
  const uint8_t pixels[64] = {};
  glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, 0x1234, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, 0x1234, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, get_int(GL_MAX_TEXTURE_SIZE) + 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(level_param(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
  // TexSubImage needs a defined level and a region inside it.
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureObjectTest, PrioritiesAndResidence) {
  GLuint names[2];
  glGenTextures(2, names);
  glBindTexture(GL_TEXTURE_2D, names[0]);
  glBindTexture(GL_TEXTURE_2D, names[1]);
  const GLfloat priorities[2] = {0.25f, 3.f};
  glPrioritizeTextures(2, names, priorities);
  GLfloat p = -1;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  EXPECT_EQ(p, 1.f);  // clamped
  glBindTexture(GL_TEXTURE_2D, names[0]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  EXPECT_EQ(p, 0.25f);
  GLboolean residences[2] = {7, 7};
  EXPECT_EQ(glAreTexturesResident(2, names, residences), GL_TRUE);
  const GLuint bad[2] = {names[0], 0};
  EXPECT_EQ(glAreTexturesResident(2, bad, residences), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

}  // namespace
}  // namespace pineda::test
