// Generic vertex attributes: current values, arrays and their queries (GL 2.0 2.7, 2.8, 6.1.14).
#include <limits>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

using VertexAttribsTest = ProgramTest;

TEST_F(VertexAttribsTest, CurrentValuesAndConversions) {
  GLfloat v[4] = {};
  glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[0], 0.f);
  EXPECT_EQ(v[3], 1.f);
  glVertexAttrib2f(3, 0.5f, -2.f);
  glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[0], 0.5f);
  EXPECT_EQ(v[1], -2.f);
  EXPECT_EQ(v[2], 0.f);
  EXPECT_EQ(v[3], 1.f);
  const GLubyte ub[4] = {255, 0, 51, 102};
  glVertexAttrib4Nubv(5, ub);
  glGetVertexAttribfv(5, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[0], 1.f);
  EXPECT_FLOAT_EQ(v[2], 0.2f);
  EXPECT_FLOAT_EQ(v[3], 0.4f);
  glVertexAttrib4ubv(5, ub);  // not normalized
  glGetVertexAttribfv(5, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[0], 255.f);
  const GLshort s[4] = {-32768, 32767, 0, 0};
  glVertexAttrib4Nsv(6, s);
  glGetVertexAttribfv(6, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[0], -1.f);
  EXPECT_EQ(v[1], 1.f);
  glVertexAttrib3d(7, 1.5, 2.5, 3.5);
  GLdouble d[4] = {};
  glGetVertexAttribdv(7, GL_CURRENT_VERTEX_ATTRIB, d);
  EXPECT_EQ(d[2], 3.5);
  EXPECT_EQ(d[3], 1.0);
  GLint i[4] = {};
  glGetVertexAttribiv(7, GL_CURRENT_VERTEX_ATTRIB, i);
  EXPECT_EQ(i[0], 1);  // float values are truncated
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// An API fuzzing run found the NaN's conversion to int undefined (UBSan).
TEST_F(VertexAttribsTest, NonFiniteCurrentValuesQueriedAsIntegers) {
  glVertexAttrib4f(2, std::numeric_limits<float>::quiet_NaN(), 1e30f, -1e30f, -2.5f);
  GLint i[4] = {1, 1, 1, 1};
  glGetVertexAttribiv(2, GL_CURRENT_VERTEX_ATTRIB, i);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(i[0], 0);  // NaN
  EXPECT_EQ(i[1], 2147483647);  // clamped to GLint
  EXPECT_EQ(i[2], -2147483647 - 1);
  EXPECT_EQ(i[3], -2);  // truncated
}

TEST_F(VertexAttribsTest, IndexErrors) {
  glVertexAttrib1f(16, 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glEnableVertexAttribArray(16);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDisableVertexAttribArray(99);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLfloat v[4];
  glGetVertexAttribfv(16, GL_VERTEX_ATTRIB_ARRAY_SIZE, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetVertexAttribfv(0, GL_CURRENT_VERTEX_ATTRIB, v);  // attribute 0 has no current value
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetVertexAttribfv(1, GL_TEXTURE_2D, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  void* p = nullptr;
  glGetVertexAttribPointerv(1, GL_VERTEX_ATTRIB_ARRAY_SIZE, &p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetVertexAttribPointerv(16, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(VertexAttribsTest, PointerStateAndErrors) {
  GLint v = -1;
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &v);
  EXPECT_EQ(v, GL_FALSE);
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_SIZE, &v);
  EXPECT_EQ(v, 4);
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_TYPE, &v);
  EXPECT_EQ(v, GL_FLOAT);
  const GLshort data[8] = {};
  glVertexAttribPointer(2, 3, GL_SHORT, GL_TRUE, 12, data);
  glEnableVertexAttribArray(2);
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_SIZE, &v);
  EXPECT_EQ(v, 3);
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_TYPE, &v);
  EXPECT_EQ(v, GL_SHORT);
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &v);
  EXPECT_EQ(v, 12);
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &v);
  EXPECT_EQ(v, GL_TRUE);
  void* p = nullptr;
  glGetVertexAttribPointerv(2, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
  EXPECT_EQ(p, static_cast<const void*>(data));
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glVertexAttribPointer(4, 2, GL_FLOAT, GL_FALSE, 0, reinterpret_cast<const void*>(16));
  glGetVertexAttribiv(4, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &v);
  EXPECT_EQ(GLuint(v), buffer);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glVertexAttribPointer(2, 5, GL_FLOAT, GL_FALSE, 0, data);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, -4, data);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glVertexAttribPointer(2, 4, GL_HALF_FLOAT, GL_FALSE, 0, data);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glVertexAttribPointer(16, 4, GL_FLOAT, GL_FALSE, 0, data);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_SIZE, &v);
  EXPECT_EQ(v, 3);  // unchanged by the failed calls
}

// Current generic attributes belong to the current group, generic arrays to the client
// vertex-array group (GL 2.0 tables 6.5 and 6.7).
TEST_F(VertexAttribsTest, PushAndPopAttribSaveGenericAttributesAndArrays) {
  glVertexAttrib4f(5, 1, 2, 3, 4);
  glPushAttrib(GL_CURRENT_BIT);
  glVertexAttrib4f(5, 9, 9, 9, 9);
  glPopAttrib();
  GLfloat v[4] = {};
  glGetVertexAttribfv(5, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[0], 1.f);
  EXPECT_EQ(v[3], 4.f);

  const GLfloat data[4] = {};
  glVertexAttribPointer(6, 2, GL_FLOAT, GL_FALSE, 8, data);
  glEnableVertexAttribArray(6);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableVertexAttribArray(6);
  glVertexAttribPointer(6, 4, GL_SHORT, GL_TRUE, 0, nullptr);
  glPopClientAttrib();
  GLint i = -1;
  glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &i);
  EXPECT_EQ(i, GL_TRUE);
  glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_SIZE, &i);
  EXPECT_EQ(i, 2);
  glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &i);
  EXPECT_EQ(i, 8);
  void* p = nullptr;
  glGetVertexAttribPointerv(6, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
  EXPECT_EQ(p, static_cast<const void*>(data));
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);  // another group leaves them alone
  glDisableVertexAttribArray(6);
  glPopClientAttrib();
  glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &i);
  EXPECT_EQ(i, GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
