// State of ARB_texture_rectangle's target: limits, bindings, enables, the initial parameters
// of a rectangle texture, the errors the extension adds (one level, no mipmap filters, no
// repeating wraps), proxies, the attribute stack and display lists.
#define GL_GLEXT_PROTOTYPES
#include <string>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class TextureRectangleStateTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  GLint tex_param(GLenum pname) {
    GLint v = -1;
    glGetTexParameteriv(GL_TEXTURE_RECTANGLE_ARB, pname, &v);
    return v;
  }
  GLint level_param(GLenum target, GLenum pname) {
    GLint v = -1;
    glGetTexLevelParameteriv(target, 0, pname, &v);
    return v;
  }
};

TEST_F(TextureRectangleStateTest, ExtensionNamesAndLimit) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  for (const char* name : {"GL_ARB_texture_rectangle ", "GL_NV_texture_rectangle ", "GL_EXT_texture_rectangle "})
    EXPECT_NE(extensions.find(name), std::string::npos) << name;
  EXPECT_EQ(get_int(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB), 8192);
}

TEST_F(TextureRectangleStateTest, NewObjectsStartClampedAndLinear) {
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 5);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_RECTANGLE_ARB), 5);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_T), GL_CLAMP_TO_EDGE);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_R), GL_CLAMP_TO_EDGE);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_LINEAR);
  EXPECT_EQ(tex_param(GL_TEXTURE_MAG_FILTER), GL_LINEAR);
  // The same name's 2D defaults are not affected: a 2D object still repeats.
  glBindTexture(GL_TEXTURE_2D, 6);
  GLint wrap = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &wrap);
  EXPECT_EQ(wrap, GL_REPEAT);
}

TEST_F(TextureRectangleStateTest, NamesKeepTheirFirstTarget) {
  glBindTexture(GL_TEXTURE_2D, 3);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 4);
  glBindTexture(GL_TEXTURE_2D, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_RECTANGLE_ARB), 4);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 3);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_RECTANGLE_ARB), 0);
  glActiveTexture(GL_TEXTURE0);
  const GLuint name = 4;
  glDeleteTextures(1, &name);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_RECTANGLE_ARB), 0);
}

TEST_F(TextureRectangleStateTest, EnablePerUnit) {
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_FALSE);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_TRUE);
  EXPECT_EQ(get_int(GL_TEXTURE_RECTANGLE_ARB), 1);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_FALSE);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_FALSE);
}

struct ParameterCase {
  GLenum pname;
  GLint value;
  GLenum error;
};

TEST_F(TextureRectangleStateTest, ParameterErrors) {
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
  const ParameterCase cases[] = {
      {GL_TEXTURE_WRAP_S, GL_REPEAT, GL_INVALID_ENUM},
      {GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT, GL_INVALID_ENUM},
      {GL_TEXTURE_WRAP_R, GL_REPEAT, GL_INVALID_ENUM},
      {GL_TEXTURE_WRAP_S, GL_CLAMP, GL_NO_ERROR},
      {GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER, GL_NO_ERROR},
      {GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE, GL_NO_ERROR},
      {GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST, GL_INVALID_ENUM},
      {GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR, GL_INVALID_ENUM},
      {GL_TEXTURE_MIN_FILTER, GL_NEAREST, GL_NO_ERROR},
      {GL_TEXTURE_MAG_FILTER, GL_NEAREST, GL_NO_ERROR},
      {GL_TEXTURE_BASE_LEVEL, 1, GL_INVALID_OPERATION},
      {GL_TEXTURE_BASE_LEVEL, -1, GL_INVALID_VALUE},
      {GL_TEXTURE_BASE_LEVEL, 0, GL_NO_ERROR},
      {GL_TEXTURE_MAX_LEVEL, 3, GL_NO_ERROR},
  };
  for (const ParameterCase& c : cases) {
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, c.pname, c.value);
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.pname << " " << c.value;
  }
  // The failed calls changed nothing.
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_T), GL_CLAMP_TO_BORDER);
  EXPECT_EQ(tex_param(GL_TEXTURE_WRAP_R), GL_CLAMP_TO_EDGE);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_NEAREST);
  EXPECT_EQ(tex_param(GL_TEXTURE_BASE_LEVEL), 0);
  // The default rectangle texture (name 0) follows the same rules.
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 0);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_LINEAR);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_REPEAT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(TextureRectangleStateTest, OneLevelOnly) {
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
  const uint8_t texels[3 * 5 * 4] = {};
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, 3, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 3, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH), 3);
  EXPECT_EQ(level_param(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_HEIGHT), 5);
  glTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint v = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE_ARB, 1, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  uint8_t out[3 * 5 * 4];
  glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, 0, 0, 2, 2, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGenerateMipmap(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCompressedTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 4, 4, 0, 8, texels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  // A rectangle is not a 1D or 3D target, and the binding target is not an image target of
  // glTexImage1D.
  glTexImage1D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(TextureRectangleStateTest, ProxyAndSizeLimit) {
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 8192, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH), 8192);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_HEIGHT), 3);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA);
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 8193, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH), 0);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_HEIGHT), 0);
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 1, 8193, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  // Depth images are allowed, as for 2D textures.
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_DEPTH_COMPONENT24, 7, 3, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_DEPTH_SIZE), 24);
}

TEST_F(TextureRectangleStateTest, AttribStackSavesEnableBindingAndParameters) {
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 3);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  glPushAttrib(GL_TEXTURE_BIT);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 4);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_TRUE);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_RECTANGLE_ARB), 3);
  EXPECT_EQ(tex_param(GL_TEXTURE_MIN_FILTER), GL_NEAREST);

  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_TRUE);
}

TEST_F(TextureRectangleStateTest, DisplayListsCompileTheTarget) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 9);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_FALSE);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_RECTANGLE_ARB), 0);
  glCallList(list);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_RECTANGLE_ARB), GL_TRUE);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_RECTANGLE_ARB), 9);
  EXPECT_EQ(tex_param(GL_TEXTURE_MAG_FILTER), GL_NEAREST);
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test
