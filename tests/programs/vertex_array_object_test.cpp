// Vertex array objects (GL_ARB_vertex_array_object, GL 3.0 2.10) in a GL 2.1 context: names,
// errors, VERTEX_ARRAY_BINDING, what an object holds and what it does not, drawing from two
// objects, deleting the bound one, and a buffer deleted while another object refers to it.
#include <cstring>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class VertexArrayObjectTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    pixel_projection();
  }
  GLint get_int(GLenum pname) {
    GLint v = -12345;
    glGetIntegerv(pname, &v);
    return v;
  }
  GLenum error() { return glGetError(); }
  // Binds `vao` and gives it `quad` (4 vertices of 2 floats) in a new vertex buffer, enabled,
  // and the indices 0..3 in a new element array buffer; ARRAY_BUFFER is unbound after.
  void set_buffer_quad(GLuint vao, const float (&quad)[8], GLuint (&buffers)[2]) {
    static const GLubyte indices[4] = {0, 1, 2, 3};
    glGenBuffers(2, buffers);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, 0, nullptr);
    glEnableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
  }
};

TEST_F(VertexArrayObjectTest, IsAdvertised) {
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  ASSERT_NE(extensions, nullptr);
  EXPECT_NE(std::strstr(extensions, "GL_ARB_vertex_array_object "), nullptr);
}

TEST_F(VertexArrayObjectTest, GenBindIsDeleteAndTheirErrors) {
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), 0);
  EXPECT_EQ(glIsVertexArray(0), GL_FALSE);
  GLuint names[2] = {0, 0};
  glGenVertexArrays(2, names);
  EXPECT_NE(names[0], 0u);
  EXPECT_NE(names[1], 0u);
  EXPECT_NE(names[0], names[1]);
  // A generated name is an object only once bound.
  EXPECT_EQ(glIsVertexArray(names[0]), GL_FALSE);
  glBindVertexArray(names[0]);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(glIsVertexArray(names[0]), GL_TRUE);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), GLint(names[0]));
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_VERTEX_ARRAY_BINDING, &b);
  EXPECT_EQ(b, GL_TRUE);
  GLfloat f = 0;
  glGetFloatv(GL_VERTEX_ARRAY_BINDING, &f);
  EXPECT_EQ(f, float(names[0]));

  // A name never generated: INVALID_OPERATION, the binding unchanged.
  glBindVertexArray(names[1] + 100);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), GLint(names[0]));
  EXPECT_EQ(glIsVertexArray(names[1] + 100), GL_FALSE);

  glGenVertexArrays(-1, names);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glDeleteVertexArrays(-1, names);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(glIsVertexArray(names[0]), GL_TRUE);

  // Zero and unused names are ignored; deleting the bound object binds 0.
  const GLuint junk[3] = {0, 9999, names[0]};
  glDeleteVertexArrays(3, junk);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), 0);
  EXPECT_EQ(glIsVertexArray(names[0]), GL_FALSE);
  // A deleted name can no longer be bound.
  glBindVertexArray(names[0]);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  // A generated, never bound name can be deleted and is then gone too.
  glDeleteVertexArrays(1, &names[1]);
  glBindVertexArray(names[1]);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glBindVertexArray(0);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));

  // Not compiled into display lists: executed at once.
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindVertexArray(vao);
  glEndList();
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), GLint(vao));
  glBindVertexArray(0);
  glCallList(list);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), 0);
  // Inside Begin/End: INVALID_OPERATION.
  glBegin(GL_POINTS);
  glBindVertexArray(vao);
  glEnd();
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), 0);
}

TEST_F(VertexArrayObjectTest, StateIsolationBetweenTwoObjects) {
  static const float a_verts[8] = {}, b_verts[8] = {}, b_colors[16] = {}, attr[4] = {};
  GLuint buffers[3] = {};
  glGenBuffers(3, buffers);
  GLuint vaos[2] = {};
  glGenVertexArrays(2, vaos);

  glBindVertexArray(vaos[0]);
  glVertexPointer(2, GL_FLOAT, 0, a_verts);
  glEnableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[0]);
  glClientActiveTexture(GL_TEXTURE1);
  glTexCoordPointer(3, GL_SHORT, 6, a_verts);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexAttribPointer(3, 2, GL_UNSIGNED_BYTE, GL_TRUE, 0, attr);
  glEnableVertexAttribArray(3);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[2]);

  glBindVertexArray(vaos[1]);
  // A new object starts with the initial state; ARRAY_BUFFER_BINDING and CLIENT_ACTIVE_TEXTURE
  // are not in it.
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_FALSE);
  EXPECT_EQ(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), GLint(buffers[2]));
  EXPECT_EQ(get_int(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE1);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_SIZE), 4);
  GLvoid* p = reinterpret_cast<GLvoid*>(1);
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, nullptr);
  GLint v = -1;
  glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &v);
  EXPECT_EQ(v, GL_FALSE);
  glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_SIZE, &v);
  EXPECT_EQ(v, 4);

  glVertexPointer(3, GL_FLOAT, 12, b_verts);
  glColorPointer(4, GL_FLOAT, 0, b_colors);
  glEnableClientState(GL_COLOR_ARRAY);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glClientActiveTexture(GL_TEXTURE0);

  glBindVertexArray(vaos[0]);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_FALSE);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 2);
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, a_verts);
  EXPECT_EQ(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING), GLint(buffers[0]));
  EXPECT_EQ(get_int(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE0);  // not switched back
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), GLint(buffers[2]));
  glClientActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_TRUE);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_SIZE), 3);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_STRIDE), 6);
  glClientActiveTexture(GL_TEXTURE0);
  glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_TYPE, &v);
  EXPECT_EQ(v, GL_UNSIGNED_BYTE);
  glGetVertexAttribPointerv(3, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
  EXPECT_EQ(p, attr);

  glBindVertexArray(vaos[1]);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_STRIDE), 12);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_TRUE);
  glGetPointerv(GL_COLOR_ARRAY_POINTER, &p);
  EXPECT_EQ(p, b_colors);
  EXPECT_EQ(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING), GLint(buffers[1]));

  // The default object kept its own (initial) state.
  glBindVertexArray(0);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_FALSE);
  EXPECT_EQ(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

// Each object draws its own vertices and colours, from client memory and from buffers, with
// glDrawArrays and glDrawElements (its element array buffer).
TEST_F(VertexArrayObjectTest, DrawingFromTwoObjectsGivesEachOnesPixels) {
  // Object 1: a red quad on the left half from client arrays.
  static const float left[8] = {0, 0, 16, 0, 16, 32, 0, 32};
  static const float red[16] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  // Object 2: a green quad on the right half from a vertex buffer, drawn by indices in an
  // element array buffer.
  const float right[8] = {16, 0, 32, 0, 32, 32, 16, 32};
  GLuint vaos[2] = {};
  glGenVertexArrays(2, vaos);

  glBindVertexArray(vaos[0]);
  glVertexPointer(2, GL_FLOAT, 0, left);
  glColorPointer(4, GL_FLOAT, 0, red);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);

  GLuint buffers[2] = {};
  set_buffer_quad(vaos[1], right, buffers);
  glBindVertexArray(0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);  // object 0's binding: object 2 keeps its own

  clear_to(0, 0, 0, 0);
  glBindVertexArray(vaos[0]);
  glDrawArrays(GL_QUADS, 0, 4);
  glBindVertexArray(vaos[1]);
  glColor4f(0, 1, 0, 1);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(near_rgba(pixel(4, 4), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(28, 28), {0, 255, 0, 255}));
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 16 * 32);
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), (width() - 16) * 32 - (width() - 32) * 32);

  // glArrayElement and glDrawRangeElements read the bound object too.
  clear_to(0, 0, 0, 0);
  glBindVertexArray(vaos[0]);
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) glArrayElement(i);
  glEnd();
  glBindVertexArray(vaos[1]);
  glColor4f(0, 0, 1, 1);
  glDrawRangeElements(GL_QUADS, 0, 3, 4, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_TRUE(near_rgba(pixel(4, 4), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(28, 28), {0, 0, 255, 255}));

  // The default object has no array enabled: nothing is drawn from it.
  clear_to(0, 0, 0, 0);
  glBindVertexArray(0);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

TEST_F(VertexArrayObjectTest, GenericAttributeArraysDrawPerObject) {
  const GLuint p = link_in_use(
      "attribute vec2 pos; attribute vec4 col; varying vec4 c;"
      "void main() { gl_Position = gl_ModelViewProjectionMatrix * vec4(pos, 0.0, 1.0); c = col; }",
      "varying vec4 c; void main() { gl_FragColor = c; }", {{0, "pos"}, {2, "col"}});
  static const float quad[8] = {0, 0, 32, 0, 32, 32, 0, 32};
  static const GLubyte yellow[16] = {255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 255};
  static const GLubyte cyan[16] = {0, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255};
  GLuint vaos[2] = {};
  glGenVertexArrays(2, vaos);
  for (int i = 0; i < 2; ++i) {
    glBindVertexArray(vaos[i]);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, quad);  // attribute 0 provokes vertices
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, i == 0 ? yellow : cyan);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(2);
  }
  glBindVertexArray(vaos[0]);
  clear_to(0, 0, 0, 0);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_TRUE(near_rgba(pixel(10, 10), {255, 255, 0, 255}));
  glBindVertexArray(vaos[1]);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_TRUE(near_rgba(pixel(10, 10), {0, 255, 255, 255}));
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  glUseProgram(0);
  glDeleteProgram(p);
}

TEST_F(VertexArrayObjectTest, DeletingTheBoundObjectRevertsToTheDefaultOnesState) {
  static const float verts[8] = {0, 0, 8, 0, 8, 8, 0, 8};
  glVertexPointer(2, GL_FLOAT, 0, verts);  // object 0's
  glEnableClientState(GL_VERTEX_ARRAY);
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(4, GL_SHORT, 0, nullptr);
  glDeleteVertexArrays(1, &vao);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), 0);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_FALSE);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 2);
  GLvoid* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, verts);
  clear_to(0, 0, 0, 0);
  glColor4f(1, 1, 1, 1);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 64);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

// GL 3.0: deleting a buffer unbinds it from the bound object only; another object that refers
// to it still draws (its store stays alive) and nothing reads freed memory (ASan).
TEST_F(VertexArrayObjectTest, BufferDeletedWhileAnotherObjectRefersToIt) {
  const float quad[8] = {0, 0, 8, 0, 8, 8, 0, 8};
  GLuint vaos[2] = {};
  glGenVertexArrays(2, vaos);
  GLuint buffers[2] = {};
  set_buffer_quad(vaos[0], quad, buffers);

  glBindVertexArray(vaos[1]);
  glDeleteBuffers(2, buffers);
  EXPECT_EQ(glIsBuffer(buffers[0]), GL_FALSE);

  glBindVertexArray(vaos[0]);
  clear_to(0, 0, 0, 0);
  glColor4f(1, 1, 1, 1);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, nullptr);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 64);
  glDeleteVertexArrays(2, vaos);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

// glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT) saves the bound object and its arrays; the pop
// binds it again (as Mesa does).
TEST_F(VertexArrayObjectTest, ClientAttribStackSavesTheBinding) {
  static const float verts[8] = {};
  GLuint vaos[2] = {};
  glGenVertexArrays(2, vaos);
  glBindVertexArray(vaos[0]);
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glBindVertexArray(vaos[1]);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), GLint(vaos[0]));
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 2);
  // Only the pixel store group: the binding stays.
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glBindVertexArray(vaos[1]);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), GLint(vaos[1]));
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
