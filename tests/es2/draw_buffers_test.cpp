// GL_EXT_draw_buffers in an OpenGL ES 2.0 context: glDrawBuffersEXT and its errors, the limits
// and DRAW_BUFFERi_EXT, colour attachments 1..3, and gl_FragData[i] of GLSL ES 1.00 shaders
// that enable the extension (gl_MaxDrawBuffers is 1 in those that do not).
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

constexpr int kSize = 8;
constexpr const char* kVertex = "attribute vec2 a_pos; void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }\n";

using DrawBuffersFn = PFNGLDRAWBUFFERSEXTPROC;

GLuint compile_fragment(const char* source, std::string& log) {
  const GLuint s = glCreateShader(GL_FRAGMENT_SHADER);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  char buffer[2048] = {};
  glGetShaderInfoLog(s, sizeof buffer, nullptr, buffer);
  log = buffer;
  if (!ok) {
    glDeleteShader(s);
    return 0;
  }
  return s;
}

class Es2DrawBuffers : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(context_.ok()) << context_.error();
    draw_buffers_ = reinterpret_cast<DrawBuffersFn>(eglGetProcAddress("glDrawBuffersEXT"));
    ASSERT_NE(draw_buffers_, nullptr);
  }
  void TearDown() override { EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)); }

  // A framebuffer object with an RGBA texture at each of the four colour attachments.
  void make_fbo() {
    glGenTextures(4, textures_.data());
    for (GLuint t : textures_) {
      glBindTexture(GL_TEXTURE_2D, t);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    }
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    for (int i = 0; i < 4; ++i)
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0_EXT + i, GL_TEXTURE_2D, textures_[size_t(i)], 0);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  }

  // Pixel (x, y) of texture i, read through a framebuffer of its own (ES 2.0 has no glReadBuffer).
  uint32_t texture_pixel(int i, int x, int y) {
    GLuint read = 0;
    glGenFramebuffers(1, &read);
    glBindFramebuffer(GL_FRAMEBUFFER, read);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textures_[size_t(i)], 0);
    const uint32_t p = read_pixel(x, y);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glDeleteFramebuffers(1, &read);
    return p;
  }

  static void draw_quad() {
    const float pos[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos);
    glEnableVertexAttribArray(0);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }

  static GLint get_int(GLenum pname) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
  }

  Es2Context context_{kSize, kSize};
  DrawBuffersFn draw_buffers_ = nullptr;
  GLuint fbo_ = 0;
  std::array<GLuint, 4> textures_{};
};

TEST_F(Es2DrawBuffers, Limits) {
  EXPECT_EQ(get_int(GL_MAX_DRAW_BUFFERS_EXT), 8);
  EXPECT_GE(get_int(GL_MAX_COLOR_ATTACHMENTS_EXT), 4);
  EXPECT_EQ(get_int(GL_DRAW_BUFFER0_EXT), GL_BACK);
  EXPECT_EQ(get_int(GL_DRAW_BUFFER1_EXT), GL_NONE);
}

TEST_F(Es2DrawBuffers, FragDataGoesToEachAttachment) {
  make_fbo();
  const GLenum all[] = {GL_COLOR_ATTACHMENT0_EXT, GL_COLOR_ATTACHMENT1_EXT, GL_COLOR_ATTACHMENT2_EXT,
                        GL_COLOR_ATTACHMENT3_EXT};
  draw_buffers_(4, all);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLenum bufs[] = {GL_COLOR_ATTACHMENT0_EXT, GL_COLOR_ATTACHMENT1_EXT, GL_NONE, GL_COLOR_ATTACHMENT3_EXT};
  draw_buffers_(4, bufs);
  EXPECT_EQ(get_int(GL_DRAW_BUFFER1_EXT), GL_COLOR_ATTACHMENT1_EXT);
  EXPECT_EQ(get_int(GL_DRAW_BUFFER2_EXT), GL_NONE);
  const GLuint p = build_program(kVertex,
                                 "#extension GL_EXT_draw_buffers : require\n"
                                 "precision mediump float;\n"
                                 "void main() {\n"
                                 "  gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);\n"
                                 "  gl_FragData[1] = vec4(0.0, 1.0, 0.0, 1.0);\n"
                                 "  gl_FragData[2] = vec4(1.0, 1.0, 0.0, 1.0);\n"
                                 "  gl_FragData[3] = vec4(1.0, 1.0, 1.0, 0.0);\n"
                                 "}\n",
                                 {{"a_pos", 0}});
  ASSERT_NE(p, 0u);
  glUseProgram(p);
  draw_quad();
  EXPECT_EQ(texture_pixel(0, 3, 3), 0xFF0000FFu);
  EXPECT_EQ(texture_pixel(1, 3, 3), 0x00FF00FFu);
  EXPECT_EQ(texture_pixel(2, 3, 3), 0x0000FFFFu);  // NONE: only cleared, never drawn
  EXPECT_EQ(texture_pixel(3, 3, 3), 0xFFFFFF00u);
  glDeleteProgram(p);
}

TEST_F(Es2DrawBuffers, ShaderDirectives) {
  std::string log;
  // The extension's macro is defined, enabled or not.
  GLuint s = compile_fragment(
      "#if !defined GL_EXT_draw_buffers || GL_EXT_draw_buffers != 1\n#error no macro\n#endif\n"
      "void main() { gl_FragColor = vec4(1.0); }\n",
      log);
  EXPECT_NE(s, 0u) << log;
  glDeleteShader(s);
  // Without the extension gl_MaxDrawBuffers is 1 and gl_FragData has one element.
  s = compile_fragment("void main() { gl_FragData[1] = vec4(1.0); }\n", log);
  EXPECT_EQ(s, 0u);
  EXPECT_NE(log.find("out of range"), std::string::npos) << log;
  s = compile_fragment(
      "#extension GL_EXT_draw_buffers : enable\n"
      "#extension GL_EXT_draw_buffers : disable\n"
      "void main() { gl_FragData[1] = vec4(1.0); }\n",
      log);
  EXPECT_EQ(s, 0u);
  s = compile_fragment("precision mediump float;\nuniform float m[gl_MaxDrawBuffers == 1 ? 1 : -1];\n"
                       "void main() { gl_FragColor = vec4(m[0]); }\n",
                       log);
  EXPECT_NE(s, 0u) << log;
  glDeleteShader(s);
  // Enabled: eight outputs, and the directive is not reported as unknown.
  s = compile_fragment(
      "#version 100\n"
      "  #  extension   GL_EXT_draw_buffers :   enable  // comment\n"
      "precision mediump float;\nuniform float m[gl_MaxDrawBuffers == 8 ? 1 : -1];\n"
      "void main() { gl_FragData[7] = vec4(m[0]); }\n",
      log);
  EXPECT_NE(s, 0u) << log;
  EXPECT_EQ(log.find("GL_EXT_draw_buffers"), std::string::npos) << log;
  glDeleteShader(s);
  // An unknown behaviour is still an error.
  s = compile_fragment("#extension GL_EXT_draw_buffers : sometimes\nvoid main() { gl_FragColor = vec4(1.0); }\n", log);
  EXPECT_EQ(s, 0u);
}

TEST_F(Es2DrawBuffers, Errors) {
  const GLenum back = GL_BACK;
  draw_buffers_(1, &back);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER0_EXT), GL_BACK);
  const GLenum front = GL_FRONT;
  draw_buffers_(1, &front);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLenum two[] = {GL_BACK, GL_NONE};
  draw_buffers_(2, two);  // the window-system framebuffer takes exactly one
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLenum attachment = GL_COLOR_ATTACHMENT0_EXT;
  draw_buffers_(1, &attachment);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLenum nine[9] = {GL_BACK};  // more than MAX_DRAW_BUFFERS_EXT
  draw_buffers_(9, nine);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  draw_buffers_(-1, two);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLenum none = GL_NONE;
  draw_buffers_(1, &none);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER0_EXT), GL_NONE);
  draw_buffers_(1, &back);

  make_fbo();
  const GLenum swapped[] = {GL_COLOR_ATTACHMENT1_EXT, GL_COLOR_ATTACHMENT0_EXT};
  draw_buffers_(2, swapped);  // output i goes to attachment i or nowhere
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  draw_buffers_(1, &back);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER0_EXT), GL_COLOR_ATTACHMENT0_EXT);  // unchanged
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(4, textures_.data());
}

}  // namespace
}  // namespace pineda::es2_test
