// Texture swizzles (GL_EXT_texture_swizzle / GL_ARB_texture_swizzle): the parameters, their
// initial values and errors, and each channel of a sampled texel taken from a channel, zero or
// one, for fixed function (the environment keeps the base format) and shaders alike, on colour
// and depth textures, border colours and sub-image updates.
#include <string>

#include "tests/programs/program_test.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {
namespace {

class TextureSwizzleTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  GLint param(GLenum pname) {
    GLint v = -1;
    glGetTexParameteriv(GL_TEXTURE_2D, pname, &v);
    return v;
  }
  void load_texel(const GLubyte rgba[4]) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  }
  void set_swizzle(GLint r, GLint g, GLint b, GLint a) {
    const GLint rgba[4] = {r, g, b, a};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, rgba);
  }
  // Fixed function, GL_REPLACE, a 4x4 square at the origin with s, t in [s0, s1].
  Rgba fixed_function_pixel(float s0 = 0.f, float s1 = 1.f) {
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    draw_textured_rect(0, 0, 4, 4, s0, s0, s1, s1);
    glDisable(GL_TEXTURE_2D);
    return pixel(1, 1);
  }
  Rgba shader_pixel(float s0 = 0.f, float s1 = 1.f) {
    const GLuint p = link("void main() { gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = ftransform(); }\n",
                          "uniform sampler2D tex;\n"
                          "void main() { gl_FragColor = texture2D(tex, gl_TexCoord[0].xy); }\n");
    EXPECT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
    glUseProgram(p);
    draw_textured_rect(0, 0, 4, 4, s0, s0, s1, s1);
    glUseProgram(0);
    glDeleteProgram(p);
    return pixel(1, 1);
  }
};

TEST_F(TextureSwizzleTest, ParametersInitialValuesAndErrors) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(extensions.find("GL_EXT_texture_swizzle "), std::string::npos);
  EXPECT_NE(extensions.find("GL_ARB_texture_swizzle "), std::string::npos);
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_R), GL_RED);
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_G), GL_GREEN);
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_B), GL_BLUE);
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_A), GL_ALPHA);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, GL_ONE);
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_G), GL_ONE);
  set_swizzle(GL_ALPHA, GL_ZERO, GL_RED, GL_GREEN);
  GLint rgba[4] = {};
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, rgba);
  EXPECT_EQ(rgba[0], GL_ALPHA);
  EXPECT_EQ(rgba[1], GL_ZERO);
  EXPECT_EQ(rgba[2], GL_RED);
  EXPECT_EQ(rgba[3], GL_GREEN);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, GL_LUMINANCE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  set_swizzle(GL_RED, GL_GREEN, GL_BLUE, GL_TEXTURE_2D);  // one bad value: nothing is set
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, GL_RED);  // a vector parameter
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_R), GL_ALPHA);
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_A), GL_GREEN);
  // Texture state: glPushAttrib(GL_TEXTURE_BIT) saves it.
  glPushAttrib(GL_TEXTURE_BIT);
  set_swizzle(GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA);
  glPopAttrib();
  EXPECT_EQ(param(GL_TEXTURE_SWIZZLE_R), GL_ALPHA);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureSwizzleTest, FixedFunctionAndShadersReadSwizzledTexels) {
  const GLubyte texel[4] = {0x10, 0x20, 0x30, 0x40};
  load_texel(texel);
  EXPECT_EQ(fixed_function_pixel(), (Rgba{0x10, 0x20, 0x30, 0x40}));
  set_swizzle(GL_BLUE, GL_ALPHA, GL_ZERO, GL_ONE);
  EXPECT_EQ(fixed_function_pixel(), (Rgba{0x30, 0x40, 0, 255}));
  EXPECT_EQ(shader_pixel(), (Rgba{0x30, 0x40, 0, 255}));
  // The bilinear samplers read the swizzled texels too.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  EXPECT_EQ(fixed_function_pixel(), (Rgba{0x30, 0x40, 0, 255}));
  EXPECT_EQ(shader_pixel(), (Rgba{0x30, 0x40, 0, 255}));
  // A sub-image update is swizzled as the rest.
  const GLubyte other[4] = {0x50, 0x60, 0x70, 0x80};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, other);
  EXPECT_EQ(fixed_function_pixel(), (Rgba{0x70, 0x80, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureSwizzleTest, EnvironmentKeepsTheBaseFormat) {
  // An alpha texture under GL_REPLACE keeps the fragment's colour whatever its swizzle gives
  // R, G and B; its alpha is the swizzled one.
  const GLubyte alpha = 0x80;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA8, 1, 1, 0, GL_ALPHA, GL_UNSIGNED_BYTE, &alpha);
  glColor4ub(0x11, 0x22, 0x33, 0x44);
  set_swizzle(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  EXPECT_EQ(fixed_function_pixel(), (Rgba{0x11, 0x22, 0x33, 0xff}));
  set_swizzle(GL_ALPHA, GL_ZERO, GL_ZERO, GL_ZERO);
  EXPECT_EQ(fixed_function_pixel(), (Rgba{0x11, 0x22, 0x33, 0}));
  EXPECT_EQ(shader_pixel(), (Rgba{0x80, 0, 0, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureSwizzleTest, BorderColourIsSwizzled) {
  const GLubyte texel[4] = {0, 0, 0, 255};
  load_texel(texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const GLfloat border[4] = {1.f, 0.f, 0.f, 1.f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  set_swizzle(GL_GREEN, GL_RED, GL_BLUE, GL_ALPHA);
  EXPECT_EQ(fixed_function_pixel(5.f, 6.f), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(shader_pixel(5.f, 6.f), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureSwizzleTest, DepthTextureSwizzleFollowsTheDepthMode) {
  const GLfloat depth = 1.f;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);  // (0, 0, 0, d)
  EXPECT_EQ(shader_pixel(), (Rgba{0, 0, 0, 255}));
  set_swizzle(GL_ALPHA, GL_ONE, GL_RED, GL_ZERO);
  EXPECT_EQ(shader_pixel(), (Rgba{255, 255, 0, 0}));
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);  // (d, d, d, 1)
  EXPECT_EQ(shader_pixel(), (Rgba{255, 255, 255, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
