// GL_ARB_map_buffer_range: glMapBufferRange and glFlushMappedBufferRange, their errors (GL 3.0
// 2.9.3, with Mesa's INVALID_OPERATION for a zero length), the mapped range's state, and a
// draw reading what was written through a range.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstring>
#include <string>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class MapBufferRangeTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glGenBuffers(1, &buffer_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    uint8_t bytes[64];
    for (int i = 0; i < 64; ++i) bytes[i] = uint8_t(i);
    glBufferData(GL_ARRAY_BUFFER, sizeof bytes, bytes, GL_DYNAMIC_DRAW);
  }
  GLint param(GLenum pname) {
    GLint v = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, pname, &v);
    return v;
  }
  // glMapBufferRange's result and error.
  GLenum map_error(GLintptr offset, GLsizeiptr length, GLbitfield access) {
    void* p = glMapBufferRange(GL_ARRAY_BUFFER, offset, length, access);
    const GLenum e = glGetError();
    EXPECT_EQ(p == nullptr, e != GL_NO_ERROR);
    if (p) glUnmapBuffer(GL_ARRAY_BUFFER);
    return e;
  }
  GLuint buffer_ = 0;
};

TEST_F(MapBufferRangeTest, IsAdvertised) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(extensions.find("GL_ARB_map_buffer_range "), std::string::npos);
}

TEST_F(MapBufferRangeTest, MapsTheRangeAndReportsIt) {
  auto* p = static_cast<uint8_t*>(glMapBufferRange(GL_ARRAY_BUFFER, 16, 8, GL_MAP_READ_BIT | GL_MAP_WRITE_BIT));
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p[0], 16);
  EXPECT_EQ(p[7], 23);
  p[1] = 200;
  EXPECT_EQ(param(GL_BUFFER_MAPPED), GL_TRUE);
  EXPECT_EQ(param(GL_BUFFER_MAP_OFFSET), 16);
  EXPECT_EQ(param(GL_BUFFER_MAP_LENGTH), 8);
  EXPECT_EQ(param(GL_BUFFER_ACCESS_FLAGS), GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
  EXPECT_EQ(param(GL_BUFFER_ACCESS), GL_READ_WRITE);
  void* pointer = nullptr;
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &pointer);
  EXPECT_EQ(pointer, p);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  EXPECT_EQ(param(GL_BUFFER_MAP_OFFSET), 0);
  EXPECT_EQ(param(GL_BUFFER_MAP_LENGTH), 0);
  EXPECT_EQ(param(GL_BUFFER_ACCESS_FLAGS), 0);
  uint8_t back[2] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 16, 2, back);
  EXPECT_EQ(back[0], 16);
  EXPECT_EQ(back[1], 200);

  // glMapBuffer maps the whole store.
  ASSERT_NE(glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY), nullptr);
  EXPECT_EQ(param(GL_BUFFER_MAP_OFFSET), 0);
  EXPECT_EQ(param(GL_BUFFER_MAP_LENGTH), 64);
  EXPECT_EQ(param(GL_BUFFER_ACCESS_FLAGS), GL_MAP_WRITE_BIT);
  glUnmapBuffer(GL_ARRAY_BUFFER);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(MapBufferRangeTest, ErrorsAsTheSpecNamesThem) {
  EXPECT_EQ(map_error(0, 64, GL_MAP_READ_BIT), GLenum(GL_NO_ERROR));
  EXPECT_EQ(map_error(-1, 4, GL_MAP_READ_BIT), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(map_error(0, -4, GL_MAP_READ_BIT), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(map_error(60, 5, GL_MAP_READ_BIT), GLenum(GL_INVALID_VALUE));  // past the end
  EXPECT_EQ(map_error(0, 4, GL_MAP_READ_BIT | 0x100), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(map_error(0, 0, GL_MAP_READ_BIT), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(map_error(0, 4, GL_MAP_INVALIDATE_RANGE_BIT), GLenum(GL_INVALID_OPERATION));  // neither read nor write
  EXPECT_EQ(map_error(0, 4, GL_MAP_READ_BIT | GL_MAP_INVALIDATE_BUFFER_BIT), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(map_error(0, 4, GL_MAP_READ_BIT | GL_MAP_UNSYNCHRONIZED_BIT), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(map_error(0, 4, GL_MAP_READ_BIT | GL_MAP_FLUSH_EXPLICIT_BIT), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(map_error(4, 4, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_UNSYNCHRONIZED_BIT),
            GLenum(GL_NO_ERROR));
  glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_WRITE_BIT);
  EXPECT_EQ(map_error(8, 4, GL_MAP_WRITE_BIT), GLenum(GL_INVALID_OPERATION));  // already mapped
  glUnmapBuffer(GL_ARRAY_BUFFER);
  glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glMapBufferRange(GL_TEXTURE_2D, 0, 4, GL_MAP_READ_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // no buffer bound
}

TEST_F(MapBufferRangeTest, FlushNeedsAnExplicitFlushMappingAndARangeInsideIt) {
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // not mapped
  ASSERT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 8, 16, GL_MAP_WRITE_BIT), nullptr);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // not mapped with FLUSH_EXPLICIT
  glUnmapBuffer(GL_ARRAY_BUFFER);
  auto* p = static_cast<uint8_t*>(glMapBufferRange(GL_ARRAY_BUFFER, 8, 16, GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT));
  ASSERT_NE(p, nullptr);
  p[15] = 99;
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 16);  // offsets from the range's start
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 12, 5);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));  // past the mapped range
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, -1, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  uint8_t back = 0;
  glGetBufferSubData(GL_ARRAY_BUFFER, 23, 1, &back);
  EXPECT_EQ(back, 99);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(MapBufferRangeTest, ADrawReadsWhatARangeWrote) {
  pixel_projection();
  clear_to(0, 0, 0, 0);
  // A quad (0,0)-(8,8) written into bytes 32..63 through an invalidating write-only range.
  auto* p = static_cast<GLfloat*>(
      glMapBufferRange(GL_ARRAY_BUFFER, 32, 32, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT));
  ASSERT_NE(p, nullptr);
  const GLfloat quad[8] = {0, 0, 8, 0, 8, 8, 0, 8};
  std::memcpy(p, quad, sizeof quad);
  ASSERT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  glVertexPointer(2, GL_FLOAT, 0, reinterpret_cast<const void*>(32));
  glEnableClientState(GL_VERTEX_ARRAY);
  glColor4ub(10, 20, 30, 255);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(pixel(4, 4), (Rgba{10, 20, 30, 255}));
  EXPECT_EQ(pixel(9, 9), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
