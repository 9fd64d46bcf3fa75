// GL_OES_framebuffer_object in OpenGL ES 1.1, with GL_OES_packed_depth_stencil and the sized
// formats of OES_rgb8_rgba8, OES_depth24 and OES_stencil8: render into a texture through a
// framebuffer object with a packed depth-stencil renderbuffer, then draw the texture in the
// window (the same pixels and answers as llvmpipe's ES 1.1, run side by side).
#define GL_GLEXT_PROTOTYPES
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <vector>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

using Pixel = std::vector<GLubyte>;

class Es1FramebufferObject : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    glGenFramebuffersOES(1, &framebuffer);
    glGenRenderbuffersOES(1, &renderbuffer);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, framebuffer);
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, texture, 0);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, renderbuffer);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_DEPTH24_STENCIL8_OES, 8, 8);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_DEPTH_ATTACHMENT_OES, GL_RENDERBUFFER_OES, renderbuffer);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_STENCIL_ATTACHMENT_OES, GL_RENDERBUFFER_OES, renderbuffer);
    glEnableClientState(GL_VERTEX_ARRAY);
  }
  Pixel pixel(int x, int y) {
    Pixel p(4, 0);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    return p;
  }
  Es1Context ctx{16, 16};
  GLuint framebuffer = 0, renderbuffer = 0, texture = 0;
};

TEST_F(Es1FramebufferObject, CompleteWithTheirState) {
  EXPECT_EQ(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES), GLenum(GL_FRAMEBUFFER_COMPLETE_OES));
  GLint value = -1;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING_OES, &value);
  EXPECT_EQ(value, GLint(framebuffer));
  glGetIntegerv(GL_RENDERBUFFER_BINDING_OES, &value);
  EXPECT_EQ(value, GLint(renderbuffer));
  glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, GL_RENDERBUFFER_STENCIL_SIZE_OES, &value);
  EXPECT_EQ(value, 8);
  glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, GL_RENDERBUFFER_DEPTH_SIZE_OES, &value);
  EXPECT_EQ(value, 24);
  glGetFramebufferAttachmentParameterivOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                           GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, &value);
  EXPECT_EQ(value, GL_TEXTURE);
  EXPECT_TRUE(glIsFramebufferOES(framebuffer));
  EXPECT_TRUE(glIsRenderbufferOES(renderbuffer));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The extension's formats and those of OES_rgb8_rgba8, OES_depth24 and OES_stencil8 (as
// Mesa's ES 1.1); an unsized format is none.
TEST_F(Es1FramebufferObject, OnlyESRenderableFormats) {
  glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA, 8, 8);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  for (const GLenum format : {GL_RGB565_OES, GL_RGBA4_OES, GL_RGB5_A1_OES, GL_DEPTH_COMPONENT16_OES, GL_RGB8_OES,
                              GL_RGBA8_OES, GL_DEPTH_COMPONENT24_OES, GL_STENCIL_INDEX8_OES}) {
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, format, 8, 8);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << format;
    GLint stored = 0;
    glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, GL_RENDERBUFFER_INTERNAL_FORMAT_OES, &stored);
    EXPECT_EQ(GLenum(stored), format);
  }
}

// Colour, depth and stencil in three renderbuffers of the sized formats.
TEST_F(Es1FramebufferObject, SeparateSizedRenderbuffers) {
  GLuint buffers[3];
  glGenRenderbuffersOES(3, buffers);
  const GLenum formats[3] = {GL_RGBA8_OES, GL_DEPTH_COMPONENT24_OES, GL_STENCIL_INDEX8_OES};
  const GLenum points[3] = {GL_COLOR_ATTACHMENT0_OES, GL_DEPTH_ATTACHMENT_OES, GL_STENCIL_ATTACHMENT_OES};
  for (int i = 0; i < 3; ++i) {
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, buffers[i]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, formats[i], 8, 8);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, points[i], GL_RENDERBUFFER_OES, buffers[i]);
  }
  ASSERT_EQ(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES), GLenum(GL_FRAMEBUFFER_COMPLETE_OES));
  glViewport(0, 0, 8, 8);
  glClearColor(0, 0, 0, 1);
  glClearStencil(0);
  glClearDepthf(1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  const GLfloat near_quad[] = {-1, -1, -0.5f, 1, -1, -0.5f, -1, 1, -0.5f, 1, 1, -0.5f};
  const GLfloat far_quad[] = {-1, -1, 0.5f, 1, -1, 0.5f, -1, 1, 0.5f, 1, 1, 0.5f};
  glColor4f(1, 0, 0, 1);
  glVertexPointer(3, GL_FLOAT, 0, near_quad);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glColor4f(0, 1, 0, 1);  // behind: fails the depth test, its stencil stays 1
  glVertexPointer(3, GL_FLOAT, 0, far_quad);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glDisable(GL_DEPTH_TEST);
  glColor4f(0, 0, 1, 1);  // where the stencil is 1: everywhere
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  EXPECT_EQ(pixel(3, 3), (Pixel{0, 0, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es1FramebufferObject, RendersIntoTheTextureWithStencil) {
  glViewport(0, 0, 8, 8);
  glClearColor(0, 0, 1, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  // A red lower-left triangle marks the stencil; green fills where it is not set.
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  const GLfloat triangle[] = {-1, -1, 1, -1, -1, 1};
  glVertexPointer(2, GL_FLOAT, 0, triangle);
  glColor4f(1, 0, 0, 1);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  const GLfloat quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  glVertexPointer(2, GL_FLOAT, 0, quad);
  glColor4f(0, 1, 0, 1);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_STENCIL_TEST);
  EXPECT_EQ(pixel(1, 1), (Pixel{255, 0, 0, 255}));
  EXPECT_EQ(pixel(6, 6), (Pixel{0, 255, 0, 255}));

  // The texture in the 16x16 window, each texel over 2x2 pixels.
  glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
  glViewport(0, 0, 16, 16);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const GLfloat coords[] = {0, 0, 1, 0, 0, 1, 1, 1};
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, coords);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  EXPECT_EQ(pixel(2, 2), (Pixel{255, 0, 0, 255}));
  EXPECT_EQ(pixel(13, 13), (Pixel{0, 255, 0, 255}));
  glGenerateMipmapOES(GL_TEXTURE_2D);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es1FramebufferObject, DesktopContextsRefuseTheOESNames) {
  const EGLint attribs[] = {EGL_NONE};
  EglContext desktop(EGL_OPENGL_API, attribs, 16, 16, EGL_OPENGL_BIT);
  ASSERT_TRUE(desktop.ok()) << desktop.error();
  GLuint name = 0;
  glGenFramebuffersOES(1, &name);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(name, 0u);
}

}  // namespace
}  // namespace pineda::es1_test
