// gl_FrontMaterial in a vertex shader is the material in effect at glBegin: glMaterial calls
// between glBegin and glEnd light fixed-function vertices only (as Mesa; piglit
// gl-2.0-shader-materials).
#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

using MaterialAtBeginTest = ProgramTest;

TEST_F(MaterialAtBeginTest, ShadersIgnoreMaterialsSetInsideThePrimitive) {
  const GLuint p = link(
      "void main() { gl_FrontColor = gl_FrontMaterial.ambient + gl_FrontMaterial.diffuse; gl_Position = gl_Vertex; }\n",
      nullptr);
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  const float ambient[4] = {0.f, 0.4f, 0.f, 1.f}, diffuse[4] = {0.f, 0.2f, 0.6f, 0.f}, red[4] = {1, 0, 0, 1};
  const GLuint list = glGenLists(1);
  for (bool in_list : {false, true}) {
    clear_to(0, 0, 0, 0);
    if (in_list) glNewList(list, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glBegin(GL_TRIANGLE_FAN);
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corners) {
      glMaterialfv(GL_FRONT, GL_AMBIENT, red);  // before the first vertex too
      glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
      glVertex2fv(c);
    }
    glEnd();
    if (in_list) {
      glEndList();
      glCallList(list);
    }
    EXPECT_EQ(pixel(5, 5), (Rgba{0, 153, 153, 255})) << (in_list ? "display list" : "immediate");
    float after[4];
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, after);  // the last value set is current after glEnd
    EXPECT_EQ(after[0], 1.f);
  }
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
