// Desktop GLSL links several shaders of one stage as one (GL 2.0 2.15.2): a function defined
// in one and called from another, main() in exactly one.
#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

using SeveralShadersPerStageTest = ProgramTest;

TEST_F(SeveralShadersPerStageTest, FunctionsComeFromOtherShadersOfTheStage) {
  const GLuint p = glCreateProgram();
  glAttachShader(p, compile(GL_VERTEX_SHADER, "vec4 position(); void main() { gl_Position = position(); }\n"));
  glAttachShader(p, compile(GL_VERTEX_SHADER, "vec4 position() { return gl_Vertex; }\n"));
  glAttachShader(p, compile(GL_FRAGMENT_SHADER, "vec4 colour(float g); void main() { gl_FragColor = colour(0.4); }\n"));
  glAttachShader(p, compile(GL_FRAGMENT_SHADER, "uniform float r; vec4 colour(float g) { return vec4(r, g, 0.0, 1.0); }\n"));
  glLinkProgram(p);
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  glUniform1f(glGetUniformLocation(p, "r"), 0.2f);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(3, -1);
  glVertex2f(-1, 3);
  glEnd();
  EXPECT_EQ(pixel(5, 5), (Rgba{51, 102, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SeveralShadersPerStageTest, TwoMainsOrNoneFailToLink) {
  const GLuint two = glCreateProgram();
  glAttachShader(two, compile(GL_FRAGMENT_SHADER, "void main() { gl_FragColor = vec4(1.0); }\n"));
  glAttachShader(two, compile(GL_FRAGMENT_SHADER, "void main() { gl_FragColor = vec4(0.0); }\n"));
  glLinkProgram(two);
  EXPECT_EQ(program_int(two, GL_LINK_STATUS), GL_FALSE);
  const GLuint none = glCreateProgram();
  glAttachShader(none, compile(GL_VERTEX_SHADER, "vec4 f() { return gl_Vertex; }\n"));
  glLinkProgram(none);
  EXPECT_EQ(program_int(none, GL_LINK_STATUS), GL_FALSE);
  EXPECT_FALSE(program_log(none).empty());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
