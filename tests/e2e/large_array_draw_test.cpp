// Large array draws (tens of thousands of vertices, indices naming vertices all over the
// arrays): blended, overlapping primitives (whose order shows in every pixel) draw exactly what
// the same vertices draw in immediate mode, with and without indices, for points, lines,
// triangles and quads, a last incomplete primitive included, with fixed function and with a
// program reading generic attributes; and an occlusion query counts the same samples. (Written
// for a splitting of such draws into pieces that was measured and not kept; it found the
// window cache's slot sharing, window_cache_collision_test.cpp.)
#define GL_GLEXT_PROTOTYPES
#include <cstdint>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

struct Vertex {
  float r, g, b, a;
  float x, y;
};

// Vertices over the surface in small clusters (so that a triangle or quad covers a few
// pixels), from a fixed pseudo-random sequence.
std::vector<Vertex> scattered_vertices(size_t count, int width, int height) {
  std::vector<Vertex> out(count);
  uint32_t state = 7;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  float cx = 0.f, cy = 0.f;
  for (size_t i = 0; i < count; ++i) {
    if (i % 4 == 0) cx = next() * static_cast<float>(width), cy = next() * static_cast<float>(height);
    out[i] = {next(), next(), next(), 0.3f + 0.5f * next(), cx + 6.f * next() - 3.f, cy + 6.f * next() - 3.f};
  }
  return out;
}

// The mode, and the renderer's threads (PINEDA_THREADS): with one, large fixed-function draws of
// points, lines and triangles reach the renderer in runs (state/draw.cpp's draw_in_runs), with
// more as a whole.
class LargeArrayDrawTest : public GlTest, public ::testing::WithParamInterface<std::tuple<GLenum, const char*>> {
 protected:
  static GLenum mode() { return std::get<0>(GetParam()); }
  void SetUp() override {
    setenv("PINEDA_THREADS", std::get<1>(GetParam()), 1);
    GlTest::SetUp();
    unsetenv("PINEDA_THREADS");
    pixel_projection();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glPointSize(2.f);
    vertices_ = scattered_vertices(kCount, width(), height());
    glColorPointer(4, GL_FLOAT, sizeof(Vertex), &vertices_[0].r);
    glVertexPointer(2, GL_FLOAT, sizeof(Vertex), &vertices_[0].x);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_VERTEX_ARRAY);
    glGenQueries(1, &query_);
  }
  void TearDown() override {
    glDeleteQueries(1, &query_);
    if (program_) glDeleteProgram(program_);
    GlTest::TearDown();
  }

  std::vector<uint8_t> immediate(GLenum mode, const std::vector<uint32_t>& order) {
    clear_to(0, 0, 0, 0);
    glBeginQuery(GL_SAMPLES_PASSED, query_);
    glBegin(mode);
    for (const uint32_t i : order) {
      glColor4f(vertices_[i].r, vertices_[i].g, vertices_[i].b, vertices_[i].a);
      glVertex2f(vertices_[i].x, vertices_[i].y);
    }
    glEnd();
    glEndQuery(GL_SAMPLES_PASSED);
    return read_all();
  }

  // Starts the query and clears; finish() ends it and reads the pixels.
  void start() {
    clear_to(0, 0, 0, 0);
    glBeginQuery(GL_SAMPLES_PASSED, query_);
  }
  std::vector<uint8_t> finish() {
    glEndQuery(GL_SAMPLES_PASSED);
    return read_all();
  }
  GLuint samples() {
    GLuint n = 0;
    glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &n);
    return n;
  }

  // A program drawing position and color from generic attributes 0 and 1, in use.
  void use_generic_attribute_program() {
    const char* vertex = R"(#version 110
attribute vec2 position;
attribute vec4 color;
varying vec4 v_color;
void main() {
  v_color = color;
  gl_Position = gl_ModelViewProjectionMatrix * vec4(position, 0.0, 1.0);
})";
    const char* fragment = R"(#version 110
varying vec4 v_color;
void main() { gl_FragColor = v_color; })";
    program_ = glCreateProgram();
    for (const auto& [type, source] : {std::pair{GLenum(GL_VERTEX_SHADER), vertex}, {GLenum(GL_FRAGMENT_SHADER), fragment}}) {
      const GLuint shader = glCreateShader(type);
      glShaderSource(shader, 1, &source, nullptr);
      glCompileShader(shader);
      glAttachShader(program_, shader);
      glDeleteShader(shader);
    }
    glBindAttribLocation(program_, 0, "position");
    glBindAttribLocation(program_, 1, "color");
    glLinkProgram(program_);
    GLint linked = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &linked);
    ASSERT_TRUE(linked);
    glUseProgram(program_);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), &vertices_[0].x);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), &vertices_[0].r);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
  }

  // As immediate(), through the program's generic attributes (attribute 0 last: it provokes
  // the vertex).
  std::vector<uint8_t> immediate_generic(GLenum mode, const std::vector<uint32_t>& order) {
    clear_to(0, 0, 0, 0);
    glBeginQuery(GL_SAMPLES_PASSED, query_);
    glBegin(mode);
    for (const uint32_t i : order) {
      glVertexAttrib4f(1, vertices_[i].r, vertices_[i].g, vertices_[i].b, vertices_[i].a);
      glVertexAttrib2f(0, vertices_[i].x, vertices_[i].y);
    }
    glEnd();
    glEndQuery(GL_SAMPLES_PASSED);
    return read_all();
  }

  // More vertices than the window cache's 1024 slots many times over, and one vertex more than
  // whole quads take.
  static constexpr size_t kCount = 3 * 12288 + 4 * 1000 + 1;
  std::vector<Vertex> vertices_;
  GLuint query_ = 0, program_ = 0;
};

// Every vertex named about twice, far apart: neighbours in the list come from all over the
// arrays.
std::vector<uint32_t> scattered_order(size_t count) {
  std::vector<uint32_t> order(2 * count);
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<uint32_t>((i * 7919u + i / 3) % count);
  return order;
}

TEST_P(LargeArrayDrawTest, DrawArraysEqualsImmediateMode) {
  std::vector<uint32_t> order(kCount);
  for (size_t i = 0; i < kCount; ++i) order[i] = static_cast<uint32_t>(i);
  const std::vector<uint8_t> expected = immediate(mode(), order);
  const GLuint expected_samples = samples();
  ASSERT_GT(expected_samples, 10000u);
  start();
  glDrawArrays(mode(), 0, static_cast<GLsizei>(kCount));
  EXPECT_EQ(finish(), expected);
  EXPECT_EQ(samples(), expected_samples);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(LargeArrayDrawTest, DrawElementsEqualsImmediateMode) {
  const std::vector<uint32_t> order = scattered_order(kCount);
  const std::vector<uint8_t> expected = immediate(mode(), order);
  const GLuint expected_samples = samples();
  ASSERT_GT(expected_samples, 10000u);
  start();
  glDrawElements(mode(), static_cast<GLsizei>(order.size()), GL_UNSIGNED_INT, order.data());
  EXPECT_EQ(finish(), expected);
  EXPECT_EQ(samples(), expected_samples);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(LargeArrayDrawTest, WithAProgramDrawArraysAndDrawElementsEqualImmediateMode) {
  use_generic_attribute_program();
  std::vector<uint32_t> in_order(kCount);
  for (size_t i = 0; i < kCount; ++i) in_order[i] = static_cast<uint32_t>(i);
  const std::vector<uint32_t> scattered = scattered_order(kCount);
  const std::vector<uint32_t>* const orders[] = {&in_order, &scattered};
  for (const std::vector<uint32_t>* order : orders) {
    const std::vector<uint8_t> expected = immediate_generic(mode(), *order);
    const GLuint expected_samples = samples();
    ASSERT_GT(expected_samples, 10000u);
    start();
    if (order == &in_order) glDrawArrays(mode(), 0, static_cast<GLsizei>(kCount));
    else glDrawElements(mode(), static_cast<GLsizei>(order->size()), GL_UNSIGNED_INT, order->data());
    EXPECT_EQ(finish(), expected) << (order == &in_order ? "DrawArrays" : "DrawElements");
    EXPECT_EQ(samples(), expected_samples);
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

INSTANTIATE_TEST_SUITE_P(Modes, LargeArrayDrawTest,
                         ::testing::Combine(::testing::Values(GL_POINTS, GL_LINES, GL_TRIANGLES, GL_QUADS),
                                            ::testing::Values("1", "2")),
                         [](const ::testing::TestParamInfo<std::tuple<GLenum, const char*>>& info) {
                           const char* name = "Quads";
                           switch (std::get<0>(info.param)) {
                             case GL_POINTS: name = "Points"; break;
                             case GL_LINES: name = "Lines"; break;
                             case GL_TRIANGLES: name = "Triangles"; break;
                             default: break;
                           }
                           return std::string(name) + "_Threads" + std::get<1>(info.param);
                         });

}  // namespace
}  // namespace pineda::test
