// Depth textures sampled by a fragment shader through sampler2D: the depth goes where
// DEPTH_TEXTURE_MODE puts it (piglit depth-tex-modes-glsl).
#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class DepthTextureSamplingTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    clear_to(0, 0, 0, 0);
  }
};

TEST_F(DepthTextureSamplingTest, GenericAttributeTexCoordsAndDrawElements) {
  const GLfloat depths[2][2] = {{0.f, 1.f}, {1.f, 0.f}};
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  const GLuint vs = compile(GL_VERTEX_SHADER,
                            "attribute vec2 textureCoords; varying vec2 texCoords;\n"
                            "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; texCoords = textureCoords; }\n");
  const GLuint fs = compile(GL_FRAGMENT_SHADER,
                            "uniform sampler2D depthTex2d; varying vec2 texCoords;\n"
                            "void main() { gl_FragColor = vec4(vec3(1.0, 0.0, 1.0) * texture2D(depthTex2d, texCoords).xyz, 1.0); }\n");
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glBindAttribLocation(p, 1, "textureCoords");
  glLinkProgram(p);
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  const GLfloat vertices[12] = {1, -1, 0, 1, 1, 0, -1, -1, 0, -1, 1, 0};
  const GLfloat texcoords[8] = {1, 0, 1, 1, 0, 0, 0, 1};
  const GLuint elements[4] = {0, 1, 2, 3};
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(GLfloat), vertices);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(GLfloat), texcoords);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glDrawElements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_INT, elements);
  EXPECT_EQ(pixel(4, 4), (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(pixel(28, 4), (Rgba{255, 0, 255, 255}));
  EXPECT_EQ(pixel(4, 28), (Rgba{255, 0, 255, 255}));
  EXPECT_EQ(pixel(28, 28), (Rgba{0, 0, 0, 255}));
  // ALPHA puts the depth in alpha only: the colour is 0 everywhere.
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
  glDrawElements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_INT, elements);
  EXPECT_EQ(pixel(28, 4), (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
