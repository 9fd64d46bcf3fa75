// Framebuffer and renderbuffer objects: names, bindings, state defaults, queries and the
// errors of each entry point.
#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

using FboObjectsTest = FboTest;

TEST_F(FboObjectsTest, DefaultsAndLimits) {
  EXPECT_EQ(get_int(GL_FRAMEBUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_READ_FRAMEBUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_RENDERBUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_MAX_RENDERBUFFER_SIZE), 8192);
  EXPECT_EQ(get_int(GL_MAX_COLOR_ATTACHMENTS), 8);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  for (const char* name : {"GL_ARB_framebuffer_object ", "GL_EXT_framebuffer_object ", "GL_EXT_framebuffer_blit ",
                           "GL_EXT_packed_depth_stencil "})
    EXPECT_NE(ext.find(name), std::string::npos) << name;
  EXPECT_EQ(get_int(GL_MAX_SAMPLES), 4);
}

TEST_F(FboObjectsTest, NamesExistOnceBound) {
  GLuint fb[2] = {0, 0};
  glGenFramebuffers(2, fb);
  EXPECT_NE(fb[0], 0u);
  EXPECT_NE(fb[0], fb[1]);
  EXPECT_FALSE(glIsFramebuffer(fb[0]));
  glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
  EXPECT_TRUE(glIsFramebuffer(fb[0]));
  EXPECT_EQ(get_int(GL_FRAMEBUFFER_BINDING), int(fb[0]));
  EXPECT_EQ(get_int(GL_READ_FRAMEBUFFER_BINDING), int(fb[0]));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_COLOR_ATTACHMENT0);
  EXPECT_EQ(get_int(GL_READ_BUFFER), GL_COLOR_ATTACHMENT0);
  EXPECT_EQ(get_int(GL_DOUBLEBUFFER), 0);
  EXPECT_EQ(get_int(GL_ACCUM_RED_BITS), 0);
  // Deleting the bound framebuffer binds the window's again, with its draw buffer.
  glDeleteFramebuffers(2, fb);
  EXPECT_FALSE(glIsFramebuffer(fb[0]));
  EXPECT_EQ(get_int(GL_FRAMEBUFFER_BINDING), 0);
  EXPECT_NE(get_int(GL_DRAW_BUFFER), GL_COLOR_ATTACHMENT0);

  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  EXPECT_FALSE(glIsRenderbuffer(rb));
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  EXPECT_TRUE(glIsRenderbuffer(rb));
  EXPECT_EQ(get_int(GL_RENDERBUFFER_BINDING), int(rb));
  glDeleteRenderbuffers(1, &rb);
  EXPECT_FALSE(glIsRenderbuffer(rb));
  EXPECT_EQ(get_int(GL_RENDERBUFFER_BINDING), 0);
  // Compatibility GL binds names that were never generated.
  glBindFramebuffer(GL_FRAMEBUFFER, 77);
  EXPECT_TRUE(glIsFramebuffer(77));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(FboObjectsTest, SeparateDrawAndReadBindings) {
  GLuint fb[2];
  glGenFramebuffers(2, fb);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
  EXPECT_EQ(get_int(GL_DRAW_FRAMEBUFFER_BINDING), int(fb[0]));
  EXPECT_EQ(get_int(GL_READ_FRAMEBUFFER_BINDING), int(fb[1]));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_EQ(get_int(GL_DRAW_FRAMEBUFFER_BINDING), int(fb[0]));
  EXPECT_EQ(get_int(GL_READ_FRAMEBUFFER_BINDING), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(2, fb);
}

TEST_F(FboObjectsTest, BindingErrors) {
  glBindFramebuffer(GL_TEXTURE_2D, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBindRenderbuffer(GL_FRAMEBUFFER, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glCheckFramebufferStatus(GL_RENDERBUFFER), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLuint names[1];
  glGenFramebuffers(-1, names);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGenRenderbuffers(-1, names);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteFramebuffers(-1, names);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(FboObjectsTest, RenderbufferStorageAndParameters) {
  GLint v = -1;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // none bound
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v);
  EXPECT_EQ(v, GL_RGBA);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v);
  EXPECT_EQ(v, 0);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, 7, 5);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  struct { GLenum pname; GLint value; } expected[] = {
      {GL_RENDERBUFFER_WIDTH, 7}, {GL_RENDERBUFFER_HEIGHT, 5}, {GL_RENDERBUFFER_INTERNAL_FORMAT, GL_RGB565},
      {GL_RENDERBUFFER_RED_SIZE, 5}, {GL_RENDERBUFFER_GREEN_SIZE, 6}, {GL_RENDERBUFFER_BLUE_SIZE, 5},
      {GL_RENDERBUFFER_ALPHA_SIZE, 0}, {GL_RENDERBUFFER_DEPTH_SIZE, 0}, {GL_RENDERBUFFER_STENCIL_SIZE, 0}};
  for (const auto& e : expected) {
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, e.pname, &v);
    EXPECT_EQ(v, e.value) << std::hex << e.pname;
  }
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 3, 3);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v);
  EXPECT_EQ(v, 24);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &v);
  EXPECT_EQ(v, 8);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_STENCIL_INDEX1, 3, 3);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &v);
  EXPECT_EQ(v, 8);  // every stencil size is stored in 8 bits, as Mesa
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, 3, 3);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v);
  EXPECT_EQ(v, 16);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  glRenderbufferStorage(GL_RENDERBUFFER, GL_COMPRESSED_RGB, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glRenderbufferStorage(GL_RENDERBUFFER, 4, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glRenderbufferStorage(GL_TEXTURE_2D, GL_RGBA8, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, -1, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 8193);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 5, GL_RGBA8, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));  // MAX_SAMPLES is 4
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDeleteRenderbuffers(1, &rb);
}

TEST_F(FboObjectsTest, AttachmentErrors) {
  const GLuint tex = make_texture(GL_RGBA8, 4, 4);
  const GLuint rb = make_renderbuffer(GL_RGBA8, 4, 4);
  // The window-system framebuffer takes no attachments.
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_TEXTURE_2D, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_BACK, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT8, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // past MAX_COLOR_ATTACHMENTS
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 12345, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // no such texture
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, tex, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // a 2D texture is no cube map
  glFramebufferTexture1D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 14);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, tex, 0, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // not a 3D texture
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rb);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 999);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLint v = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_EQ(v, GL_NONE);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // nothing attached
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
  glDeleteRenderbuffers(1, &rb);
}

TEST_F(FboObjectsTest, AttachmentQueries) {
  GLuint cube = 0;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 1, GL_RGBA4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint rb = make_renderbuffer(GL_DEPTH24_STENCIL8, 4, 4);
  const GLuint fb = make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, cube, 1);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb);
  auto query = [](GLenum attachment, GLenum pname) {
    GLint v = -1;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, attachment, pname, &v);
    return v;
  };
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE), GL_TEXTURE);
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME), int(cube));
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL), 1);
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE), GL_TEXTURE_CUBE_MAP_NEGATIVE_Y);
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE), 4);
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE), 4);
  EXPECT_EQ(query(GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE), GL_RENDERBUFFER);
  EXPECT_EQ(query(GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME), int(rb));
  EXPECT_EQ(query(GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE), 24);
  EXPECT_EQ(query(GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE), 8);
  EXPECT_EQ(query(GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));  // not a texture
  // Detaching with name 0.
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, 0, 0);
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE), GL_NONE);
  EXPECT_EQ(query(GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME), 0);
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &cube);
  glDeleteRenderbuffers(1, &rb);
}

// The window-system framebuffer's buffers (ARB_framebuffer_object): a 16x16 single-buffered
// surface with 8-bit RGBA, 24-bit depth and 8-bit stencil.
TEST_F(FboObjectsTest, DefaultFramebufferAttachments) {
  auto query = [](GLenum attachment, GLenum pname) {
    GLint v = -1;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, attachment, pname, &v);
    return v;
  };
  const GLboolean double_buffered = get_int(GL_DOUBLEBUFFER);
  EXPECT_EQ(query(GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE), GL_FRAMEBUFFER_DEFAULT);
  EXPECT_EQ(query(GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE), double_buffered ? GL_FRAMEBUFFER_DEFAULT : GL_NONE);
  EXPECT_EQ(query(GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE), 8);
  EXPECT_EQ(query(GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE), 24);
  EXPECT_EQ(query(GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE), 8);
  EXPECT_EQ(query(GL_FRONT_RIGHT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE), GL_NONE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  query(GL_FRONT_RIGHT, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  query(GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(FboObjectsTest, DrawAndReadBufferOnObjects) {
  const GLuint fb = make_fbo();
  glDrawBuffer(GL_BACK);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // a window-system buffer
  glDrawBuffer(GL_COLOR_ATTACHMENT8);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDrawBuffer(GL_TEXTURE_2D);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDrawBuffer(GL_COLOR_ATTACHMENT3);
  glReadBuffer(GL_NONE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_COLOR_ATTACHMENT3);
  EXPECT_EQ(get_int(GL_READ_BUFFER), GL_NONE);
  // The window keeps its own; the object its own when bound again.
  const GLint window_draw = [&] {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return get_int(GL_DRAW_BUFFER);
  }();
  EXPECT_NE(window_draw, GL_COLOR_ATTACHMENT3);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_COLOR_ATTACHMENT3);
  glDeleteFramebuffers(1, &fb);
}

}  // namespace
}  // namespace pineda::test
