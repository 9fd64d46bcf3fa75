// Allocations the machine cannot hold end in GL_OUT_OF_MEMORY with the state as it was, never
// in an abort. AddressSanitizer reports such allocations itself instead of failing them, so
// these tests run only without it.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "tests/e2e/support/gl_test.h"

// GCC says __SANITIZE_ADDRESS__, clang __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define PINEDA_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PINEDA_UNDER_ASAN 1
#endif
#endif

namespace pineda::test {
namespace {

class OutOfMemoryTest : public GlTest {
 protected:
  void SetUp() override {
#if defined(PINEDA_UNDER_ASAN)
    GTEST_SKIP() << "AddressSanitizer aborts on an allocation it cannot satisfy";
#endif
    GlTest::SetUp();
  }
};

TEST_F(OutOfMemoryTest, BufferDataBeyondMemoryKeepsTheOldStore) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  const uint8_t bytes[4] = {1, 2, 3, 4};
  glBufferData(GL_ARRAY_BUFFER, 4, bytes, GL_STATIC_DRAW);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(INTPTR_MAX), nullptr, GL_DYNAMIC_DRAW);
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  GLint size = 0, usage = 0;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &usage);
  EXPECT_EQ(size, 4);
  EXPECT_EQ(usage, GLint(GL_STATIC_DRAW));
  uint8_t back[4] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, back);
  EXPECT_EQ(std::vector<uint8_t>(back, back + 4), std::vector<uint8_t>(bytes, bytes + 4));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A 2^30 x 2^30 RGBA image is copied when the list is compiled: the copy cannot be made, the
// list gets no command, and compilation goes on.
TEST_F(OutOfMemoryTest, CompiledDrawPixelsBeyondMemoryLeavesTheListUsable) {
  const uint8_t pixel[4] = {255, 255, 255, 255};
  glNewList(1, GL_COMPILE);
  glDrawPixels(1 << 30, 1 << 30, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  glClearColor(0, 0, 1, 1);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLfloat clear[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  EXPECT_EQ(clear[2], 1.f);
}

// The same sizes overflow a 64-bit byte count with 16-byte pixels.
TEST_F(OutOfMemoryTest, CompiledDrawPixelsWhoseSizeOverflowsIsOutOfMemory) {
  const float pixel[4] = {1, 1, 1, 1};
  glNewList(1, GL_COMPILE);
  glDrawPixels(0x7fffffff, 0x7fffffff, GL_RGBA, GL_FLOAT, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  glEndList();
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
