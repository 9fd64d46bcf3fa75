// glCheckFramebufferStatus for every status it can return, and GL_INVALID_FRAMEBUFFER_OPERATION
// from the commands that draw into or read from an incomplete framebuffer.
#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

using CompletenessTest = FboTest;

TEST_F(CompletenessTest, MissingAttachment) {
  const GLuint fb = make_fbo();
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT));
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT));
  glDeleteFramebuffers(1, &fb);
}

TEST_F(CompletenessTest, CompleteWithColourAndDepthStencil) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 8, 8);
  const GLuint ds = make_renderbuffer(GL_DEPTH24_STENCIL8, 8, 8);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(get_int(GL_RED_BITS), 8);
  EXPECT_EQ(get_int(GL_ALPHA_BITS), 8);
  EXPECT_EQ(get_int(GL_DEPTH_BITS), 24);
  EXPECT_EQ(get_int(GL_STENCIL_BITS), 8);
  glDeleteFramebuffers(1, &fb);
  const GLuint rbs[2] = {color, ds};
  glDeleteRenderbuffers(2, rbs);
}

TEST_F(CompletenessTest, IncompleteAttachment) {
  const GLuint empty = make_renderbuffer(GL_RGBA8, 0, 0);
  const GLuint depth = make_renderbuffer(GL_DEPTH_COMPONENT24, 4, 4);
  const GLuint color = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, empty);  // no storage
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, depth);  // not colour
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, color);  // not depth
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth);  // no stencil
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  // A texture level that does not exist, then a depth texture at a colour point.
  const GLuint tex = make_texture(GL_RGBA8, 4, 4);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 1);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  const GLuint depth_tex = make_texture(GL_DEPTH_COMPONENT24, 4, 4, GL_DEPTH_COMPONENT, GL_FLOAT);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, depth_tex, 0);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_tex, 0);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glDeleteFramebuffers(1, &fb);
  const GLuint rbs[3] = {empty, depth, color};
  glDeleteRenderbuffers(3, rbs);
  const GLuint texs[2] = {tex, depth_tex};
  glDeleteTextures(2, texs);
}

// No draw and read buffer rules, through either entry point (GL 4.1 and
// GL_ARB_ES2_compatibility dropped them, as Mesa): reading a missing image is
// INVALID_OPERATION, drawing into one draws nothing.
TEST_F(CompletenessTest, DrawAndReadBufferWithoutImage) {
  const GLuint color = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, color);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);  // into COLOR_ATTACHMENT0: nothing
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(near_rgba(pixel(1, 1), {0, 0, 0, 0}));
  glDrawBuffer(GL_COLOR_ATTACHMENT1);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  uint8_t p[4] = {7, 7, 7, 7};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(p[0], 7);
  glRasterPos2i(0, 0);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 1, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glReadBuffer(GL_NONE);
  glDrawBuffer(GL_NONE);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &color);
}

// EXT_framebuffer_object's rules through its entry point; ARB_framebuffer_object's allow both.
TEST_F(CompletenessTest, ExtDimensionsAndFormats) {
  const GLuint a = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint b = make_renderbuffer(GL_RGBA8, 8, 4);
  const GLuint c = make_renderbuffer(GL_RGBA4, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, a);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, b);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT));
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, c);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_FORMATS_EXT));
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glDeleteFramebuffers(1, &fb);
  const GLuint rbs[3] = {a, b, c};
  glDeleteRenderbuffers(3, rbs);
}

TEST_F(CompletenessTest, IncompleteFramebufferOperations) {
  clear_to(0.2f, 0.4f, 0.6f, 1.f);
  const GLuint fb = make_fbo();  // no attachments
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glBegin(GL_TRIANGLES);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // no glBegin was in effect
  const float vertices[] = {0, 0, 4, 0, 0, 4};
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  const GLubyte indices[] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, indices);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glDisableClientState(GL_VERTEX_ARRAY);
  uint8_t p[4] = {1, 2, 3, 4};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  EXPECT_EQ(p[0], 1);
  glRasterPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  const GLubyte bits[1] = {0xff};
  glBitmap(1, 1, 0, 0, 0, 0, bits);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 1, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glAccum(GL_LOAD, 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  // The window's pixels were not touched.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {51, 102, 153, 255}));
  glDeleteFramebuffers(1, &fb);
}

TEST_F(CompletenessTest, DeletingAnAttachedImageDetachesIt) {
  const GLuint tex = make_texture(GL_RGBA8, 4, 4);
  const GLuint rb = make_renderbuffer(GL_DEPTH_COMPONENT16, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glDeleteRenderbuffers(1, &rb);
  GLint type = -1;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  EXPECT_EQ(type, GL_NONE);
  glDeleteTextures(1, &tex);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT));
  glDeleteFramebuffers(1, &fb);
}

TEST_F(CompletenessTest, UnboundFramebufferKeepsADeletedRenderbuffer) {
  const GLuint rb = make_renderbuffer(GL_RGBA8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteRenderbuffers(1, &rb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  EXPECT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_TRUE(near_rgba(pixel(2, 2), {255, 0, 0, 255}));
  glDeleteFramebuffers(1, &fb);
}

}  // namespace
}  // namespace pineda::test
