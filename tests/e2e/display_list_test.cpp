// Display lists draw what the same calls draw in immediate mode; arrays and images are
// read when the list is compiled.
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class DisplayListTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
  void scene() {
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex2f(1, 1);
    glColor3f(0, 1, 0);
    glVertex2f(30, 3);
    glColor3f(0, 0, 1);
    glVertex2f(12, 29);
    glEnd();
    glColor4f(1, 1, 0, 1);
    glRectf(20, 20, 28.5f, 30);
  }
};

TEST_F(DisplayListTest, ListDrawsWhatImmediateModeDraws) {
  scene();
  const auto reference = read_all();
  clear_to(0, 0, 0, 0);
  glNewList(1, GL_COMPILE);
  scene();
  glEndList();
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());  // GL_COMPILE draws nothing
  glCallList(1);
  EXPECT_EQ(read_all(), reference);
  clear_to(0, 0, 0, 0);
  glNewList(2, GL_COMPILE_AND_EXECUTE);
  scene();
  glEndList();
  EXPECT_EQ(read_all(), reference);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Each command of a list changes the state for the commands after it, draws of an otherwise
// unchanged state included (a draw keeps what it worked out from the state while no call changes
// it: a list's commands count as calls).
TEST_F(DisplayListTest, CommandsBetweenDrawsOfAListChangeTheDrawsAfterThem) {
  static const GLfloat kSquare[] = {0, 0, 8, 0, 8, 8, 0, 8};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kSquare);
  glColor3f(1, 1, 1);
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glTranslatef(16, 0, 0);
  glDrawArrays(GL_QUADS, 0, 4);
  glColor3f(1, 0, 0);
  glDrawArrays(GL_QUADS, 0, 4);  // over the second square, red
  glEndList();
  glCallList(1);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 8 * 8);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 8 * 8);
  EXPECT_TRUE(near_rgba(pixel(4, 4), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(20, 4), {255, 0, 0, 255}));
  // After the list, the state it left: a draw of the square lands at x 16 and is red.
  clear_to(0, 0, 0, 0);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 8 * 8);
  EXPECT_TRUE(near_rgba(pixel(20, 4), {255, 0, 0, 255}));
}

TEST_F(DisplayListTest, ArraysAreReadAtCompileTime) {
  GLfloat vertices[8] = {0, 0, 8, 0, 8, 8, 0, 8};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glColor3f(1, 1, 1);
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glEndList();
  for (GLfloat& v : vertices) v += 16;  // moving the array afterwards does not change the list
  glCallList(1);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 64);
  EXPECT_TRUE(near_rgba(pixel(4, 4), {255, 255, 255, 255}));
}

TEST_F(DisplayListTest, TextureImagesAreReadAtCompileTime) {
  uint8_t texel[4] = {0, 0, 255, 255};
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glNewList(1, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glEndList();
  texel[0] = 255;
  glCallList(1);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0.5f, 0.5f);
  glVertex2i(0, 0);
  glVertex2i(4, 0);
  glVertex2i(4, 4);
  glVertex2i(0, 4);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(1, 1), {0, 0, 255, 255}));
}

// glCallList and glCallLists may stand between glBegin and glEnd, also inside a list.
TEST_F(DisplayListTest, CompiledCallListsBetweenBeginAndEnd) {
  glNewList(5, GL_COMPILE);
  glVertex2f(3.5f, 3.5f);
  glEndList();
  const GLuint names[1] = {5};
  glNewList(6, GL_COMPILE);
  glBegin(GL_POINTS);
  glCallLists(1, GL_UNSIGNED_INT, names);
  glEnd();
  glEndList();
  glColor3f(1, 1, 1);
  glCallList(6);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 1);
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 255, 255, 255}));
}

// Mesa compiles the scalar glTexParameter forms as vector ones with (param, 0, 0, 0), so in a
// list the border colour takes them; outside a list it does not (INVALID_ENUM).
TEST_F(DisplayListTest, ScalarBorderColourIsAVectorInAList) {
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glNewList(7, GL_COMPILE_AND_EXECUTE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLfloat border[4] = {9, 9, 9, 9};
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  EXPECT_EQ(border[0], 0.5f);
  EXPECT_EQ(border[1], 0.f);
  const GLfloat zero[4] = {0, 0, 0, 0};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, zero);
  glNewList(8, GL_COMPILE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1);
  glEndList();
  glCallList(8);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  EXPECT_EQ(border[0], 1.f);
  EXPECT_EQ(border[3], 0.f);
  glBegin(GL_POINTS);
  glCallList(8);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

}  // namespace
}  // namespace pineda::test
