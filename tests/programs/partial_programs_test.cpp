// Programs with one stage (the other stage is fixed function), two-sided colours and flat
// shading of the colour varyings (GL 2.0 2.15, 2.14.7, 3.11).
#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class PartialProgramsTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    clear_to(0, 0, 0, 0);
  }
  void use(GLuint p) {
    ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
    glUseProgram(p);
  }
  void triangle(float x0, float y0, float x1, float y1, float x2, float y2) {
    glBegin(GL_TRIANGLES);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glVertex2f(x2, y2);
    glEnd();
  }
};

TEST_F(PartialProgramsTest, VertexShaderOnlyFeedsTheFixedFunctionFragmentStage) {
  use(link("void main() { gl_Position = gl_Vertex; gl_FrontColor = vec4(0.0, 1.0, 0.0, 0.5); }\n", nullptr));
  glColor3f(1, 0, 0);  // replaced by the shader's colour
  triangle(-1, -1, 3, -1, -1, 3);
  EXPECT_EQ(count_pixels({0, 255, 0, 128}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PartialProgramsTest, VertexShaderOnlyTexCoordsReachFixedFunctionTexturing) {
  const GLubyte texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
  glBindTexture(GL_TEXTURE_2D, 3);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  use(link("void main() { gl_Position = gl_Vertex; gl_TexCoord[0] = vec4(gl_Vertex.xy * 0.5 + 0.5, 0.0, 1.0); }\n",
           nullptr));
  triangle(-1, -1, 3, -1, -1, 3);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(28, 3), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(3, 28), {0, 0, 255, 255}));
}

TEST_F(PartialProgramsTest, FragmentShaderOnlyReadsTheFixedFunctionVaryings) {
  use(link(nullptr, "void main() { gl_FragColor = vec4(gl_Color.b, gl_Color.g, gl_TexCoord[1].x, gl_Color.a); }\n"));
  glColor4f(0.2f, 0.4f, 0.6f, 1.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.8f, 0.f);
  triangle(-1, -1, 3, -1, -1, 3);
  EXPECT_EQ(count_pixels({153, 102, 204, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PartialProgramsTest, TwoSidedColoursFollowVertexProgramTwoSide) {
  use(link("void main() { gl_Position = gl_Vertex; gl_FrontColor = vec4(1.0, 0.0, 0.0, 1.0);\n"
           "  gl_BackColor = vec4(0.0, 0.0, 1.0, 1.0); }\n",
           "void main() { gl_FragColor = gl_Color; }\n"));
  triangle(-1, -1, -1, 1, 1, -1);  // clockwise: back-facing
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));  // disabled: the front colour
  glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
  triangle(-1, -1, -1, 1, 1, -1);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {0, 0, 255, 255}));
  triangle(-1, -1, 1, -1, -1, 1);  // front-facing
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));
}

TEST_F(PartialProgramsTest, FlatShadingTakesTheProvokingVertexColour) {
  use(link("void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; }\n",
           "void main() { gl_FragColor = gl_Color; }\n"));
  glShadeModel(GL_FLAT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(-1, -1);
  glColor3f(0, 1, 0);
  glVertex2f(3, -1);
  glColor3f(0, 0, 1);  // the last vertex of an independent triangle provokes
  glVertex2f(-1, 3);
  glEnd();
  EXPECT_EQ(count_pixels({0, 0, 255, 255}), width() * height());
}

}  // namespace
}  // namespace pineda::test
