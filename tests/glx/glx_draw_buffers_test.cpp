// glDrawBuffers (GL 2.0) on a double-buffered window: the front left and back left buffers can
// each be selected alone or together; fixed-function colour goes to every selected buffer, with
// one depth test.
#include "glx_fixture.h"

#include <GL/glext.h>

namespace pineda_test {
namespace {

constexpr uint32_t kRed = 0xff0000, kGreen = 0x00ff00, kBlue = 0x0000ff, kGrey = 0x333333;

using DrawBuffersFn = void (*)(GLsizei, const GLenum*);

class GlxDrawBuffersTest : public GlxTest {
 protected:
  void make_current(bool depth_stencil) {
    GLXFBConfig config = rgba8(true, depth_stencil);
    ASSERT_NE(config, nullptr);
    Window w = window(config, 20, 20);
    ASSERT_TRUE(glXMakeCurrent(dpy, w, context(config)));
    glViewport(0, 0, 20, 20);
    draw_buffers = reinterpret_cast<DrawBuffersFn>(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glDrawBuffers")));
    ASSERT_NE(draw_buffers, nullptr);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 20, 0, 20, -1, 1);
  }
  static uint32_t read_from(GLenum buffer, int x, int y) {
    glReadBuffer(buffer);
    return gl_pixel(x, y);
  }
  static void clear_both(float r, float g, float b) {
    glDrawBuffer(GL_FRONT_AND_BACK);
    glClearColor(r, g, b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  // The bottom-left 10x10 pixels at normalized device depth z.
  static void corner_quad(float r, float g, float b, float z) {
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex3f(0, 0, -z);
    glVertex3f(10, 0, -z);
    glVertex3f(10, 10, -z);
    glVertex3f(0, 10, -z);
    glEnd();
  }
  DrawBuffersFn draw_buffers = nullptr;
};

TEST_F(GlxDrawBuffersTest, EachBufferAloneOrBoth) {
  make_current(false);
  clear_both(0.2f, 0.2f, 0.2f);
  const GLenum back_only[] = {GL_BACK_LEFT};
  draw_buffers(1, back_only);
  corner_quad(1, 0, 0, 0);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kGrey);
  const GLenum front_second[] = {GL_NONE, GL_FRONT_LEFT};
  draw_buffers(2, front_second);
  corner_quad(0, 1, 0, 0);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kGreen);
  const GLenum both[] = {GL_BACK_LEFT, GL_FRONT_LEFT};
  draw_buffers(2, both);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kBlue);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kBlue);
  GLint v[2] = {};
  glGetIntegerv(GL_DRAW_BUFFER0, &v[0]);
  glGetIntegerv(GL_DRAW_BUFFER1, &v[1]);
  EXPECT_EQ(v[0], GL_BACK_LEFT);
  EXPECT_EQ(v[1], GL_FRONT_LEFT);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlxDrawBuffersTest, BothBuffersShareOneDepthTest) {
  make_current(true);
  clear_both(0.2f, 0.2f, 0.2f);
  glClearDepth(1);
  glClear(GL_DEPTH_BUFFER_BIT);
  const GLenum both[] = {GL_FRONT_LEFT, GL_BACK_LEFT};
  draw_buffers(2, both);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  corner_quad(1, 0, 0, 0.5f);
  corner_quad(0, 0, 1, 0.5f);  // same depth: fails in both buffers
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_BACK, 15, 15), kGrey);
  corner_quad(0, 1, 0, 0.f);  // nearer: drawn in both
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kGreen);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kGreen);
  float depth = 0;
  glReadPixels(5, 5, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_NEAR(depth, 0.5f, 1e-6f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlxDrawBuffersTest, BackLeftIsValidAndNamedOnce) {
  make_current(false);
  const GLenum twice[] = {GL_BACK_LEFT, GL_BACK_LEFT};
  draw_buffers(2, twice);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  const GLenum back[] = {GL_BACK};
  draw_buffers(1, back);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  const GLenum back_right[] = {GL_BACK_RIGHT};
  draw_buffers(1, back_right);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  GLint v = 0;
  glGetIntegerv(GL_DRAW_BUFFER0, &v);
  EXPECT_EQ(v, GL_BACK);
}

// A fragment shader's gl_FragData[i] goes to the buffer DRAW_BUFFERi selects.
TEST_F(GlxDrawBuffersTest, FragDataGoesToItsDrawBuffer) {
  make_current(false);
  clear_both(0.2f, 0.2f, 0.2f);
  auto proc = [](const char* name) { return glXGetProcAddress(reinterpret_cast<const GLubyte*>(name)); };
  auto create_shader = reinterpret_cast<PFNGLCREATESHADERPROC>(proc("glCreateShader"));
  auto shader_source = reinterpret_cast<PFNGLSHADERSOURCEPROC>(proc("glShaderSource"));
  auto compile_shader = reinterpret_cast<PFNGLCOMPILESHADERPROC>(proc("glCompileShader"));
  auto create_program = reinterpret_cast<PFNGLCREATEPROGRAMPROC>(proc("glCreateProgram"));
  auto attach_shader = reinterpret_cast<PFNGLATTACHSHADERPROC>(proc("glAttachShader"));
  auto link_program = reinterpret_cast<PFNGLLINKPROGRAMPROC>(proc("glLinkProgram"));
  auto use_program = reinterpret_cast<PFNGLUSEPROGRAMPROC>(proc("glUseProgram"));
  const char* vs = "void main() { gl_Position = ftransform(); }";
  const char* fs = "void main() { gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0); gl_FragData[1] = vec4(0.0, 1.0, 0.0, 1.0); }";
  const GLuint v = create_shader(GL_VERTEX_SHADER), f = create_shader(GL_FRAGMENT_SHADER);
  shader_source(v, 1, &vs, nullptr);
  shader_source(f, 1, &fs, nullptr);
  compile_shader(v);
  compile_shader(f);
  const GLuint program = create_program();
  attach_shader(program, v);
  attach_shader(program, f);
  link_program(program);
  use_program(program);
  const GLenum front_then_back[] = {GL_FRONT_LEFT, GL_BACK_LEFT};
  draw_buffers(2, front_then_back);
  corner_quad(1, 1, 1, 0);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kGreen);
  EXPECT_EQ(read_from(GL_BACK, 15, 15), kGrey);
  const GLenum back_only_second[] = {GL_NONE, GL_BACK_LEFT};
  draw_buffers(2, back_only_second);
  clear_both(0.2f, 0.2f, 0.2f);
  draw_buffers(2, back_only_second);
  corner_quad(1, 1, 1, 0);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kGreen);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kGrey);
  use_program(0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// glCopyPixels into both buffers from the back one, moving up by two rows: the front gets the
// back's original rows too (the back is copied first, so the copy into the front cannot read
// rows the back's pass already overwrote).
TEST_F(GlxDrawBuffersTest, CopyPixelsIntoBothBuffersCopiesTheOriginalRows) {
  make_current(false);
  clear_both(0.2f, 0.2f, 0.2f);
  glDrawBuffer(GL_BACK);
  corner_quad(1, 0, 0, 0);  // rows 0-9 red...
  glColor3f(0, 1, 0);
  glRecti(0, 0, 10, 3);  // ...but for rows 0-2, green
  glReadBuffer(GL_BACK);
  glDrawBuffer(GL_FRONT_AND_BACK);
  glRasterPos2i(0, 2);
  glCopyPixels(0, 0, 10, 10, GL_COLOR);
  for (GLenum buffer : {GL_BACK, GL_FRONT}) {
    for (int y : {2, 3, 4}) EXPECT_EQ(read_from(buffer, 5, y), kGreen) << buffer << " row " << y;
    for (int y : {5, 6, 11}) EXPECT_EQ(read_from(buffer, 5, y), kRed) << buffer << " row " << y;
    EXPECT_EQ(read_from(buffer, 5, 12), kGrey) << buffer;
  }
  EXPECT_EQ(read_from(GL_BACK, 5, 1), kGreen);
  EXPECT_EQ(read_from(GL_FRONT, 5, 1), kGrey);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The same copy into the back buffer alone reads its rows as it draws them, from a window's
// BGRA8 rows: the colours come through with red and blue in place.
TEST_F(GlxDrawBuffersTest, CopyPixelsIntoTheBackBufferKeepsRedAndBlue) {
  make_current(false);
  clear_both(0.2f, 0.2f, 0.2f);
  glDrawBuffer(GL_BACK);
  corner_quad(1, 0, 0, 0);
  glColor3f(0, 0, 1);
  glRecti(0, 0, 10, 3);
  glReadBuffer(GL_BACK);
  glRasterPos2i(0, 2);
  glCopyPixels(0, 0, 10, 10, GL_COLOR);
  for (int y : {2, 3, 4}) EXPECT_EQ(read_from(GL_BACK, 5, y), kBlue) << "row " << y;
  for (int y : {5, 6, 11}) EXPECT_EQ(read_from(GL_BACK, 5, y), kRed) << "row " << y;
  EXPECT_EQ(read_from(GL_BACK, 5, 12), kGrey);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kGrey);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda_test
