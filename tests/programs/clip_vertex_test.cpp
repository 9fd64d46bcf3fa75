// User clip planes with shaders (GL 2.0 2.12, GLSL 1.10 7.1): a vertex shader's gl_ClipVertex
// is tested against the eye-space planes; without it gl_Position is (as Mesa); a program with
// only a fragment shader clips as fixed function does.
#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

constexpr const char* kRed = "void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }";

class ClipVertexTest : public ProgramTest {
 protected:
  // Clears to black, draws the viewport-filling quad with `program` and the plane x >= 0
  // (in eye coordinates, the modelview being the identity) enabled.
  void draw_with_plane(GLuint program) {
    ASSERT_EQ(program_int(program, GL_LINK_STATUS), GL_TRUE) << program_log(program);
    glUseProgram(program);
    const GLdouble keep_positive_x[4] = {1, 0, 0, 0};
    glClipPlane(GL_CLIP_PLANE0, keep_positive_x);
    glEnable(GL_CLIP_PLANE0);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);
    glEnd();
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  int red_pixels_left() { return red_pixels_in(0, width() / 2); }
  int red_pixels_right() { return red_pixels_in(width() / 2, width()); }
  int half() const { return width() / 2 * height(); }

 private:
  int red_pixels_in(int x0, int x1) {
    const std::vector<uint8_t> all = read_all();
    int n = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = x0; x < x1; ++x) {
        const uint8_t* p = &all[(static_cast<size_t>(y) * width() + x) * 4];
        n += p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255;
      }
    return n;
  }
};

TEST_F(ClipVertexTest, ThePlanesTestGlClipVertex) {
  // gl_ClipVertex mirrors x: the plane keeps what is on the left of the window.
  draw_with_plane(link("void main() { gl_Position = gl_Vertex; gl_ClipVertex = gl_Vertex * vec4(-1, 1, 1, 1); }",
                       kRed));
  EXPECT_EQ(red_pixels_left(), half());
  EXPECT_EQ(red_pixels_right(), 0);
}

TEST_F(ClipVertexTest, WithoutGlClipVertexThePlanesTestThePosition) {
  draw_with_plane(link("void main() { gl_Position = gl_Vertex; }", kRed));
  EXPECT_EQ(red_pixels_left(), 0);
  EXPECT_EQ(red_pixels_right(), half());
}

TEST_F(ClipVertexTest, AFragmentShaderAloneClipsAsFixedFunction) {
  draw_with_plane(link(nullptr, kRed));
  EXPECT_EQ(red_pixels_left(), 0);
  EXPECT_EQ(red_pixels_right(), half());
}

TEST_F(ClipVertexTest, ADisabledPlaneDoesNotClip) {
  const GLuint program = link("void main() { gl_Position = gl_Vertex; gl_ClipVertex = vec4(-1.0); }", kRed);
  draw_with_plane(program);
  EXPECT_EQ(red_pixels_left() + red_pixels_right(), 0);  // every vertex outside: all clipped
  glDisable(GL_CLIP_PLANE0);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);
  glEnd();
  EXPECT_EQ(red_pixels_left() + red_pixels_right(), 2 * half());
}

}  // namespace
}  // namespace pineda::test
