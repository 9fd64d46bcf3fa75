// Colour-index calls on an RGBA visual (GL 1.1 sections 2.7, 2.8, 4.2): the state is kept,
// queried, compiled into lists and pushed as the spec says, and rendering ignores it.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class ColorIndexTest : public GlTest {
 protected:
  float get_float(GLenum pname) {
    GLfloat v = -100.f;
    glGetFloatv(pname, &v);
    return v;
  }
  GLint get_int(GLenum pname) {
    GLint v = -100;
    glGetIntegerv(pname, &v);
    return v;
  }
};

TEST_F(ColorIndexTest, CurrentIndexEveryForm) {
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 1.f);  // initial value
  glIndexi(7);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 7.f);
  glIndexf(2.75f);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 2.75f);
  EXPECT_EQ(get_int(GL_CURRENT_INDEX), 3);  // a floating-point state rounds to the nearest integer
  glIndexd(-4.5);
  GLdouble d = 0;
  glGetDoublev(GL_CURRENT_INDEX, &d);
  EXPECT_EQ(d, -4.5);
  glIndexs(-12);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), -12.f);
  glIndexub(200);  // not normalized: an index is a number, not a colour component
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 200.f);
  const GLdouble dv = 9.25;
  const GLfloat fv = 10.5f;
  const GLint iv = 11;
  const GLshort sv = 12;
  const GLubyte ubv = 13;
  glIndexdv(&dv);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 9.25f);
  glIndexfv(&fv);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 10.5f);
  glIndexiv(&iv);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 11.f);
  glIndexsv(&sv);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 12.f);
  glIndexubv(&ubv);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 13.f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ColorIndexTest, IndexIsAllowedBetweenBeginAndEnd) {
  glBegin(GL_POINTS);
  glIndexi(5);
  glVertex2f(0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 5.f);
  glBegin(GL_POINTS);  // the other index calls are not
  glClearIndex(2);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glIndexMask(1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_float(GL_INDEX_CLEAR_VALUE), 0.f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), -1);
}

TEST_F(ColorIndexTest, ClearIndexAndIndexMask) {
  EXPECT_EQ(get_float(GL_INDEX_CLEAR_VALUE), 0.f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), -1);  // all bits set
  glClearIndex(3.5f);
  glIndexMask(0x0f);
  EXPECT_EQ(get_float(GL_INDEX_CLEAR_VALUE), 3.5f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 0x0f);
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_INDEX_WRITEMASK, &b);
  EXPECT_EQ(b, GL_TRUE);
}

TEST_F(ColorIndexTest, RgbaRenderingIgnoresIndexState) {
  glClearColor(0.f, 1.f, 0.f, 1.f);
  glClearIndex(5);
  glIndexMask(0);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {0, 255, 0, 255}));
  pixel_projection();
  glColor3f(1, 0, 0);
  glIndexi(9);
  glRectf(0, 0, 4, 4);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {255, 0, 0, 255}));
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 16);
}

TEST_F(ColorIndexTest, PushAttribGroups) {
  glIndexi(4);
  glClearIndex(6);
  glIndexMask(0x3);
  glPushAttrib(GL_CURRENT_BIT);
  glIndexi(40);
  glClearIndex(60);
  glIndexMask(0x30);
  glPopAttrib();
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 4.f);
  EXPECT_EQ(get_float(GL_INDEX_CLEAR_VALUE), 60.f);  // not in CURRENT_BIT
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 0x30);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glIndexi(41);
  glClearIndex(61);
  glIndexMask(0x31);
  glPopAttrib();
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 41.f);  // not in COLOR_BUFFER_BIT
  EXPECT_EQ(get_float(GL_INDEX_CLEAR_VALUE), 60.f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 0x30);
}

TEST_F(ColorIndexTest, IndexArrayStateAndErrors) {
  const GLshort indices[] = {10, 0, 11, 0, 12, 0};
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_STRIDE), 0);
  glIndexPointer(GL_SHORT, 4, indices);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_STRIDE), 4);
  void* p = nullptr;
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, indices);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_FALSE);
  glEnableClientState(GL_INDEX_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glIndexPointer(GL_BYTE, 0, indices);  // not an index array type
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glIndexPointer(GL_INT, -1, indices);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_SHORT);  // the failed calls changed nothing
  glDisableClientState(GL_INDEX_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_FALSE);
}

TEST_F(ColorIndexTest, ArrayElementAndDrawArraysFetchTheIndex) {
  const GLubyte indices[] = {21, 22, 23, 24};
  const GLfloat vertices[] = {0, 0, 1, 0, 1, 1, 0, 1};
  glIndexPointer(GL_UNSIGNED_BYTE, 0, indices);
  glEnableClientState(GL_INDEX_ARRAY);
  glArrayElement(2);  // outside Begin/End: the current values still change
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 23.f);
  glBegin(GL_POINTS);
  glArrayElement(1);
  glEnd();
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 22.f);
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_POINTS, 0, 4);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 24.f);  // the last vertex's
  const GLuint order[] = {3, 0};
  glDrawElements(GL_POINTS, 2, GL_UNSIGNED_INT, order);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 21.f);
  glDisableClientState(GL_INDEX_ARRAY);
  glIndexi(3);
  glArrayElement(2);  // a disabled index array leaves the current index alone
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 3.f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ColorIndexTest, IndexArrayInABufferObject) {
  const GLint data[] = {0, 77, 78};
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
  glIndexPointer(GL_INT, 0, reinterpret_cast<const void*>(sizeof(GLint)));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_BUFFER_BINDING), GLint(buffer));
  glEnableClientState(GL_INDEX_ARRAY);
  glArrayElement(1);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 78.f);
  glIndexi(5);
  glArrayElement(2);  // past the end of the buffer: nothing is read
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 5.f);
  glDeleteBuffers(1, &buffer);
}

TEST_F(ColorIndexTest, ClientAttribStackKeepsTheIndexArray) {
  const GLfloat a[] = {1, 2}, b[] = {3, 4};
  glIndexPointer(GL_FLOAT, 0, a);
  glEnableClientState(GL_INDEX_ARRAY);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glIndexPointer(GL_DOUBLE, 16, b);
  glDisableClientState(GL_INDEX_ARRAY);
  glPopClientAttrib();
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_TRUE);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_STRIDE), 0);
  void* p = nullptr;
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, a);
  // glInterleavedArrays disables the index array.
  const GLfloat interleaved[] = {0, 0};
  glInterleavedArrays(GL_V2F, 0, interleaved);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_FALSE);
}

TEST_F(ColorIndexTest, DisplayListsCompileTheCalls) {
  GLubyte indices[] = {31, 32};
  glIndexPointer(GL_UNSIGNED_BYTE, 0, indices);
  glEnableClientState(GL_INDEX_ARRAY);
  glNewList(1, GL_COMPILE);
  glIndexi(9);
  glClearIndex(4);
  glIndexMask(3);
  glEndList();
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 1.f);  // GL_COMPILE executes nothing
  EXPECT_EQ(get_float(GL_INDEX_CLEAR_VALUE), 0.f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), -1);
  glCallList(1);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 9.f);
  EXPECT_EQ(get_float(GL_INDEX_CLEAR_VALUE), 4.f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 3);
  glNewList(2, GL_COMPILE);
  glArrayElement(1);  // the array is read now
  glIndexPointer(GL_FLOAT, 0, nullptr);  // client state: executed, not compiled
  glEndList();
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_FLOAT);
  indices[1] = 99;
  glCallList(2);
  EXPECT_EQ(get_float(GL_CURRENT_INDEX), 32.f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
