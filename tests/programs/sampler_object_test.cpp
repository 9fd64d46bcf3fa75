// Sampler objects (GL_ARB_sampler_objects) in a GL 2.1 context: names, parameters and their
// initial values (GL 3.3 table 6.23), errors, bindings per unit, and a bound sampler's
// parameters replacing the texture's for fixed function and shaders alike, completeness
// included.
#include <vector>

#include "tests/programs/program_test.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {
namespace {

constexpr Rgba kVertexRed{255, 0, 0, 255}, kTexelGreen{0, 255, 0, 255};

class SamplerObjectTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
  GLuint gen_sampler() {
    GLuint s = 0;
    glGenSamplers(1, &s);
    return s;
  }
  GLint sampler_int(GLuint s, GLenum pname) {
    GLint v = -12345;
    glGetSamplerParameteriv(s, pname, &v);
    return v;
  }
  // Texture 1 on unit 0: a 2x1 image, black then white, NEAREST filters, CLAMP_TO_EDGE;
  // `mipmaps`: with a green 1x1 level too.
  void load_black_white(bool mipmaps = false) {
    const uint8_t texels[8] = {0, 0, 0, 255, 255, 255, 255, 255}, green[4] = {0, 255, 0, 255};
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    if (mipmaps) glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  // The bottom row after the texture is drawn magnified over the window's width (fixed
  // function, GL_REPLACE).
  std::vector<Rgba> textured_row() {
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glColor4ub(255, 0, 0, 255);
    draw_textured_rect(0, 0, float(width()), 1, 0, 0, 1, 1);
    std::vector<Rgba> row;
    for (int x = 0; x < width(); ++x) row.push_back(pixel(x, 0));
    return row;
  }
};

TEST_F(SamplerObjectTest, NamesAndInitialParameters) {
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(std::string(extensions).find("GL_ARB_sampler_objects "), std::string::npos);
  GLuint names[2] = {0, 0};
  glGenSamplers(2, names);
  EXPECT_NE(names[0], 0u);
  EXPECT_NE(names[1], names[0]);
  EXPECT_EQ(glIsSampler(names[0]), GL_TRUE);
  EXPECT_EQ(glIsSampler(0), GL_FALSE);
  EXPECT_EQ(glIsSampler(names[1] + 100), GL_FALSE);
  const GLuint s = names[0];
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_MAG_FILTER), GL_LINEAR);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_WRAP_S), GL_REPEAT);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_WRAP_T), GL_REPEAT);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_WRAP_R), GL_REPEAT);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_COMPARE_MODE), GL_NONE);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_COMPARE_FUNC), GL_LEQUAL);
  GLfloat f[4] = {-1, -1, -1, -1};
  glGetSamplerParameterfv(s, GL_TEXTURE_MIN_LOD, f);
  EXPECT_EQ(f[0], -1000.f);
  glGetSamplerParameterfv(s, GL_TEXTURE_MAX_LOD, f);
  EXPECT_EQ(f[0], 1000.f);
  glGetSamplerParameterfv(s, GL_TEXTURE_LOD_BIAS, f);
  EXPECT_EQ(f[0], 0.f);
  glGetSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, f);
  EXPECT_EQ((std::vector<float>(f, f + 4)), (std::vector<float>{0, 0, 0, 0}));
  GLint binding = -1;
  glGetIntegerv(GL_SAMPLER_BINDING, &binding);
  EXPECT_EQ(binding, 0);

  glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  glSamplerParameterf(s, GL_TEXTURE_LOD_BIAS, 1.5f);
  const GLfloat border[4] = {0.25f, 0.5f, 0.75f, 1.f};
  glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_WRAP_T), GL_MIRRORED_REPEAT);
  glGetSamplerParameterfv(s, GL_TEXTURE_LOD_BIAS, f);
  EXPECT_EQ(f[0], 1.5f);
  glGetSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, f);
  EXPECT_EQ((std::vector<float>(f, f + 4)), (std::vector<float>{0.25f, 0.5f, 0.75f, 1.f}));
  GLint ints[4] = {};
  glGetSamplerParameterIiv(s, GL_TEXTURE_WRAP_T, ints);
  EXPECT_EQ(ints[0], GL_MIRRORED_REPEAT);
  glActiveTexture(GL_TEXTURE5);
  glBindSampler(5, s);
  glGetIntegerv(GL_SAMPLER_BINDING, &binding);
  EXPECT_EQ(binding, GLint(s));
  // Deleting a bound sampler unbinds it; its name is free again.
  glDeleteSamplers(2, names);
  glGetIntegerv(GL_SAMPLER_BINDING, &binding);
  EXPECT_EQ(binding, 0);
  EXPECT_EQ(glIsSampler(s), GL_FALSE);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SamplerObjectTest, ErrorsLeaveTheStateAsItWas) {
  const GLuint s = gen_sampler();
  glGenSamplers(-1, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteSamplers(-1, &s);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBindSampler(8, s);  // GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS is 8
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBindSampler(0, s + 100);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glSamplerParameteri(s + 100, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLint v = -12345;
  glGetSamplerParameteriv(s + 100, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(v, -12345);
  // Texture parameters that are not sampling parameters, and bad values.
  glSamplerParameteri(s, GL_TEXTURE_BASE_LEVEL, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glSamplerParameteri(s, GL_GENERATE_MIPMAP, GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glSamplerParameteri(s, GL_TEXTURE_COMPARE_FUNC, GL_ZERO);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glSamplerParameterf(s, GL_TEXTURE_BORDER_COLOR, 1.f);  // a vector parameter
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetSamplerParameteriv(s, GL_TEXTURE_PRIORITY, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_WRAP_S), GL_REPEAT);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_COMPARE_FUNC), GL_LEQUAL);
  GLint binding = -1;
  glGetIntegerv(GL_SAMPLER_BINDING, &binding);
  EXPECT_EQ(binding, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SamplerObjectTest, BoundSamplerFiltersInsteadOfTheTexture) {
  load_black_white();
  const std::vector<Rgba> nearest = textured_row();
  EXPECT_EQ(nearest.front(), (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(nearest.back(), (Rgba{255, 255, 255, 255}));
  // The texture's own LINEAR filter: the row a sampler with LINEAR must give too.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const std::vector<Rgba> linear = textured_row();
  EXPECT_NE(linear, nearest);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  const GLuint s = gen_sampler();
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindSampler(0, s);
  EXPECT_EQ(textured_row(), linear);
  // The texture's parameters are its own still.
  GLint mag = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &mag);
  EXPECT_EQ(mag, GL_NEAREST);
  // Bound to another unit, it leaves unit 0 alone.
  glBindSampler(0, 0);
  glBindSampler(1, s);
  EXPECT_EQ(textured_row(), nearest);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SamplerObjectTest, SamplerFilterDecidesCompleteness) {
  load_black_white();  // one level: complete only without a mipmap filter
  const GLuint s = gen_sampler();  // NEAREST_MIPMAP_LINEAR
  glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glBindSampler(0, s);
  // Incomplete: the unit is as if disabled, and the fragment keeps its colour.
  for (const Rgba& p : textured_row()) EXPECT_EQ(p, kVertexRed);
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  EXPECT_EQ(textured_row().back(), (Rgba{255, 255, 255, 255}));
  // The reverse: the texture's own filters need mipmaps, the sampler's do not.
  glBindSampler(0, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  EXPECT_EQ(textured_row().back(), kVertexRed);
  glBindSampler(0, s);
  EXPECT_EQ(textured_row().back(), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SamplerObjectTest, ShadersSampleThroughTheBoundSampler) {
  load_black_white(true);
  const GLuint p = link("void main() { gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = ftransform(); }\n",
                        "uniform sampler2D tex;\n"
                        "void main() { gl_FragColor = texture2D(tex, gl_TexCoord[0].xy); }\n");
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "tex"), 0);
  // Two texels to a pixel: level 0's nearest texel (white at s = 0.5), or with the sampler's
  // mipmap filter level 1 (green).
  const GLuint s = gen_sampler();
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  draw_textured_rect(0, 0, 1, 1, 0.f, 0.f, 1.f, 1.f);
  EXPECT_EQ(pixel(0, 0), (Rgba{255, 255, 255, 255}));
  glBindSampler(0, s);
  draw_textured_rect(0, 0, 1, 1, 0.f, 0.f, 1.f, 1.f);
  EXPECT_EQ(pixel(0, 0), kTexelGreen);
  // An incomplete texture reads (0, 0, 0, 1) in a shader.
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  clear_to(0, 1, 0, 1);
  draw_textured_rect(0, 0, 1, 1, 0.f, 0.f, 1.f, 1.f);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 255}));
  glUseProgram(0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SamplerObjectTest, RectangleTextureWithRepeatingSamplerIsIncomplete) {
  const uint8_t green[4] = {0, 255, 0, 255};
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 2);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glColor4ub(255, 0, 0, 255);
  const GLuint s = gen_sampler();
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindSampler(0, s);
  draw_textured_rect(0, 0, 4, 4, 0, 0, 1, 1);
  EXPECT_EQ(pixel(1, 1), kVertexRed);  // wrap modes REPEAT
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  draw_textured_rect(0, 0, 4, 4, 0, 0, 1, 1);
  EXPECT_EQ(pixel(1, 1), kTexelGreen);
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  draw_textured_rect(0, 0, 4, 4, 0, 0, 1, 1);
  EXPECT_EQ(pixel(1, 1), kVertexRed);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SamplerObjectTest, DisplayListsRecordBindingsAndParameters) {
  const GLuint s = gen_sampler();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindSampler(2, s);
  const GLint linear = GL_LINEAR;
  glSamplerParameteriv(s, GL_TEXTURE_MIN_FILTER, &linear);
  glEndList();
  glActiveTexture(GL_TEXTURE2);
  GLint binding = -1;
  glGetIntegerv(GL_SAMPLER_BINDING, &binding);
  EXPECT_EQ(binding, 0);
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  glCallList(list);
  glGetIntegerv(GL_SAMPLER_BINDING, &binding);
  EXPECT_EQ(binding, GLint(s));
  EXPECT_EQ(sampler_int(s, GL_TEXTURE_MIN_FILTER), GL_LINEAR);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
