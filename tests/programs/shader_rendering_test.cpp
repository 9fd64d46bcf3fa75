// Rendering with a vertex and a fragment shader: uniforms, varyings, textures, discard,
// gl_FragCoord, generic attribute arrays in buffer objects, built-in uniforms and the
// per-fragment operations after the shader. Expected pixels are exact.
#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

const char* kPassVs = "void main() { gl_Position = gl_Vertex; }\n";

class ShaderRenderingTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    clear_to(0, 0, 0, 0);
  }
  GLuint use(const char* vs, const char* fs) {
    const GLuint p = link(vs, fs);
    EXPECT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
    glUseProgram(p);
    return p;
  }
  // The whole viewport as two triangles at depth z.
  void full_screen(float z = 0.f) {
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, z);
    glVertex3f(1, -1, z);
    glVertex3f(1, 1, z);
    glVertex3f(-1, 1, z);
    glEnd();
  }
};

TEST_F(ShaderRenderingTest, UniformColourFillsTheTriangles) {
  const GLuint p = use(kPassVs, "uniform vec4 color; void main() { gl_FragColor = color; }\n");
  glUniform4f(glGetUniformLocation(p, "color"), 0.2f, 0.4f, 0.6f, 0.8f);
  full_screen();
  EXPECT_EQ(count_pixels({51, 102, 153, 204}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  expect_osmesa_buffer_matches_readback();
}

TEST_F(ShaderRenderingTest, DrawsSnapshotTheUniforms) {
  const GLuint p = use(kPassVs, "uniform vec4 color; void main() { gl_FragColor = color; }\n");
  const GLint c = glGetUniformLocation(p, "color");
  glUniform4f(c, 1, 0, 0, 1);
  glBegin(GL_QUADS);  // left half
  glVertex2f(-1, -1);
  glVertex2f(0, -1);
  glVertex2f(0, 1);
  glVertex2f(-1, 1);
  glEnd();
  glUniform4f(c, 0, 0, 1, 1);  // before the queued left half is rasterized
  glBegin(GL_QUADS);
  glVertex2f(0, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(3, 10), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(28, 10), {0, 0, 255, 255}));
}

TEST_F(ShaderRenderingTest, VaryingGradientIsExactAtPixelCentres) {
  use("varying float v; void main() { v = gl_Vertex.x * 0.5 + 0.5; gl_Position = gl_Vertex; }\n",
      "varying float v; void main() { gl_FragColor = vec4(v, 1.0 - v, 0.0, 1.0); }\n");
  full_screen();
  for (int x = 0; x < width(); ++x) {
    const double v = (x + 0.5) / width();
    EXPECT_TRUE(near_rgba(pixel(x, 7), {int(std::lround(v * 255)), int(std::lround((1 - v) * 255)), 0, 255})) << x;
  }
}

TEST_F(ShaderRenderingTest, VaryingsArePerspectiveCorrect) {
  // A quad leaning back: w grows from 1 at the bottom to 3 at the top. The varying t is 0 at
  // the bottom and 1 at the top; perspective-correct, the screen midpoint sees t = 1/4.
  use("varying float t;\n"
      "void main() { t = gl_Vertex.y * 0.5 + 0.5; float w = 2.0 + gl_Vertex.y;\n"
      "  gl_Position = vec4(gl_Vertex.x * w, gl_Vertex.y * w, 0.0, w); }\n",
      "varying float t; void main() { gl_FragColor = vec4(t, 0.0, 0.0, 1.0); }\n");
  full_screen();
  // Both triangles have their bottom edge at w = 1 (t = 0) and their top at w = 3 (t = 1): with
  // s the screen-space fraction of the height, t = (s / 3) / ((1 - s) + s / 3) = s / (3 - 2s).
  for (int row : {0, 8, 16, 24, 31}) {
    const double s = (row + 0.5) / 32.0;
    const double t = s / (3.0 - 2.0 * s);
    EXPECT_TRUE(near_rgba(pixel(16, row), {int(std::lround(t * 255)), 0, 0, 255}, 1)) << row;
  }
}

TEST_F(ShaderRenderingTest, Texture2DLookupReadsTheBoundUnit) {
  const GLubyte texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, 5);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glActiveTexture(GL_TEXTURE0);
  // Not enabled with glEnable: a sampler reads its unit's texture of the sampler's target.
  const GLuint p = use("varying vec2 uv; void main() { uv = gl_Vertex.xy * 0.5 + 0.5; gl_Position = gl_Vertex; }\n",
                       "uniform sampler2D tex; varying vec2 uv; void main() { gl_FragColor = texture2D(tex, uv); }\n");
  glUniform1i(glGetUniformLocation(p, "tex"), 1);
  full_screen();
  EXPECT_TRUE(near_rgba(pixel(4, 4), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(27, 4), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(4, 27), {0, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(27, 27), {255, 255, 255, 255}));
  glUniform1i(glGetUniformLocation(p, "tex"), 0);  // unit 0 has no texture: (0, 0, 0, 1)
  full_screen();
  EXPECT_TRUE(near_rgba(pixel(27, 27), {0, 0, 0, 255}));
}

TEST_F(ShaderRenderingTest, LuminanceTextureReadsAsLLL1) {
  const GLubyte lum[4] = {51, 51, 51, 51};
  glBindTexture(GL_TEXTURE_2D, 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  use(kPassVs, "uniform sampler2D tex; void main() { gl_FragColor = texture2D(tex, vec2(0.5)); }\n");
  full_screen();
  EXPECT_TRUE(near_rgba(pixel(10, 10), {51, 51, 51, 255}));
}

// GL 2.0 table 3.20 for every base format, nearest and linear, over whole blocks and the edges'
// partial ones: what each format gives a shader in every pixel.
TEST_F(ShaderRenderingTest, EveryBaseFormatReadsAsTable320InEveryPixel) {
  struct Case {
    GLenum format;
    GLubyte texel[4];
    Rgba expected;
  };
  const Case cases[] = {{GL_ALPHA, {100}, {0, 0, 0, 100}},
                        {GL_LUMINANCE, {51}, {51, 51, 51, 255}},
                        {GL_LUMINANCE_ALPHA, {51, 100}, {51, 51, 51, 100}},
                        {GL_INTENSITY, {77}, {77, 77, 77, 77}},
                        {GL_RGB, {10, 20, 30}, {10, 20, 30, 255}},
                        {GL_RGBA, {10, 20, 30, 40}, {10, 20, 30, 40}}};
  glBindTexture(GL_TEXTURE_2D, 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  use("varying vec2 uv; void main() { uv = gl_Vertex.xy * 0.7 + 0.5; gl_Position = gl_Vertex; }\n",
      "uniform sampler2D tex; varying vec2 uv; void main() { gl_FragColor = texture2D(tex, uv); }\n");
  for (const Case& c : cases) {
    const int channels = c.format == GL_RGBA ? 4 : c.format == GL_RGB ? 3 : c.format == GL_LUMINANCE_ALPHA ? 2 : 1;
    GLubyte texels[4 * 4];
    for (int i = 0; i < 4; ++i) std::copy(c.texel, c.texel + channels, texels + i * channels);
    const GLenum external = c.format == GL_INTENSITY ? GL_LUMINANCE : c.format;
    glTexImage2D(GL_TEXTURE_2D, 0, c.format, 2, 2, 0, external, GL_UNSIGNED_BYTE, texels);
    for (GLenum filter : {GL_NEAREST, GL_LINEAR}) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
      glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
      glClear(GL_COLOR_BUFFER_BIT);
      full_screen();
      EXPECT_EQ(count_pixels(c.expected), width() * height()) << "format 0x" << std::hex << c.format << " filter 0x" << filter;
    }
  }
}

// Without mipmaps a level of detail chooses nothing: a vertex shader's lookups (at level 0, as
// texture2DLod's) read what a fragment shader's read, through the same 8-bit filter, to the bit.
TEST_F(ShaderRenderingTest, VertexShaderLookupsReadAsFragmentShaderLookups) {
  GLubyte texels[4 * 4 * 4];
  for (int i = 0; i < 64; ++i) texels[i] = GLubyte((i * 97 + 13) % 256);
  glBindTexture(GL_TEXTURE_2D, 3);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // A point's varyings are the same in all its fragments: the fragment shader's coordinates do
  // not vary, so it magnifies (level 0) too.
  use("uniform sampler2D tex; varying vec2 uv; varying vec4 c;\n"
      "void main() { uv = gl_MultiTexCoord0.xy; c = texture2D(tex, uv); gl_Position = gl_Vertex; }\n",
      "uniform sampler2D tex; varying vec2 uv; varying vec4 c;\n"
      "void main() { gl_FragColor = vec4(min(abs(c - texture2D(tex, uv)) * 65536.0, 1.0).rgb, 1.0); }\n");
  glClearColor(0.f, 0.f, 1.f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_POINTS);
  for (int i = 0; i < 64; ++i) {
    const int x = i % 8 * 3, y = i / 8 * 3;
    glTexCoord2f(0.013f + 0.0371f * float(i), 0.9f - 0.0293f * float(i));
    glVertex2f((float(x) + 0.5f) / float(width()) * 2.f - 1.f, (float(y) + 0.5f) / float(height()) * 2.f - 1.f);
  }
  glEnd();
  EXPECT_EQ(count_pixels({0, 0, 0, 255}), 64);
}

TEST_F(ShaderRenderingTest, DiscardKeepsTheFramebuffer) {
  use(kPassVs, "void main() { if (gl_FragCoord.x < 10.0) discard; gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }\n");
  full_screen();
  EXPECT_TRUE(near_rgba(pixel(9, 5), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(10, 5), {0, 255, 0, 255}));
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), (width() - 10) * height());
}

TEST_F(ShaderRenderingTest, FragCoordIsThePixelCentreAndWindowDepth) {
  glDepthRange(0.25, 0.75);
  use(kPassVs, "void main() { gl_FragColor = vec4(gl_FragCoord.x / 32.0, gl_FragCoord.y / 32.0, gl_FragCoord.z, gl_FragCoord.w); }\n");
  full_screen(0.5f);  // window z = 0.25 + 0.5 * (0.5 + 1) / 2 = 0.625
  for (int x : {0, 13, 31})
    for (int y : {0, 20, 31})
      EXPECT_TRUE(near_rgba(pixel(x, y), {int(std::lround((x + 0.5) / 32 * 255)), int(std::lround((y + 0.5) / 32 * 255)),
                                          int(std::lround(0.625 * 255)), 255}))
          << x << "," << y;
}

TEST_F(ShaderRenderingTest, GenericAttributeArraysFromABufferObject) {
  const GLuint p = use("attribute vec2 pos; attribute vec4 col; varying vec4 c;\n"
                       "void main() { c = col; gl_Position = vec4(pos, 0.0, 1.0); }\n",
                       "varying vec4 c; void main() { gl_FragColor = c; }\n");
  struct Vertex {
    GLfloat pos[2];
    GLubyte col[4];
  };
  const Vertex vertices[4] = {{{-1, -1}, {255, 128, 0, 255}},
                              {{1, -1}, {255, 128, 0, 255}},
                              {{1, 1}, {255, 128, 0, 255}},
                              {{-1, 1}, {255, 128, 0, 255}}};
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices, GL_STATIC_DRAW);
  // pos at 0: generic attribute 0 is the vertex position a draw needs.
  glBindAttribLocation(p, 0, "pos");
  glBindAttribLocation(p, 3, "col");
  glLinkProgram(p);
  ASSERT_EQ(glGetAttribLocation(p, "pos"), 0);
  ASSERT_EQ(glGetAttribLocation(p, "col"), 3);
  glUseProgram(p);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
  glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, col)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(3);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(count_pixels({255, 128, 0, 255}), width() * height());
  const GLubyte indices[3] = {0, 1, 2};
  clear_to(0, 0, 0, 0);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, indices);
  EXPECT_TRUE(near_rgba(pixel(30, 1), {255, 128, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(1, 30), {0, 0, 0, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Generic attribute 0 from client memory, with a vertex shader that reads no built-in
// attribute (the vertices carry only their element, edge flag and attribute 0 then).
TEST_F(ShaderRenderingTest, GenericAttributeZeroFromAClientArray) {
  link_in_use("attribute vec2 pos; attribute vec4 col; varying vec4 c;\n"
              "void main() { c = col; gl_Position = vec4(pos, 0.0, 1.0); }\n",
              "varying vec4 c; void main() { gl_FragColor = c; }\n", {{0, "pos"}, {2, "col"}});
  const GLfloat pos[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  const GLfloat col[16] = {0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 0, col);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(2);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), width() * height());
  clear_to(0, 0, 0, 0);
  const GLushort indices[3] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices);
  EXPECT_EQ(pixel(30, 1), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(1, 30), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ShaderRenderingTest, ImmediateModeGenericAttributesAndAttributeZero) {
  const GLuint p = use("attribute vec4 shade; varying vec4 c; void main() { c = shade; gl_Position = gl_Vertex; }\n",
                       "varying vec4 c; void main() { gl_FragColor = c; }\n");
  const GLint shade = glGetAttribLocation(p, "shade");
  ASSERT_GT(shade, 0);  // gl_Vertex holds location 0
  glBegin(GL_TRIANGLES);
  glVertexAttrib4f(GLuint(shade), 0, 0, 1, 1);
  glVertexAttrib2f(0, -1, -1);  // attribute 0 provokes the vertex, as glVertex does
  glVertexAttrib2f(0, 3, -1);
  glVertexAttrib2f(0, -1, 3);
  glEnd();
  EXPECT_EQ(count_pixels({0, 0, 255, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ShaderRenderingTest, BuiltinMatricesAndFtransform) {
  pixel_projection();
  glTranslatef(4, 0, 0);
  use("void main() { gl_Position = ftransform(); }\n", "void main() { gl_FragColor = vec4(1.0); }\n");
  glRectf(4, 8, 12, 16);  // x 8..16 after the translation
  EXPECT_TRUE(near_rgba(pixel(8, 8), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(15, 15), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(7, 8), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(16, 8), {0, 0, 0, 0}));
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 64);
  use("void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n",
      "void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }\n");
  glRectf(20, 20, 24, 22);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 8);
  EXPECT_TRUE(near_rgba(pixel(24, 20), {255, 0, 0, 255}));
  use("void main() { gl_Position = gl_ProjectionMatrix * (gl_ModelViewMatrix * gl_Vertex); }\n",
      "void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }\n");
  glRectf(0, 0, 2, 2);
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), 4);
  EXPECT_TRUE(near_rgba(pixel(4, 0), {0, 255, 0, 255}));
}

// gl_FragCoord.w is 1/w of the clip position, also where every vertex has the same w and the
// program has no varyings (no perspective division to share it with): piglit's fragcoord_w.
TEST_F(ShaderRenderingTest, FragCoordWIsOneOverClipWWithoutVaryings) {
  use("void main() { gl_Position = vec4(gl_Vertex.xy * 2.0, 0.0, 2.0); }\n",
      "void main() { gl_FragColor = vec4(1.0, gl_FragCoord.w, 1.0, 0.0); }\n");
  full_screen();
  EXPECT_EQ(pixel(3, 3), (std::array<int, 4>{255, 128, 255, 0}));
  EXPECT_EQ(pixel(30, 30), (std::array<int, 4>{255, 128, 255, 0}));
}

// GL 2.0 2.14.7: the colours a vertex shader writes are clamped to [0, 1] before interpolation
// (piglit's glsl-clamp-vertex-color): unclamped, (-2 + 2) / 2 would not be 0 but the sum below.
TEST_F(ShaderRenderingTest, VertexShaderColoursAreClamped) {
  use("void main() { gl_Position = gl_Vertex; gl_FrontColor = vec4(-2.0, -1.0, 0.5, 3.0);"
      " gl_FrontSecondaryColor = vec4(2.0, 0.5, 1.5, -0.5); }\n",
      "void main() { gl_FragColor = (gl_Color + gl_SecondaryColor) * 0.5; }\n");
  full_screen();
  EXPECT_EQ(pixel(5, 5), (std::array<int, 4>{128, 64, 191, 128}));
}

TEST_F(ShaderRenderingTest, ColourAttributeAndVarying) {
  use("void main() { gl_FrontColor = gl_Color; gl_Position = gl_Vertex; }\n",
      "void main() { gl_FragColor = gl_Color; }\n");
  glColor4ub(10, 20, 30, 40);
  full_screen();
  EXPECT_TRUE(near_rgba(pixel(5, 5), {10, 20, 30, 40}));
}

TEST_F(ShaderRenderingTest, DepthTestAndBlendingAfterTheShader) {
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  const GLuint p = use(kPassVs, "uniform vec4 color; void main() { gl_FragColor = color; }\n");
  const GLint c = glGetUniformLocation(p, "color");
  glUniform4f(c, 1, 0, 0, 1);
  full_screen(0.0f);
  glUniform4f(c, 0, 1, 0, 1);
  full_screen(0.5f);  // behind: fails LESS
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), width() * height());
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glUniform4f(c, 0, 0, 1, 0.6f);
  full_screen();
  // 0.6 * (0, 0, 1, 0.6) + 0.4 * (1, 0, 0, 1): the source is rounded to 8 bits first (153).
  EXPECT_TRUE(near_rgba(pixel(9, 9), {102, 0, 153, 194}, 1));
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
  glUniform4f(c, 0, 1, 1, 1);
  full_screen();
  EXPECT_TRUE(near_rgba(pixel(9, 9), {0, 0, 153, 194}, 1));
}

TEST_F(ShaderRenderingTest, StencilAndScissorApplyToShadedFragments) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 16, 32);
  use(kPassVs, "void main() { gl_FragColor = vec4(1.0); }\n");
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  full_screen();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16 * 32);
  glDisable(GL_SCISSOR_TEST);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  use(kPassVs, "void main() { gl_FragColor = vec4(0.0, 0.0, 1.0, 1.0); }\n");
  full_screen();
  EXPECT_EQ(count_pixels({0, 0, 255, 255}), 16 * 32);
  EXPECT_TRUE(near_rgba(pixel(15, 3), {255, 255, 255, 255}));
}

TEST_F(ShaderRenderingTest, PointSizeFromTheShaderAndPointCoord) {
  glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
  use("void main() { gl_PointSize = 4.0; gl_Position = gl_Vertex; }\n",
      "#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n");
  glBegin(GL_POINTS);
  glVertex2f(0, 0);  // centre (16, 16): pixels 14..17
  glEnd();
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height() - 16);
  // gl_PointCoord's origin is the upper left: s = 0.5 + (x + 0.5 - 16) / 4, t = 0.5 - (y + 0.5 - 16) / 4.
  EXPECT_TRUE(near_rgba(pixel(14, 17), {int(std::lround(0.125 * 255)), int(std::lround(0.125 * 255)), 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(17, 14), {int(std::lround(0.875 * 255)), int(std::lround(0.875 * 255)), 0, 255}));
  glDisable(GL_VERTEX_PROGRAM_POINT_SIZE);  // glPointSize (1) again
  clear_to(0, 0, 0, 0);
  glBegin(GL_POINTS);
  glVertex2f(0, 0);
  glEnd();
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height() - 1);
}

TEST_F(ShaderRenderingTest, FrontFacing) {
  use(kPassVs, "void main() { gl_FragColor = gl_FrontFacing ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0); }\n");
  glBegin(GL_TRIANGLES);  // counter-clockwise: front
  glVertex2f(-1, -1);
  glVertex2f(0, -1);
  glVertex2f(-1, 1);
  glEnd();
  glBegin(GL_TRIANGLES);  // clockwise: back
  glVertex2f(1, -1);
  glVertex2f(0.2f, -1);
  glVertex2f(1, 1);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(2, 2), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(29, 2), {255, 0, 0, 255}));
}

TEST_F(ShaderRenderingTest, UseProgramZeroReturnsToFixedFunction) {
  use(kPassVs, "void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }\n");
  glUseProgram(0);
  glColor3f(0, 0, 1);
  full_screen();
  EXPECT_EQ(count_pixels({0, 0, 255, 255}), width() * height());
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// The derived lighting built-ins take their alpha from the material: sceneColor the diffuse
// alpha, each light product its own material colour's alpha (as Mesa; piglit
// glsl-1.10-built-in-uniform-state).
TEST_F(ShaderRenderingTest, LightProductsTakeTheMaterialsAlpha) {
  const GLfloat material_ambient[] = {0.5f, 0.5f, 0.5f, 0.2f}, material_diffuse[] = {1.0f, 0.5f, 0.25f, 0.6f};
  const GLfloat material_emission[] = {0.25f, 0.0f, 0.0f, 0.4f}, model_ambient[] = {0.5f, 1.0f, 0.0f, 1.0f};
  const GLfloat light_diffuse[] = {0.5f, 1.0f, 1.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT, material_ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, material_diffuse);
  glMaterialfv(GL_FRONT, GL_EMISSION, material_emission);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  const GLuint scene = use(kPassVs, "void main() { gl_FragColor = gl_FrontLightModelProduct.sceneColor; }\n");
  full_screen();
  // (0.25 + 0.25, 0.5, 0), alpha 0.6.
  EXPECT_EQ(pixel(2, 2), (Rgba{128, 128, 0, 153}));
  glDeleteProgram(scene);
  const GLuint product = use(kPassVs, "void main() { gl_FragColor = gl_FrontLightProduct[0].diffuse; }\n");
  full_screen();
  EXPECT_EQ(pixel(2, 2), (Rgba{128, 128, 64, 153}));
  glDeleteProgram(product);
}

}  // namespace
}  // namespace pineda::test
