// Occlusion queries (GL 1.5): SAMPLES_PASSED counts fragments that pass depth and stencil.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class OcclusionQueryTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glGenQueries(1, &query_);
  }
  GLuint result(GLuint q) {
    GLuint v = 12345;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &v);
    return v;
  }
  // A rectangle at depth z (window depth (1 - z) / 2 with the pixel projection).
  void rect(int x0, int y0, int x1, int y1, float z) {
    glBegin(GL_QUADS);
    glVertex3f(float(x0), float(y0), z);
    glVertex3f(float(x1), float(y0), z);
    glVertex3f(float(x1), float(y1), z);
    glVertex3f(float(x0), float(y1), z);
    glEnd();
  }
  GLuint query_ = 0;
};

TEST_F(OcclusionQueryTest, CountsCoveredPixels) {
  EXPECT_EQ(glIsQuery(query_), GL_FALSE);  // a query object exists from its first glBeginQuery
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  EXPECT_EQ(glIsQuery(query_), GL_TRUE);
  GLint current = 0;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
  EXPECT_EQ(current, GLint(query_));
  rect(0, 0, 10, 10, 0.f);
  rect(20, 20, 23, 25, 0.f);
  glEndQuery(GL_SAMPLES_PASSED);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
  EXPECT_EQ(current, 0);
  GLuint available = 0;
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT_AVAILABLE, &available);
  EXPECT_EQ(available, GLuint(GL_TRUE));
  EXPECT_EQ(result(query_), 100u + 15u);
  GLint signed_result = 0;
  glGetQueryObjectiv(query_, GL_QUERY_RESULT, &signed_result);
  EXPECT_EQ(signed_result, 115);
  rect(0, 0, 32, 32, 0.f);  // after the query: not counted
  EXPECT_EQ(result(query_), 115u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(OcclusionQueryTest, DepthAndStencilFailuresAreNotCounted) {
  glEnable(GL_DEPTH_TEST);
  rect(0, 0, 16, 32, 0.5f);  // near: window depth 0.25
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // counting needs no colour writes
  rect(0, 0, 32, 32, 0.f);   // depth 0.5: hidden on the left half
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(result(query_), 16u * 32u);

  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xff);  // the stencil buffer is 0
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  rect(0, 0, 32, 32, 0.9f);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(result(query_), 0u);
}

TEST_F(OcclusionQueryTest, QueriesRunOneAfterAnother) {
  GLuint q[2];
  glGenQueries(2, q);
  glBeginQuery(GL_SAMPLES_PASSED, q[0]);
  rect(0, 0, 4, 4, 0.f);
  glEndQuery(GL_SAMPLES_PASSED);
  glBeginQuery(GL_SAMPLES_PASSED, q[1]);
  rect(0, 0, 6, 6, 0.f);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(result(q[0]), 16u);
  EXPECT_EQ(result(q[1]), 36u);
  glBeginQuery(GL_SAMPLES_PASSED, q[0]);  // a new query restarts from zero
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(result(q[0]), 0u);
  glDeleteQueries(2, q);
  EXPECT_EQ(glIsQuery(q[0]), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(OcclusionQueryTest, Errors) {
  glBeginQuery(GL_TEXTURE_2D, query_);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBeginQuery(GL_SAMPLES_PASSED, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glEndQuery(GL_SAMPLES_PASSED);  // none active
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLuint v = 7;
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &v);  // never begun: not a query object
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(v, 7u);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glBeginQuery(GL_SAMPLES_PASSED, query_ + 1);  // one is active
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &v);  // active
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glEndQuery(GL_SAMPLES_PASSED);
  glGetQueryObjectuiv(query_, GL_TEXTURE_2D, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint bits = 0;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &bits);
  EXPECT_EQ(bits, 64);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_TEXTURE_2D, &bits);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGenQueries(-1, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBegin(GL_POINTS);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_occlusion_query"), std::string::npos);
}

TEST_F(OcclusionQueryTest, DeletingTheActiveQueryEndsIt) {
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glDeleteQueries(1, &query_);
  GLint current = -1;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
  EXPECT_EQ(current, 0);
  glBeginQuery(GL_SAMPLES_PASSED, query_ + 5);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glEndQuery(GL_SAMPLES_PASSED);
}

TEST_F(OcclusionQueryTest, PixelRectanglesAreCounted) {
  const GLubyte pixels[2 * 3 * 4] = {};
  glRasterPos2i(4, 4);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glDrawPixels(2, 3, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(result(query_), 6u);
  const GLubyte bits[2] = {0xf0, 0x80};  // rows of 4 and 1 set pixels
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glBitmap(8, 2, 0, 0, 0, 0, bits);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(result(query_), 5u);
}

TEST_F(OcclusionQueryTest, BeginAndEndAreCompiledIntoLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  rect(0, 0, 3, 3, 0.f);
  glEndQuery(GL_SAMPLES_PASSED);
  glEndList();
  EXPECT_EQ(glIsQuery(query_), GL_FALSE);
  glCallList(list);
  EXPECT_EQ(result(query_), 9u);
}

}  // namespace
}  // namespace pineda::test
