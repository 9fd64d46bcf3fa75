// GL_ARB_copy_buffer: glCopyBufferSubData between buffers and within one, the COPY_READ_BUFFER
// and COPY_WRITE_BUFFER bindings, and every error of GL 3.1 2.9.5 (in Mesa's order), each
// leaving the buffers as they were.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class CopyBufferTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glGenBuffers(2, buffers_);
    fill(GL_COPY_READ_BUFFER, buffers_[0], 0);
    fill(GL_COPY_WRITE_BUFFER, buffers_[1], 100);
  }
  // 32 bytes first, first + 1, ... bound to `target`.
  static void fill(GLenum target, GLuint buffer, int first) {
    glBindBuffer(target, buffer);
    std::vector<uint8_t> bytes(32);
    for (int i = 0; i < 32; ++i) bytes[size_t(i)] = uint8_t(first + i);
    glBufferData(target, GLsizeiptr(bytes.size()), bytes.data(), GL_STATIC_COPY);
  }
  static std::vector<int> contents(GLenum target) {
    uint8_t bytes[32] = {};
    glGetBufferSubData(target, 0, 32, bytes);
    return std::vector<int>(bytes, bytes + 32);
  }
  // The bytes `first`, first + 1, ... with `count` of them from index `at` replaced by
  // `from`, from + 1, ...
  static std::vector<int> expected(int first, int at, int from, int count) {
    std::vector<int> v;
    for (int i = 0; i < 32; ++i) v.push_back(i >= at && i < at + count ? from + i - at : first + i);
    return v;
  }
  GLuint buffers_[2] = {0, 0};
};

TEST_F(CopyBufferTest, CopiesBetweenBuffersAndReportsTheBindings) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(extensions.find("GL_ARB_copy_buffer "), std::string::npos);
  GLint read = -1, write = -1;
  glGetIntegerv(GL_COPY_READ_BUFFER_BINDING, &read);
  glGetIntegerv(GL_COPY_WRITE_BUFFER_BINDING, &write);
  EXPECT_EQ(read, GLint(buffers_[0]));
  EXPECT_EQ(write, GLint(buffers_[1]));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 4, 20, 12);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(contents(GL_COPY_WRITE_BUFFER), expected(100, 20, 4, 12));
  EXPECT_EQ(contents(GL_COPY_READ_BUFFER), expected(0, 0, 0, 0));
  // Any buffer target serves as either end; a zero size copies nothing.
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
  glCopyBufferSubData(GL_ARRAY_BUFFER, GL_COPY_READ_BUFFER, 0, 0, 2);
  glCopyBufferSubData(GL_ARRAY_BUFFER, GL_COPY_READ_BUFFER, 32, 32, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(contents(GL_COPY_READ_BUFFER), expected(0, 0, 100, 2));
  // Deleting a buffer unbinds it from the copy targets.
  glDeleteBuffers(1, &buffers_[0]);
  glGetIntegerv(GL_COPY_READ_BUFFER_BINDING, &read);
  EXPECT_EQ(read, 0);
}

TEST_F(CopyBufferTest, CopiesWithinOneBufferWhereTheRangesDoNotOverlap) {
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER, 0, 16, 16);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(contents(GL_COPY_READ_BUFFER), expected(0, 16, 0, 16));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER, 0, 15, 16);  // one byte in common
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER, 17, 16, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(contents(GL_COPY_READ_BUFFER), expected(0, 16, 0, 16));
}

TEST_F(CopyBufferTest, ErrorsCopyNothing) {
  glCopyBufferSubData(GL_TEXTURE_2D, GL_COPY_WRITE_BUFFER, 0, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_TEXTURE_2D, 0, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_ARRAY_BUFFER, 0, 0, 4);  // nothing bound there
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, -1, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, -1, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, -4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 29, 0, 4);  // past the source's end
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 29, 4);  // past the destination's end
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0x7fffffff, 0, 0x7fffffff);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  // A mapped buffer at either end: INVALID_OPERATION, before the range checks.
  ASSERT_NE(glMapBuffer(GL_COPY_WRITE_BUFFER, GL_READ_ONLY), nullptr);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCopyBufferSubData(GL_COPY_WRITE_BUFFER, GL_COPY_READ_BUFFER, -1, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glUnmapBuffer(GL_COPY_WRITE_BUFFER), GL_TRUE);
  EXPECT_EQ(contents(GL_COPY_READ_BUFFER), expected(0, 0, 0, 0));
  EXPECT_EQ(contents(GL_COPY_WRITE_BUFFER), expected(100, 0, 0, 0));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A display list does not hold the copy: it runs at once (GL 3.1 compatibility, 5.4.1).
TEST_F(CopyBufferTest, RunsAtOnceWhileAListIsCompiled) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, 8);
  glEndList();
  EXPECT_EQ(contents(GL_COPY_WRITE_BUFFER), expected(100, 0, 0, 8));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
