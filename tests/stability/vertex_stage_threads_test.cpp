// The vertex stages of a big draw (array fetch, transform and lighting, vertex shaders) run in
// pieces on the renderer's threads: the images must not depend on the number of threads.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/e2e/support/gl_program.h"
#include "tests/e2e/support/gl_surface.h"
#include "tests/stability/case_table.h"

namespace pineda::test {
namespace {

constexpr int kSize = 160;
constexpr int kGrid = 120;  // 14641 vertices: several pieces of the vertex stages

struct Mesh {
  std::vector<float> positions, normals, colors;
  std::vector<GLuint> indices;
};

// A rippled grid over most of the view, with normals and colours that vary per vertex.
Mesh rippled_grid() {
  Mesh m;
  for (int j = 0; j <= kGrid; ++j)
    for (int i = 0; i <= kGrid; ++i) {
      const float x = -0.9f + 1.8f * float(i) / kGrid, y = -0.9f + 1.8f * float(j) / kGrid;
      const float z = 0.1f * std::sin(9.0f * x) * std::cos(7.0f * y);
      m.positions.insert(m.positions.end(), {x, y, z});
      const float nx = -0.9f * std::cos(9.0f * x) * std::cos(7.0f * y), ny = 0.7f * std::sin(9.0f * x) * std::sin(7.0f * y);
      m.normals.insert(m.normals.end(), {nx, ny, 1.0f});
      m.colors.insert(m.colors.end(), {0.5f + 0.5f * x, 0.5f + 0.5f * y, 0.6f, 1.0f});
    }
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const GLuint a = GLuint(j * (kGrid + 1) + i), c = a + kGrid + 1;
      m.indices.insert(m.indices.end(), {a, a + 1, c, c, a + 1, c + 1});
    }
  return m;
}

const char* const kVertexShader = R"(#version 110
attribute vec3 position;
attribute vec3 normal;
attribute vec4 color;
varying vec4 v_color;
void main() {
  vec3 n = normalize(normal);
  v_color = color * (0.3 + 0.7 * max(dot(n, vec3(0.3, 0.4, 0.866)), 0.0));
  gl_Position = vec4(position.xy * (1.0 + position.z), position.z, 1.0);
})";

const char* const kFragmentShader = R"(#version 110
varying vec4 v_color;
void main() { gl_FragColor = v_color; })";

// The mesh drawn with fixed-function lighting (glDrawElements) on the left and through a
// vertex shader (glDrawArrays of the unindexed triangles) on the right; the colour buffer.
std::vector<uint8_t> render(const char* threads) {
  setenv("PINEDA_THREADS", threads, 1);
  GlSurface surface({kSize, kSize, 24, 8});
  unsetenv("PINEDA_THREADS");
  EXPECT_TRUE(surface.ok()) << surface.error();
  if (!surface.ok()) return {};
  const Mesh mesh = rippled_grid();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glViewport(0, 0, kSize / 2, kSize);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  const GLfloat light[4] = {0.3f, 0.4f, 0.866f, 0.0f}, specular[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, mesh.positions.data());
  glNormalPointer(GL_FLOAT, 0, mesh.normals.data());
  glColorPointer(4, GL_FLOAT, 0, mesh.colors.data());
  glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, mesh.indices.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisable(GL_LIGHTING);

  std::vector<float> positions, normals, colors;  // one vertex per index
  for (GLuint k : mesh.indices) {
    positions.insert(positions.end(), &mesh.positions[3 * k], &mesh.positions[3 * k + 3]);
    normals.insert(normals.end(), &mesh.normals[3 * k], &mesh.normals[3 * k + 3]);
    colors.insert(colors.end(), &mesh.colors[4 * k], &mesh.colors[4 * k + 4]);
  }
  glViewport(kSize / 2, 0, kSize / 2, kSize);
  const GLuint program = link_gl_program(kVertexShader, kFragmentShader, {{0, "position"}, {1, "normal"}, {2, "color"}});
  glUseProgram(program);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, positions.data());
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, normals.data());
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 0, colors.data());
  for (GLuint i = 0; i < 3; ++i) glEnableVertexAttribArray(i);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(mesh.indices.size()));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> out(kSize * kSize * 4);
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glUseProgram(0);
  glDeleteProgram(program);
  surface.release();
  return out;
}

TEST(VertexStageThreads, ImagesIdenticalForAnyThreadCount) {
  const std::vector<uint8_t> one = render("1");
  ASSERT_EQ(one.size(), size_t(kSize * kSize * 4));
  int lit_left = 0, lit_right = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const uint8_t* p = &one[4 * (y * kSize + x)];
      if (p[0] || p[1] || p[2]) ++(x < kSize / 2 ? lit_left : lit_right);
    }
  EXPECT_GT(lit_left, kSize * kSize / 4) << "the lit mesh must cover most of the left half";
  EXPECT_GT(lit_right, kSize * kSize / 4) << "the shaded mesh must cover most of the right half";
  for (const char* threads : {"2", "3"}) {
    const std::vector<uint8_t> many = render(threads);
    ASSERT_EQ(one.size(), many.size());
    int differing = 0;
    for (size_t i = 0; i < one.size(); i += 4)
      differing += one[i] != many[i] || one[i + 1] != many[i + 1] || one[i + 2] != many[i + 2] || one[i + 3] != many[i + 3];
    expect_case(std::string("PINEDA_THREADS=") + threads + " vs 1: pixels differing", 0, differing);
  }
}

}  // namespace
}  // namespace pineda::test
