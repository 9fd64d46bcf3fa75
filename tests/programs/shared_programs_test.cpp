// Shader and program objects belong to the share group (GL 2.1 Appendix D): a context made
// with a share list sees the other's shaders and programs, one name space serves both, and a
// program deleted while another context uses it lives until that context stops using it.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <memory>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr const char* kVertex = "void main() { gl_Position = gl_Vertex; }";
constexpr const char* kRed = "void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }";

GLuint compile(GLenum type, const char* source) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  return s;
}

GLuint link_red_program() {
  const GLuint p = glCreateProgram();
  glAttachShader(p, compile(GL_VERTEX_SHADER, kVertex));
  glAttachShader(p, compile(GL_FRAGMENT_SHADER, kRed));
  glLinkProgram(p);
  return p;
}

void draw_full_quad() {
  glBegin(GL_QUADS);
  glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);
  glEnd();
}

GLint program_int(GLuint p, GLenum pname) {
  GLint v = -1;
  glGetProgramiv(p, pname, &v);
  return v;
}

class SharedProgramsTest : public ::testing::TestWithParam<bool> {  // param: force EGL
 protected:
  SurfaceSpec spec(const GlSurface* share = nullptr) const {
    return {.width = 16, .height = 16, .force_egl = GetParam(), .share = share};
  }
};

TEST_P(SharedProgramsTest, AProgramLinkedInOneContextDrawsInTheOther) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  const GLuint program = link_red_program();
  ASSERT_EQ(program_int(program, GL_LINK_STATUS), GL_TRUE);
  GLuint shaders[2] = {0, 0};
  glGetAttachedShaders(program, 2, nullptr, shaders);

  GlSurface second(spec(&first));  // now current
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(glIsProgram(program), GL_TRUE);
  EXPECT_EQ(glIsShader(shaders[0]), GL_TRUE);
  EXPECT_EQ(glIsShader(shaders[1]), GL_TRUE);
  glUseProgram(program);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_full_quad();
  EXPECT_EQ(read_rgba(8, 8), (Rgba{255, 0, 0, 255}));
  // One name space: a shader made here does not reuse a name the first context gave out.
  const GLuint shader = glCreateShader(GL_FRAGMENT_SHADER);
  EXPECT_NE(shader, program);
  EXPECT_NE(shader, shaders[0]);
  EXPECT_NE(shader, shaders[1]);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(SharedProgramsTest, ADeletedProgramLivesWhileAnotherContextUsesIt) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  const GLuint program = link_red_program();
  GlSurface second(spec(&first));
  ASSERT_TRUE(second.ok()) << second.error();
  glUseProgram(program);

  ASSERT_TRUE(first.make_current());
  glDeleteProgram(program);
  EXPECT_EQ(glIsProgram(program), GL_TRUE);  // still current in the second context
  EXPECT_EQ(program_int(program, GL_DELETE_STATUS), GL_TRUE);

  ASSERT_TRUE(second.make_current());
  draw_full_quad();
  EXPECT_EQ(read_rgba(3, 3), (Rgba{255, 0, 0, 255}));
  glUseProgram(0);
  EXPECT_EQ(glIsProgram(program), GL_FALSE);
  ASSERT_TRUE(first.make_current());
  EXPECT_EQ(glIsProgram(program), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(SharedProgramsTest, DestroyingTheContextThatUsesADeletedProgramFreesIt) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  const GLuint program = link_red_program();
  auto second = std::make_unique<GlSurface>(spec(&first));
  ASSERT_TRUE(second->ok()) << second->error();
  glUseProgram(program);
  ASSERT_TRUE(first.make_current());
  glDeleteProgram(program);
  EXPECT_EQ(glIsProgram(program), GL_TRUE);
  second.reset();
  ASSERT_TRUE(first.make_current());
  EXPECT_EQ(glIsProgram(program), GL_FALSE);
}

TEST_P(SharedProgramsTest, ContextsWithoutAShareListHaveTheirOwnPrograms) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  const GLuint program = link_red_program();
  GlSurface second(spec());
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(glIsProgram(program), GL_FALSE);
}

INSTANTIATE_TEST_SUITE_P(OsmesaOrEgl, SharedProgramsTest, ::testing::Bool());

}  // namespace
}  // namespace pineda::test
