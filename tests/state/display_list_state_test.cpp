// Display lists: names, compilation state, errors, and what is compiled or executed at once.
#define GL_GLEXT_PROTOTYPES
#include <cmath>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class DisplayListStateTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

TEST_F(DisplayListStateTest, InitialQueries) {
  EXPECT_EQ(get_int(GL_LIST_BASE), 0);
  EXPECT_EQ(get_int(GL_LIST_INDEX), 0);
  EXPECT_EQ(get_int(GL_LIST_MODE), 0);
  EXPECT_GE(get_int(GL_MAX_LIST_NESTING), 64);
}

TEST_F(DisplayListStateTest, CompilationStateIsQueryable) {
  glListBase(7);
  EXPECT_EQ(get_int(GL_LIST_BASE), 7);
  glNewList(5, GL_COMPILE);
  EXPECT_EQ(get_int(GL_LIST_INDEX), 5);
  EXPECT_EQ(get_int(GL_LIST_MODE), GL_COMPILE);
  glEndList();
  EXPECT_EQ(get_int(GL_LIST_INDEX), 0);
  glNewList(6, GL_COMPILE_AND_EXECUTE);
  EXPECT_EQ(get_int(GL_LIST_MODE), GL_COMPILE_AND_EXECUTE);
  glEndList();
}

TEST_F(DisplayListStateTest, GenIsDelete) {
  const GLuint first = glGenLists(3);
  ASSERT_NE(first, 0u);
  EXPECT_EQ(glIsList(first), GL_TRUE);
  EXPECT_EQ(glIsList(first + 2), GL_TRUE);
  EXPECT_EQ(glIsList(first + 3), GL_FALSE);
  EXPECT_EQ(glIsList(0), GL_FALSE);
  const GLuint next = glGenLists(2);
  EXPECT_TRUE(next + 1 < first || next > first + 2);
  glDeleteLists(first, 3);
  EXPECT_EQ(glIsList(first + 1), GL_FALSE);
  EXPECT_EQ(glGenLists(0), 0u);
  glNewList(100, GL_COMPILE);
  glEndList();
  EXPECT_EQ(glIsList(100), GL_TRUE);  // defining a list makes its name used
}

TEST_F(DisplayListStateTest, Errors) {
  glNewList(0, GL_COMPILE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glNewList(1, GL_RENDER);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glNewList(1, GL_COMPILE);
  glNewList(2, GL_COMPILE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_LIST_INDEX), 1);
  glEndList();
  EXPECT_EQ(glGenLists(-1), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteLists(1, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLubyte names[1] = {0};
  glCallLists(1, GL_DOUBLE, names);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCallLists(-1, GL_UNSIGNED_BYTE, names);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCallList(12345);  // undefined: nothing happens
}

TEST_F(DisplayListStateTest, CompileDoesNotExecuteAndCallDoes) {
  glNewList(1, GL_COMPILE);
  glEnable(GL_BLEND);
  glDepthFunc(GL_GREATER);
  glColor3f(0, 1, 0);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{1, 1, 1, 1}));
  glCallList(1);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_TRUE);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_GREATER);
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{0, 1, 0, 1}));
}

TEST_F(DisplayListStateTest, CompileAndExecuteDoesBoth) {
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glEnable(GL_CULL_FACE);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_CULL_FACE), GL_TRUE);
  glDisable(GL_CULL_FACE);
  glCallList(1);
  EXPECT_EQ(glIsEnabled(GL_CULL_FACE), GL_TRUE);
}

TEST_F(DisplayListStateTest, ErrorsOfCompiledCallsAreRaisedWhenTheyRun) {
  glNewList(1, GL_COMPILE);
  glDepthFunc(0x1234);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(DisplayListStateTest, QueriesAndClientStateAreExecutedImmediately) {
  glNewList(1, GL_COMPILE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  glEndList();
  EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 2);
}

TEST_F(DisplayListStateTest, MatrixAndAttribCommandsReplay) {
  glNewList(1, GL_COMPILE);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_LIGHTING);
  glTranslatef(1, 2, 3);
  glPopAttrib();
  glEndList();
  glCallList(1);
  glCallList(1);
  EXPECT_EQ(glIsEnabled(GL_LIGHTING), GL_FALSE);
  const auto m = get_floats(GL_MODELVIEW_MATRIX, 16);
  EXPECT_EQ(m[12], 2.f);
  EXPECT_EQ(m[13], 4.f);
  EXPECT_EQ(m[14], 6.f);
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 0);
}

TEST_F(DisplayListStateTest, CallListsUsesTheBaseAtCallTime) {
  glNewList(10, GL_COMPILE);
  glColor3f(1, 0, 0);
  glEndList();
  glNewList(11, GL_COMPILE);
  glColor3f(0, 0, 1);
  glEndList();
  const GLubyte offsets[1] = {1};
  glListBase(10);
  glCallLists(1, GL_UNSIGNED_BYTE, offsets);
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{0, 0, 1, 1}));
  glListBase(9);
  glCallLists(1, GL_UNSIGNED_BYTE, offsets);
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{1, 0, 0, 1}));
}

// Found by the API fuzzer (UBSan: float to int conversion out of range): GL_FLOAT offsets are
// truncated; ones no GLint holds (2.7e35, -1e30, NaN) name no list and are skipped.
TEST_F(DisplayListStateTest, CallListsFloatOffsetsBeyondGLintNameNoList) {
  glNewList(3, GL_COMPILE);
  glColor3f(0, 1, 0);
  glEndList();
  glListBase(0);
  glColor3f(1, 1, 1);
  const GLfloat offsets[4] = {2.76733e35f, -1e30f, std::nanf(""), 3.75f};
  glCallLists(3, GL_FLOAT, offsets);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{1, 1, 1, 1}));
  glCallLists(4, GL_FLOAT, offsets);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{0, 1, 0, 1}));
}

// Found by the API fuzzer (out of memory: 8 GB copied): a compiled glDrawBuffers copies its
// names only for a count glDrawBuffers accepts; the list names the error when it runs.
TEST_F(DisplayListStateTest, CompiledDrawBuffersWithHugeCountCopiesNothing) {
  GLint before = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &before);
  const GLenum bufs[1] = {GL_FRONT_LEFT};
  glNewList(1, GL_COMPILE);
  glDrawBuffers(2147483647, bufs);  // the immediate call reads nothing either
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), before);
}

TEST_F(DisplayListStateTest, RecursionStopsAtTheNestingLimit) {
  glNewList(1, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glCallList(1);  // calls itself
  glEndList();
  glCallList(1);
  const auto m = get_floats(GL_MODELVIEW_MATRIX, 16);
  EXPECT_GE(m[12], 1.f);
  EXPECT_LE(m[12], float(get_int(GL_MAX_LIST_NESTING)) + 1);
}

}  // namespace
}  // namespace pineda::test
