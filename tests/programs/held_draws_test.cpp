// Consecutive glDrawArrays and glDrawElements calls of GL_TRIANGLES with nothing changed
// between them are held back and run as one draw (state/vertex_arrays/held_draws.h): the pixels,
// depths, query counts and errors are those of the calls run one at a time, and held draws run
// before whatever follows them (a uniform, new buffer contents) and never read client memory
// after their call.
#include <cstdint>
#include <random>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class HeldDrawsTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    program_ = link_in_use("attribute vec3 pos; attribute vec4 shade; varying vec4 v_shade;\n"
                           "void main() { v_shade = shade; gl_Position = vec4(pos, 1.0); }\n",
                           "uniform vec4 tint; varying vec4 v_shade; void main() { gl_FragColor = v_shade * tint; }\n",
                           {{0, "pos"}, {1, "shade"}});
    tint_ = glGetUniformLocation(program_, "tint");
    glUniform4f(tint_, 1, 1, 1, 1);
    glGenBuffers(1, &buffer_);
    clear();
  }
  void TearDown() override {
    glDeleteBuffers(1, &buffer_);
    ProgramTest::TearDown();
  }

  void clear() {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  // Vertices (x, y, z, then r, g, b, a) into the buffer, read through attributes 0 and 1.
  void use_buffer(const std::vector<GLfloat>& vertices) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(GLfloat)), vertices.data(), GL_STATIC_DRAW);
    point_at(nullptr);
  }
  // The attributes at `base` (an offset into the bound buffer, or client memory).
  static void point_at(const GLfloat* base) {
    // Integer arithmetic: the buffer's offset 0 is a null pointer, which C++ forbids offsetting.
    const auto at = [base](size_t floats) {
      return reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(base) + floats * sizeof(GLfloat));
    };
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(GLfloat), at(0));
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(GLfloat), at(3));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
  }
  // A triangle in normalized coordinates: the corner (x, y), `size` wide and high.
  static void add_triangle(std::vector<GLfloat>& out, float x, float y, float size, float z, const float rgba[4]) {
    for (const auto& c : {std::pair{0.f, 0.f}, std::pair{size, 0.f}, std::pair{0.f, size}}) {
      out.insert(out.end(), {x + c.first, y + c.second, z});
      out.insert(out.end(), rgba, rgba + 4);
    }
  }
  // `count` triangles of random places, sizes, depths and colours.
  static std::vector<GLfloat> random_triangles(int count) {
    std::mt19937 rng(54);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    std::vector<GLfloat> out;
    for (int i = 0; i < count; ++i) {
      const float rgba[4] = {unit(rng), unit(rng), unit(rng), 1.f};
      add_triangle(out, unit(rng) * 2.2f - 1.2f, unit(rng) * 2.2f - 1.2f, 0.02f + 0.3f * unit(rng), unit(rng) * 1.8f - 0.9f,
                   rgba);
    }
    return out;
  }
  // Triangle t of the buffer: glDrawArrays, or with `indexed` glDrawElements of its three
  // vertices named from the second on.
  static void draw_triangle(int t, bool indexed) {
    if (!indexed) return glDrawArrays(GL_TRIANGLES, 3 * t, 3);
    const GLushort indices[3] = {GLushort(3 * t + 1), GLushort(3 * t + 2), GLushort(3 * t)};
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices);
  }
  // A query that is not a draw between each two: every draw runs at its call.
  static void draw_each_at_once(int triangles, bool indexed = false) {
    for (int t = 0; t < triangles; ++t) {
      draw_triangle(t, indexed);
      GLint viewport[4];
      glGetIntegerv(GL_VIEWPORT, viewport);
    }
  }
  static void draw_each(int triangles, bool indexed = false) {
    for (int t = 0; t < triangles; ++t) draw_triangle(t, indexed);
  }
  // The triangles of the buffer, depth-tested, drawn a call each: held back, and each run at its
  // call, give the same pixels and depths, most of the window drawn. Returns the held ones'.
  ColourAndDepth expect_held_as_at_once(int triangles, bool indexed = false) {
    glEnable(GL_DEPTH_TEST);
    draw_each_at_once(triangles, indexed);
    const ColourAndDepth at_once = read_colour_and_depth();
    clear();
    draw_each(triangles, indexed);
    ColourAndDepth held = read_colour_and_depth();
    EXPECT_EQ(held.colour, at_once.colour);
    EXPECT_EQ(held.depth, at_once.depth);
    int drawn = 0;
    for (size_t i = 3; i < held.colour.size(); i += 4) drawn += held.colour[i] == 255;
    EXPECT_GT(drawn, width() * height() / 4);
    return held;
  }
  // Pixel (x, y) of the window at normalized coordinates.
  Rgba at(float x, float y) { return pixel(int((x + 1) * 0.5f * width()), int((y + 1) * 0.5f * height())); }

  GLuint program_ = 0, buffer_ = 0;
  GLint tint_ = -1;
};

constexpr float kHeldRed[4] = {1, 0, 0, 1}, kHeldGreen[4] = {0, 1, 0, 1}, kHeldBlue[4] = {0, 0, 1, 1};

TEST_F(HeldDrawsTest, ManyDrawsGiveThePixelsAndDepthsOfDrawsRunOneAtATime) {
  constexpr int kTriangles = 600;
  use_buffer(random_triangles(kTriangles));
  const ColourAndDepth held = expect_held_as_at_once(kTriangles);
  clear();
  glDrawArrays(GL_TRIANGLES, 0, 3 * kTriangles);
  const ColourAndDepth one_draw = read_colour_and_depth();
  EXPECT_EQ(one_draw.colour, held.colour);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(HeldDrawsTest, FixedFunctionDrawsGiveThePixelsOfDrawsRunOneAtATime) {
  constexpr int kTriangles = 600;
  glUseProgram(0);
  use_buffer(random_triangles(kTriangles));
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(1);
  glVertexPointer(3, GL_FLOAT, 7 * sizeof(GLfloat), nullptr);
  glColorPointer(4, GL_FLOAT, 7 * sizeof(GLfloat), reinterpret_cast<const void*>(3 * sizeof(GLfloat)));
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  expect_held_as_at_once(kTriangles);
}

TEST_F(HeldDrawsTest, IndexedDrawsGiveThePixelsOfDrawsRunOneAtATime) {
  constexpr int kTriangles = 600;
  use_buffer(random_triangles(kTriangles));
  expect_held_as_at_once(kTriangles, true);
}

// Held array and indexed draws run in their calls' order: the later one's colour shows where
// they overlap.
TEST_F(HeldDrawsTest, HeldArrayAndIndexedDrawsKeepTheirOrder) {
  std::vector<GLfloat> vertices;
  add_triangle(vertices, -1.f, -1.f, 0.5f, 0.f, kHeldBlue);  // runs at its call
  add_triangle(vertices, -0.8f, 0.f, 1.f, 0.f, kHeldRed);
  add_triangle(vertices, -0.5f, 0.f, 1.f, 0.f, kHeldGreen);
  use_buffer(vertices);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  draw_triangle(1, true);
  glDrawArrays(GL_TRIANGLES, 6, 3);
  draw_triangle(1, true);
  EXPECT_EQ(at(-0.9f, -0.9f), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(at(-0.45f, 0.1f), (Rgba{255, 0, 0, 255}));  // the last draw's
  EXPECT_EQ(at(0.3f, 0.1f), (Rgba{0, 255, 0, 255}));
}

// The second red triangle is held back when the tint changes: it stays red, and the green one
// drawn after it covers it where they overlap.
TEST_F(HeldDrawsTest, HeldDrawsRunBeforeTheNextCall) {
  std::vector<GLfloat> vertices;
  add_triangle(vertices, -1.f, -1.f, 1.f, 0.f, kHeldBlue);   // runs at its call
  add_triangle(vertices, -0.8f, 0.f, 1.f, 0.f, kHeldRed);    // held back
  add_triangle(vertices, -0.5f, 0.f, 1.f, 0.f, kHeldRed);    // after the tint: green
  use_buffer(vertices);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDrawArrays(GL_TRIANGLES, 3, 3);
  glUniform4f(tint_, 0, 1, 1, 1);  // red becomes black, blue stays blue
  glDrawArrays(GL_TRIANGLES, 6, 3);
  EXPECT_EQ(at(-0.9f, -0.9f), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(at(-0.75f, 0.1f), (Rgba{255, 0, 0, 255}));  // the held triangle alone
  EXPECT_EQ(at(-0.45f, 0.1f), (Rgba{0, 0, 0, 255}));    // both: the later, tinted one
  EXPECT_EQ(at(0.3f, 0.1f), (Rgba{0, 0, 0, 255}));      // the tinted one alone
  EXPECT_EQ(at(0.6f, 0.6f), (Rgba{0, 0, 0, 0}));        // none
}

// A draw that is not held (a triangle fan) runs after the held ones: where it overlaps the held
// red triangle, its green shows.
TEST_F(HeldDrawsTest, HeldDrawsRunBeforeTheNextDrawOfAnotherKind) {
  std::vector<GLfloat> vertices;
  add_triangle(vertices, -1.f, -1.f, 0.5f, 0.f, kHeldBlue);
  add_triangle(vertices, -0.8f, 0.f, 1.f, 0.f, kHeldRed);
  add_triangle(vertices, -0.5f, 0.f, 1.f, 0.f, kHeldGreen);
  use_buffer(vertices);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDrawArrays(GL_TRIANGLES, 3, 3);
  glDrawArrays(GL_TRIANGLE_FAN, 6, 3);
  EXPECT_EQ(at(-0.75f, 0.1f), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(at(-0.45f, 0.1f), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(at(0.3f, 0.1f), (Rgba{0, 255, 0, 255}));
}

TEST_F(HeldDrawsTest, HeldDrawsReadTheBufferAsItWasAtTheirCall) {
  std::vector<GLfloat> vertices;
  add_triangle(vertices, -1.f, -1.f, 0.5f, 0.f, kHeldBlue);
  add_triangle(vertices, -1.f, 0.f, 0.5f, 0.f, kHeldGreen);  // held back, then moved right
  use_buffer(vertices);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDrawArrays(GL_TRIANGLES, 3, 3);
  std::vector<GLfloat> moved;
  add_triangle(moved, 0.f, 0.f, 0.5f, 0.f, kHeldRed);
  glBufferSubData(GL_ARRAY_BUFFER, GLintptr(21 * sizeof(GLfloat)), GLsizeiptr(moved.size() * sizeof(GLfloat)), moved.data());
  glFinish();
  EXPECT_EQ(at(-0.9f, -0.9f), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(at(-0.9f, 0.1f), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(at(0.1f, 0.1f), (Rgba{0, 0, 0, 0}));
}

// Client memory may change after a call without a GL call between: such draws run at their call.
TEST_F(HeldDrawsTest, DrawsFromClientMemoryReadItAtTheirCall) {
  std::vector<GLfloat> vertices;
  add_triangle(vertices, -1.f, -1.f, 0.5f, 0.f, kHeldBlue);
  add_triangle(vertices, -1.f, 0.f, 0.5f, 0.f, kHeldGreen);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  point_at(vertices.data());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDrawArrays(GL_TRIANGLES, 3, 3);
  std::vector<GLfloat> moved;
  add_triangle(moved, 0.f, 0.f, 0.5f, 0.f, kHeldRed);
  std::copy(moved.begin(), moved.end(), vertices.begin() + 21);
  glFinish();
  EXPECT_EQ(at(-0.9f, -0.9f), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(at(-0.9f, 0.1f), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(at(0.1f, 0.1f), (Rgba{0, 0, 0, 0}));
}

TEST_F(HeldDrawsTest, AnOcclusionQueryCountsHeldDraws) {
  constexpr int kTriangles = 200;
  use_buffer(random_triangles(kTriangles));
  GLuint queries[2];
  glGenQueries(2, queries);
  glBeginQuery(GL_SAMPLES_PASSED, queries[0]);
  draw_each_at_once(kTriangles);
  glEndQuery(GL_SAMPLES_PASSED);
  clear();
  glBeginQuery(GL_SAMPLES_PASSED, queries[1]);
  draw_each(kTriangles);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint at_once = 0, held = 0;
  glGetQueryObjectuiv(queries[0], GL_QUERY_RESULT, &at_once);
  glGetQueryObjectuiv(queries[1], GL_QUERY_RESULT, &held);
  EXPECT_EQ(held, at_once);
  EXPECT_GT(held, GLuint(width() * height() / 4));
  glDeleteQueries(2, queries);
}

// A draw that records an error is not followed by held draws: each call records its own.
TEST_F(HeldDrawsTest, EveryCallOfAnInvalidDrawRecordsItsError) {
  const GLuint conflict = link("attribute vec3 pos; void main() { gl_Position = vec4(pos, 1.0); }\n",
                               "uniform sampler2D a; uniform samplerCube b;\n"
                               "void main() { gl_FragColor = texture2D(a, vec2(0.5)) + textureCube(b, vec3(1.0, 0.0, 0.0)); }\n");
  ASSERT_EQ(program_int(conflict, GL_LINK_STATUS), GL_TRUE) << program_log(conflict);
  glUseProgram(conflict);  // both samplers on unit 0
  std::vector<GLfloat> vertices;
  add_triangle(vertices, -1.f, -1.f, 0.5f, 0.f, kHeldBlue);
  use_buffer(vertices);
  for (int call = 0; call < 3; ++call) {
    glDrawArrays(GL_TRIANGLES, 0, 3);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION)) << "call " << call;
  }
  glDeleteProgram(conflict);
}

}  // namespace
}  // namespace pineda::test
