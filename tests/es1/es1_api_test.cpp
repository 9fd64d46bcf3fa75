// What an OpenGL ES 1.1 context tells and accepts: its strings, the ES-only queries, and the
// errors for what ES 1.1 leaves out of GL 1.5 (functions: GL_INVALID_OPERATION, as Mesa;
// enums: GL_INVALID_ENUM); and desktop GL contexts refusing the ES-only functions.
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <string>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "<null>";
}

class Es1Api : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(ctx.ok()) << ctx.error(); }
  Es1Context ctx;
};

TEST_F(Es1Api, Strings) {
  EXPECT_EQ(gl_string(GL_VERSION), "OpenGL ES-CM 1.1 Pineda 0.1.0");
  EXPECT_EQ(gl_string(GL_VENDOR), "Pineda");
  EXPECT_EQ(gl_string(GL_RENDERER), "Pineda (software rasterizer)");
  EXPECT_EQ(gl_string(GL_EXTENSIONS),
            "GL_EXT_blend_minmax GL_EXT_multi_draw_arrays GL_EXT_texture_lod_bias GL_OES_blend_equation_separate "
            "GL_OES_blend_func_separate GL_OES_blend_subtract GL_OES_byte_coordinates GL_OES_compressed_paletted_texture "
            "GL_OES_depth24 GL_OES_draw_texture GL_OES_element_index_uint GL_OES_fixed_point GL_OES_framebuffer_object "
            "GL_OES_packed_depth_stencil GL_OES_point_size_array GL_OES_point_sprite GL_OES_read_format "
            "GL_OES_rgb8_rgba8 GL_OES_single_precision GL_OES_stencil8 GL_OES_stencil_wrap GL_OES_texture_env_crossbar "
            "GL_OES_texture_mirrored_repeat GL_OES_texture_npot ");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es1Api, ReadFormatIsRgbaUnsignedByte) {
  GLint format = 0, type = 0;
  glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, &format);
  glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE_OES, &type);
  EXPECT_EQ(format, GL_RGBA);
  EXPECT_EQ(type, GL_UNSIGNED_BYTE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The one library exports every GL function, but an ES 1.1 context runs only its own.
TEST_F(Es1Api, DesktopOnlyFunctionsAreInvalidOperation) {
  using Begin = void (*)(GLenum);
  using Vertex2f = void (*)(GLfloat, GLfloat);
  auto begin = reinterpret_cast<Begin>(eglGetProcAddress("glBegin"));
  auto vertex = reinterpret_cast<Vertex2f>(eglGetProcAddress("glVertex2f"));
  ASSERT_NE(begin, nullptr);
  ASSERT_NE(vertex, nullptr);
  begin(GL_TRIANGLES);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  vertex(1, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  // Not inside glBegin/glEnd: an ES call still works.
  glClearColorx(0, 0, 0, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es1Api, DesktopOnlyEnumsAreInvalidEnum) {
  constexpr GLenum kTexture1D = 0x0DE0, kLineStipple = 0x0B24, kDouble = 0x140A, kUnpackRowLength = 0x0CF2;
  glEnable(kTexture1D);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLboolean b = GL_TRUE;
  glGetBooleanv(kLineStipple, &b);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(b, GL_TRUE);
  glPixelStorei(kUnpackRowLength, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLfloat v[3] = {};
  glVertexPointer(3, kDouble, 0, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEnable(GL_TEXTURE_2D);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// ES 1.1 table 2.4: sizes and types of the arrays.
TEST_F(Es1Api, ArrayTypesAreES) {
  GLfixed v[16] = {};
  glVertexPointer(3, GL_FIXED, 0, v);
  glVertexPointer(2, GL_BYTE, 0, v);
  glNormalPointer(GL_FIXED, 0, v);
  glColorPointer(4, GL_FIXED, 0, v);
  glTexCoordPointer(2, GL_FIXED, 0, v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint type = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_TYPE, &type);
  EXPECT_EQ(type, GL_BYTE);
  glColorPointer(3, GL_FLOAT, 0, v);  // colours have 4 components in ES
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexCoordPointer(1, GL_FLOAT, 0, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glColorPointer(4, GL_SHORT, 0, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(Es1Api, GetPointerv) {
  static const GLfixed v[3] = {};
  glVertexPointer(3, GL_FIXED, 0, v);
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, static_cast<const void*>(v));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The ES-only functions are not part of desktop GL 1.5: a desktop context refuses them.
TEST(DesktopContext, RefusesESOnlyFunctions) {
  const EGLint gl[] = {EGL_NONE};
  EglContext desktop(EGL_OPENGL_API, gl, 8, 8, EGL_OPENGL_BIT);
  ASSERT_TRUE(desktop.ok()) << desktop.error();
  glOrthof(-1, 1, -1, 1, -1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glClearColorx(0, 0, 0, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLfixed x = 7;
  glGetFixedv(GL_DEPTH_FUNC, &x);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(x, 7);
  EXPECT_EQ(gl_string(GL_EXTENSIONS).find("GL_OES_fixed_point"), std::string::npos);
}

// ES 1.1 has the 4 fixed-function texture units only (desktop GL 2.0 has 8 texture image units).
TEST_F(Es1Api, ActiveTextureTakesFourUnits) {
  glActiveTexture(GL_TEXTURE3);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glActiveTexture(GL_TEXTURE4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint v = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE3);
  glGetIntegerv(GL_MAX_TEXTURE_UNITS, &v);
  EXPECT_EQ(v, 4);
}

// ES 1.1 3.7.1 on glTexImage2D: one of five base internal formats, equal to format, a pair of
// table 3.4, no border; each error as Mesa's ES 1.1 context records it (llvmpipe, side by side).
TEST_F(Es1Api, TexImage2DTakesOnlyWhatES11Allows) {
  const GLubyte texels[4 * 4 * 4] = {};
  glBindTexture(GL_TEXTURE_2D, 1);
  auto image = [&](GLint internalformat, GLenum format, GLenum type, GLint border) {
    glTexImage2D(GL_TEXTURE_2D, 0, internalformat, 2, 2, border, format, type, texels);
    return glGetError();
  };
  EXPECT_EQ(image(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, 0), GLenum(GL_NO_ERROR));
  EXPECT_EQ(image(GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, 0), GLenum(GL_NO_ERROR));
  EXPECT_EQ(image(GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 0), GLenum(GL_NO_ERROR));
  EXPECT_EQ(image(3, GL_RGB, GL_UNSIGNED_BYTE, 0), GLenum(GL_INVALID_VALUE));  // desktop GL's component count
  EXPECT_EQ(image(GL_PALETTE4_RGB8_OES, GL_PALETTE4_RGB8_OES, GL_UNSIGNED_BYTE, 0), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(image(GL_RGBA, GL_RGB, GL_UNSIGNED_BYTE, 0), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(image(GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, 0), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(image(GL_RGB, GL_RGB, GL_UNSIGNED_BYTE, 1), GLenum(GL_INVALID_VALUE));
}

}  // namespace
}  // namespace pineda::es1_test
