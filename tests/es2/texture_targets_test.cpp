// OpenGL ES 2.0 has the 2D and cube map targets alone: rectangle textures (a desktop
// extension) and 3D textures (GL_OES_texture_3D, which Pineda's ES 2.0 does not advertise)
// are INVALID_ENUM wherever a target is taken, and change nothing. Desktop GL keeps them
// (tests/programs/rectangle_sampler_test.cpp, tests/e2e).
#include <gtest/gtest.h>

#include <string>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

constexpr GLenum kRectangle = 0x84F5;         // GL_TEXTURE_RECTANGLE
constexpr GLenum kRectangleBinding = 0x84F6;  // GL_TEXTURE_BINDING_RECTANGLE
constexpr GLenum kTexture3D = 0x806F;         // GL_TEXTURE_3D (GL_TEXTURE_3D_OES)
constexpr GLenum kTexture3DBinding = 0x806A;  // GL_TEXTURE_BINDING_3D

class Es2TextureTargets : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(context.ok()) << context.error();
    glGenTextures(1, &tex_);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  Es2Context context{8, 8};
  GLuint tex_ = 0;
};

TEST_F(Es2TextureTargets, NoTexture3DExtension) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_EQ(extensions.find("GL_OES_texture_3D"), std::string::npos);
}

TEST_F(Es2TextureTargets, BindTextureRefusesRectangleAnd3D) {
  for (GLenum target : {kRectangle, kTexture3D}) {
    glBindTexture(target, tex_);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << target;
  }
  // The name was bound to nothing, so it still takes the 2D target.
  glBindTexture(GL_TEXTURE_2D, tex_);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint bound = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  EXPECT_EQ(bound, GLint(tex_));
  for (GLenum pname : {kRectangleBinding, kTexture3DBinding}) {
    bound = -1;
    glGetIntegerv(pname, &bound);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << pname;
    EXPECT_EQ(bound, -1) << pname;
  }
}

TEST_F(Es2TextureTargets, ImageAndParameterCallsRefuseRectangleAnd3D) {
  const GLubyte texel[4] = {1, 2, 3, 4};
  for (GLenum target : {kRectangle, kTexture3D}) {
    glTexImage2D(target, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << target;
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << target;
    const GLfloat linear = GL_LINEAR;
    glTexParameterfv(target, GL_TEXTURE_MAG_FILTER, &linear);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << target;
    GLint value = -1;
    glGetTexParameteriv(target, GL_TEXTURE_MIN_FILTER, &value);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << target;
    EXPECT_EQ(value, -1) << target;
    GLfloat fvalue = -1;
    glGetTexParameterfv(target, GL_TEXTURE_WRAP_S, &fvalue);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << target;
    EXPECT_EQ(fvalue, -1.f) << target;
  }
  // The same calls on GL_TEXTURE_2D are fine.
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  GLint value = -1;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &value);
  EXPECT_EQ(value, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es2TextureTargets, EnableRefusesRectangleAnd3D) {
  for (GLenum cap : {kRectangle, kTexture3D}) {
    glEnable(cap);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << cap;
    glDisable(cap);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << cap;
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << cap;
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << cap;
  }
}

}  // namespace
}  // namespace pineda::es2_test
