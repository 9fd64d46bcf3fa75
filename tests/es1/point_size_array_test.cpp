// OES_point_size_array: each vertex brings its point size (GL_FIXED or GL_FLOAT), exact pixels.
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <vector>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr int kSize = 32;
constexpr GLfixed X(double v) { return static_cast<GLfixed>(v * 65536.0); }

class PointSizeArray : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    glViewport(0, 0, kSize, kSize);
    glMatrixMode(GL_PROJECTION);
    glOrthox(0, X(kSize), 0, X(kSize), X(-1), X(1));
    glMatrixMode(GL_MODELVIEW);
    glClearColorx(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4x(X(1), X(1), X(1), X(1));
  }
  // How many pixels are white.
  int lit_pixels() {
    std::vector<GLubyte> p(kSize * kSize * 4);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    int n = 0;
    for (int i = 0; i < kSize * kSize; ++i) n += p[i * 4] == 255;
    return n;
  }
  bool lit(int x, int y) {
    GLubyte p[4] = {};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return p[0] == 255;
  }
  Es1Context ctx{kSize, kSize};
};

TEST_F(PointSizeArray, FixedSizesPerVertex) {
  const GLfixed positions[] = {X(4.5), X(4.5), X(12.5), X(12.5), X(24.5), X(24.5)};
  const GLfixed sizes[] = {X(1), X(3), X(5)};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FIXED, 0, positions);
  glEnableClientState(GL_POINT_SIZE_ARRAY_OES);
  glPointSizePointerOES(GL_FIXED, 0, sizes);
  glDrawArrays(GL_POINTS, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(lit_pixels(), 1 + 9 + 25);
  EXPECT_TRUE(lit(4, 4));
  EXPECT_FALSE(lit(5, 4));
  EXPECT_TRUE(lit(11, 11));
  EXPECT_TRUE(lit(13, 13));
  EXPECT_FALSE(lit(14, 12));
  EXPECT_TRUE(lit(22, 22));
  EXPECT_TRUE(lit(26, 26));
  EXPECT_FALSE(lit(27, 24));
}

TEST_F(PointSizeArray, DisabledArrayUsesPointSize) {
  const GLfloat positions[] = {8.5f, 8.5f};
  const GLfloat sizes[] = {7};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glPointSizePointerOES(GL_FLOAT, 0, sizes);
  glPointSizex(X(3));
  glDrawArrays(GL_POINTS, 0, 1);
  EXPECT_EQ(lit_pixels(), 9);
  glEnableClientState(GL_POINT_SIZE_ARRAY_OES);
  glDrawArrays(GL_POINTS, 0, 1);
  EXPECT_EQ(lit_pixels(), 49);
}

TEST_F(PointSizeArray, StateAndErrors) {
  const GLfloat sizes[] = {1, 2};
  glPointSizePointerOES(GL_FLOAT, 8, sizes);
  GLint type = 0, stride = 0, binding = -1;
  glGetIntegerv(GL_POINT_SIZE_ARRAY_TYPE_OES, &type);
  glGetIntegerv(GL_POINT_SIZE_ARRAY_STRIDE_OES, &stride);
  glGetIntegerv(GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES, &binding);
  EXPECT_EQ(type, GL_FLOAT);
  EXPECT_EQ(stride, 8);
  EXPECT_EQ(binding, 0);
  void* pointer = nullptr;
  glGetPointerv(GL_POINT_SIZE_ARRAY_POINTER_OES, &pointer);
  EXPECT_EQ(pointer, static_cast<const void*>(sizes));
  EXPECT_FALSE(glIsEnabled(GL_POINT_SIZE_ARRAY_OES));
  glEnableClientState(GL_POINT_SIZE_ARRAY_OES);
  EXPECT_TRUE(glIsEnabled(GL_POINT_SIZE_ARRAY_OES));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPointSizePointerOES(GL_SHORT, 0, sizes);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glPointSizePointerOES(GL_FLOAT, -4, sizes);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

// As Mesa: the deleted buffer's binding reverts to zero (the stored offset then names client
// memory, the application's problem); draws with the array disabled keep working.
TEST_F(PointSizeArray, DeletingItsBufferUnbindsIt) {
  const GLfloat sizes[] = {5};
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, sizeof sizes, sizes, GL_STATIC_DRAW);
  glPointSizePointerOES(GL_FLOAT, 0, nullptr);
  GLint binding = -1;
  glGetIntegerv(GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES, &binding);
  EXPECT_EQ(binding, GLint(buffer));
  glDeleteBuffers(1, &buffer);
  glGetIntegerv(GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES, &binding);
  EXPECT_EQ(binding, 0);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &binding);
  EXPECT_EQ(binding, 0);
  const GLfloat positions[] = {8.5f, 8.5f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glPointSizex(X(3));
  glDrawArrays(GL_POINTS, 0, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(lit_pixels(), 9);
  EXPECT_TRUE(lit(7, 7));
  EXPECT_TRUE(lit(9, 9));
}

}  // namespace
}  // namespace pineda::es1_test
