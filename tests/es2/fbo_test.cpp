// Render to texture through an ES 2.0 framebuffer object, with a depth renderbuffer, then the
// texture composited into the pbuffer: exact pixels at each step.
#include <gtest/gtest.h>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

constexpr const char* kColorVertex = "attribute vec3 a_pos; void main() { gl_Position = vec4(a_pos, 1.0); }\n";
constexpr const char* kColorFragment =
    "precision mediump float; uniform vec4 u_color; void main() { gl_FragColor = u_color; }\n";
constexpr const char* kCopyVertex =
    "attribute vec2 a_pos; varying vec2 v_uv;\n"
    "void main() { v_uv = a_pos * 0.5 + 0.5; gl_Position = vec4(a_pos, 0.0, 1.0); }\n";
constexpr const char* kCopyFragment =
    "precision mediump float; uniform sampler2D u_tex; varying vec2 v_uv;\n"
    "void main() { gl_FragColor = texture2D(u_tex, v_uv).bgra; }\n";

void draw_quad(GLuint location, float z) {
  const float pos[] = {-1, -1, z, 1, -1, z, -1, 1, z, 1, 1, z};
  glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, 0, pos);
  glEnableVertexAttribArray(location);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

TEST(Es2Fbo, RenderToTextureWithDepthThenComposite) {
  Es2Context context(8, 8);
  ASSERT_TRUE(context.ok()) << context.error();
  GLuint tex = 0, depth = 0, fbo = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, 8, 8);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));

  const GLuint color = build_program(kColorVertex, kColorFragment, {{"a_pos", 0}});
  ASSERT_NE(color, 0u);
  glUseProgram(color);
  const GLint u_color = glGetUniformLocation(color, "u_color");
  glClearColor(0, 0, 0, 1);
  glClearDepthf(1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUniform4f(u_color, 1.f, 0.f, 0.f, 1.f);
  draw_quad(0, -0.5f);  // near: red
  glUniform4f(u_color, 0.f, 1.f, 0.f, 1.f);
  draw_quad(0, 0.5f);  // behind: rejected
  EXPECT_EQ(read_pixel(3, 3), 0xFF0000FFu);
  glDisable(GL_DEPTH_TEST);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const GLuint copy = build_program(kCopyVertex, kCopyFragment, {{"a_pos", 0}});
  ASSERT_NE(copy, 0u);
  glUseProgram(copy);
  glUniform1i(glGetUniformLocation(copy, "u_tex"), 0);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const float pos[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) ASSERT_EQ(read_pixel(x, y), 0x0000FFFFu) << x << "," << y;  // red, swizzled to blue
}

// OES_packed_depth_stencil and OES_depth_texture: a DEPTH_STENCIL texture takes both
// attachments; a DEPTH_COMPONENT texture the depth one.
TEST(Es2Fbo, DepthTexturesComplete) {
  Es2Context context(8, 8);
  ASSERT_TRUE(context.ok()) << context.error();
  GLuint tex[3] = {}, fbo = 0;
  glGenTextures(3, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_OES, 4, 4, 0, GL_DEPTH_STENCIL_OES, GL_UNSIGNED_INT_24_8_OES,
               nullptr);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex[1], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, tex[1], 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex[2], 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::es2_test
