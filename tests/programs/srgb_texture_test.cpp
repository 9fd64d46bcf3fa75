// sRGB textures (GL 2.1 3.8.15, EXT_texture_sRGB): texels are decoded to linear per texel
// before filtering, through the same sampler for fixed function and shaders; alpha is not
// decoded, and glGetTexImage returns the values as stored. EXT_texture_sRGB_decode's
// SKIP_DECODE_EXT, as a texture parameter or a sampler object's, reads them as stored.
#include <cstring>
#include <string>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

// round(255 * decode(c)) for the values used here: decode(0x80) = 0.21586, decode(0x40) = 0.05127.
constexpr int kLinear80 = 55, kLinear40 = 13;

class SrgbTextureTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    clear_to(0, 0, 0, 0);
    glBindTexture(GL_TEXTURE_2D, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    set_filter(GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void set_filter(GLenum filter) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  }
  // The whole window textured with s, t in [0, 1].
  void textured_window() {
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(-1, -1);
    glTexCoord2f(1, 0);
    glVertex2f(1, -1);
    glTexCoord2f(1, 1);
    glVertex2f(1, 1);
    glTexCoord2f(0, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
  GLint level_int(GLenum pname) {
    GLint v = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pname, &v);
    return v;
  }
};

TEST_F(SrgbTextureTest, FixedFunctionDecodesRgbButNotAlpha) {
  const GLubyte texel[4] = {0x80, 0x40, 0xFF, 0x80};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glEnable(GL_TEXTURE_2D);
  textured_window();
  EXPECT_EQ(pixel(5, 5), (Rgba{kLinear80, kLinear40, 255, 0x80}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_int(GL_TEXTURE_INTERNAL_FORMAT), GL_SRGB8_ALPHA8);
  EXPECT_EQ(level_int(GL_TEXTURE_RED_SIZE), 8);
  EXPECT_EQ(level_int(GL_TEXTURE_ALPHA_SIZE), 8);
  GLubyte stored[4] = {0, 0, 0, 0};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, stored);
  EXPECT_EQ(std::memcmp(stored, texel, 4), 0);
}

TEST_F(SrgbTextureTest, EveryFormatDecodes) {
  const GLubyte rgb[3] = {0x80, 0x80, 0x80}, la[2] = {0x80, 0x40};
  struct Case {
    GLenum internal, format;
    const GLubyte* data;
    Rgba expected;
  } cases[] = {
      {GL_SRGB, GL_RGB, rgb, {kLinear80, kLinear80, kLinear80, 255}},
      {GL_SRGB8, GL_RGB, rgb, {kLinear80, kLinear80, kLinear80, 255}},
      {GL_SRGB_ALPHA, GL_LUMINANCE_ALPHA, la, {kLinear80, kLinear80, kLinear80, 0x40}},
      {GL_SLUMINANCE, GL_LUMINANCE, la, {kLinear80, kLinear80, kLinear80, 255}},
      {GL_SLUMINANCE8, GL_LUMINANCE, la, {kLinear80, kLinear80, kLinear80, 255}},
      {GL_SLUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, la, {kLinear80, kLinear80, kLinear80, 0x40}},
      {GL_SLUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, la, {kLinear80, kLinear80, kLinear80, 0x40}},
      {GL_COMPRESSED_SRGB, GL_RGB, rgb, {kLinear80, kLinear80, kLinear80, 255}},
      {GL_COMPRESSED_SLUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, la, {kLinear80, kLinear80, kLinear80, 0x40}},
  };
  glEnable(GL_TEXTURE_2D);
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(c.internal), 1, 1, 0, c.format, GL_UNSIGNED_BYTE, c.data);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << std::hex << c.internal;
    textured_window();
    EXPECT_EQ(pixel(5, 5), c.expected) << std::hex << c.internal;
  }
  EXPECT_EQ(level_int(GL_TEXTURE_INTERNAL_FORMAT), GL_SLUMINANCE_ALPHA);  // the generic compressed one's base
  EXPECT_EQ(level_int(GL_TEXTURE_LUMINANCE_SIZE), 8);
}

// Decoding comes before filtering: halfway between sRGB 0x00 and 0x80 is linear
// 0.2159 / 2 = 0.1079 (28), not the decoded 0x40 (13) that filtering the encoded values gives.
TEST_F(SrgbTextureTest, LinearFilteringAveragesDecodedTexels) {
  const GLubyte texels[2 * 3] = {0x00, 0x00, 0x00, 0x80, 0x80, 0x80};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8, 2, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  set_filter(GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);  // s = 0.5 (the two texels' boundary) everywhere
  glTexCoord2f(0.5f, 0.5f);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  EXPECT_EQ(pixel(7, 7), (Rgba{28, 28, 28, 255}));
  // The same with REPEAT wrapping and with CLAMP_TO_EDGE (the sampler's fast paths).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  clear_to(0, 0, 0, 0);
  glBegin(GL_QUADS);
  glTexCoord2f(0.5f, 0.5f);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  EXPECT_EQ(pixel(7, 7), (Rgba{28, 28, 28, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SrgbTextureTest, ShadersSampleThroughTheSameDecoding) {
  const GLubyte texels[2 * 4] = {0x00, 0x00, 0x00, 0x00, 0x80, 0x40, 0xC0, 0x80};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB_ALPHA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  const GLuint p = link("void main() { gl_Position = gl_Vertex; }\n",
                        "uniform sampler2D tex; uniform float s;\n"
                        "void main() { gl_FragColor = texture2D(tex, vec2(s, 0.5)); }\n");
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  glUniform1f(glGetUniformLocation(p, "s"), 0.75f);  // the second texel's centre
  textured_window();
  EXPECT_EQ(pixel(5, 5), (Rgba{kLinear80, kLinear40, 134, 0x80}));  // decode(0xC0) = 0.5271
  set_filter(GL_LINEAR);
  glUniform1f(glGetUniformLocation(p, "s"), 0.5f);
  textured_window();
  EXPECT_EQ(pixel(5, 5), (Rgba{28, 7, 67, 0x40}));  // halves of the linear values; alpha filtered as stored
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SrgbTextureTest, SkipDecodeReadsTexelsAsStored) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(extensions.find("GL_EXT_texture_sRGB_decode "), std::string::npos);
  const GLubyte texel[4] = {0x80, 0x40, 0xFF, 0x80};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  GLint decode = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SRGB_DECODE_EXT, &decode);
  EXPECT_EQ(decode, GL_DECODE_EXT);
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SRGB_DECODE_EXT, GL_SKIP_DECODE_EXT);
  textured_window();
  EXPECT_EQ(pixel(5, 5), (Rgba{0x80, 0x40, 0xFF, 0x80}));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SRGB_DECODE_EXT, GL_LINEAR);  // not a decode mode
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SRGB_DECODE_EXT, &decode);
  EXPECT_EQ(decode, GL_SKIP_DECODE_EXT);
  // A sampler object's parameter replaces the texture's, either way.
  GLuint sampler = 0;
  glGenSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindSampler(0, sampler);
  textured_window();
  EXPECT_EQ(pixel(5, 5), (Rgba{kLinear80, kLinear40, 255, 0x80}));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SRGB_DECODE_EXT, GL_DECODE_EXT);
  glSamplerParameteri(sampler, GL_TEXTURE_SRGB_DECODE_EXT, GL_SKIP_DECODE_EXT);
  textured_window();
  EXPECT_EQ(pixel(5, 5), (Rgba{0x80, 0x40, 0xFF, 0x80}));
  glBindSampler(0, 0);
  textured_window();
  EXPECT_EQ(pixel(5, 5), (Rgba{kLinear80, kLinear40, 255, 0x80}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
