// MAX_DRAW_BUFFERS is 8, as Mesa: eight colour attachments written by one draw, each output
// to its own buffer, gl_FragColor to all of them, and a ninth draw buffer refused.
#include <array>

#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

constexpr int kBuffers = 8;
constexpr int kSize = 16;

class EightDrawBuffersTest : public FboTest {
 protected:
  void SetUp() override {
    FboTest::SetUp();
    fb_ = make_fbo();
    glGenRenderbuffers(kBuffers, rbs_.data());
    for (int i = 0; i < kBuffers; ++i) {
      glBindRenderbuffer(GL_RENDERBUFFER, rbs_[size_t(i)]);
      glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kSize, kSize);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + GLenum(i), GL_RENDERBUFFER, rbs_[size_t(i)]);
      attachments_[size_t(i)] = GL_COLOR_ATTACHMENT0 + GLenum(i);
    }
    ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glDrawBuffers(kBuffers, attachments_.data());
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  void TearDown() override {
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb_);
    glDeleteRenderbuffers(kBuffers, rbs_.data());
    FboTest::TearDown();
  }

  Rgba attachment_pixel(int i, int x, int y) {
    glReadBuffer(GL_COLOR_ATTACHMENT0 + GLenum(i));
    return pixel(x, y);
  }

  GLuint fb_ = 0;
  std::array<GLuint, kBuffers> rbs_{};
  std::array<GLenum, kBuffers> attachments_{};
};

TEST_F(EightDrawBuffersTest, EveryDrawBufferIsSet) {
  EXPECT_EQ(get_int(GL_MAX_DRAW_BUFFERS), kBuffers);
  for (int i = 0; i < kBuffers; ++i) EXPECT_EQ(get_int(GL_DRAW_BUFFER0 + GLenum(i)), int(GL_COLOR_ATTACHMENT0) + i) << i;
}

TEST_F(EightDrawBuffersTest, FragDataGoesToEachOfEightAttachments) {
  // Output i is (i, 2i, 3i, 255 - i) * 10 / 255: eight different, exactly representable values.
  const GLuint p = fragment_program(
      "void main() {\n"
      "  for (int i = 0; i < 8; ++i)\n"
      "    gl_FragData[i] = vec4(float(i), float(2 * i), float(3 * i), 25.5 - float(i)) * 10.0 / 255.0;\n"
      "}\n");
  glUseProgram(p);
  draw_rect(0, 0, 8, 8);
  for (int i = 0; i < kBuffers; ++i) {
    const auto v = uint8_t(10 * i);
    EXPECT_EQ(attachment_pixel(i, 3, 3), (Rgba{v, uint8_t(2 * v), uint8_t(3 * v), uint8_t(255 - v)})) << i;
    EXPECT_EQ(attachment_pixel(i, 12, 12), (Rgba{0, 0, 0, 0})) << i;  // outside the rectangle
  }
  glDeleteProgram(p);
}

TEST_F(EightDrawBuffersTest, FragColorGoesToAllEight) {
  const GLuint p = fragment_program("void main() { gl_FragColor = vec4(200.0, 100.0, 50.0, 150.0) / 255.0; }");
  glUseProgram(p);
  draw_rect(0, 0, 4, 4);
  for (int i = 0; i < kBuffers; ++i) EXPECT_EQ(attachment_pixel(i, 1, 1), (Rgba{200, 100, 50, 150})) << i;
  glDeleteProgram(p);
}

TEST_F(EightDrawBuffersTest, NineDrawBuffersAreInvalidValue) {
  std::array<GLenum, kBuffers + 1> nine{};
  nine.fill(GL_NONE);
  glDrawBuffers(kBuffers + 1, nine.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER7), int(GL_COLOR_ATTACHMENT7));  // unchanged
  get_int(GL_DRAW_BUFFER0 + kBuffers);  // past MAX_DRAW_BUFFERS
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

}  // namespace
}  // namespace pineda::test
