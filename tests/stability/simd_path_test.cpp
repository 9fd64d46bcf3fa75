// PINEDA_SIMD=baseline or avx2 (read when a context is created) runs the baseline or AVX2 copy
// of the fragment routines instead of the best one: the images must be identical, bit for bit.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <vector>

#include "tests/e2e/support/gl_surface.h"
#include "tests/stability/case_table.h"

namespace pineda::test {
namespace {

// A textured (bilinear), blended, depth-tested, fogged perspective scene; the colour buffer.
std::vector<uint8_t> render_scene(const char* simd) {
  if (simd) setenv("PINEDA_SIMD", simd, 1);
  GlSurface surface({128, 96, 24, 8});
  unsetenv("PINEDA_SIMD");
  EXPECT_TRUE(surface.ok()) << surface.error();
  if (!surface.ok()) return {};
  std::vector<uint8_t> texels(64 * 64 * 4);
  for (int i = 0; i < 64 * 64; ++i) {
    const int x = i % 64, y = i / 64;
    texels[4 * i] = uint8_t(x * 4), texels[4 * i + 1] = uint8_t(y * 4), texels[4 * i + 2] = uint8_t(((x ^ y) & 8) * 30),
    texels[4 * i + 3] = 200;
  }
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.1, 0.1, -0.075, 0.075, 0.1, 100);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);  // before fog: the fill routines' key
  glColor4d(0.9, 0.5, 0.1, 0.5), glVertex3d(-3, -2, -8), glColor4d(0.1, 0.2, 0.9, 1), glVertex3d(3, -2, -9);
  glVertex3d(0, 2.5, -7);
  glEnd();
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 0.05f);
  for (int layer = 0; layer < 3; ++layer) {
    if (layer == 1) glEnable(GL_TEXTURE_2D);
    if (layer == 2) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 40; ++i) {
      const double a = i * 0.7 + layer, z = -1 - 0.7 * i;
      glColor4d(0.5 + 0.5 * std::sin(a), 0.5 + 0.5 * std::cos(a), 0.3, 0.6);
      glTexCoord2d(0, 0), glVertex3d(-2 + std::sin(a), -1.5, z);
      glColor4d(0.2, 0.9, 0.5 + 0.5 * std::sin(2 * a), 0.8);
      glTexCoord2d(4, 0), glVertex3d(2, -1 + std::cos(a), z - 3);
      glTexCoord2d(2, 3), glVertex3d(std::cos(a), 1.5, z + 0.5);
    }
    glEnd();
  }
  std::vector<uint8_t> out(128 * 96 * 4);
  glReadPixels(0, 0, 128, 96, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glDeleteTextures(1, &tex);
  surface.release();
  return out;
}

TEST(SimdPath, BaselineAvx2AndBestGiveIdenticalImages) {
  const std::vector<uint8_t> best = render_scene(nullptr);
  for (const char* simd : {"baseline", "avx2"}) {
    const std::vector<uint8_t> other = render_scene(simd);
    ASSERT_EQ(best.size(), other.size());
    int differing = 0, background = 0;
    for (size_t i = 0; i < best.size(); i += 4) {
      differing += best[i] != other[i] || best[i + 1] != other[i + 1] || best[i + 2] != other[i + 2] ||
                   best[i + 3] != other[i + 3];
      background += best[i] == 26 && best[i + 1] == 51 && best[i + 2] == 77;
    }
    const char* best_name = __builtin_cpu_supports("avx512bw") ? "AVX-512" : __builtin_cpu_supports("avx2") ? "AVX2" : "SSE2";
    expect_case(std::string("PINEDA_SIMD=") + simd + " vs best (" + best_name + "): pixels differing", 0, differing);
    EXPECT_LT(background, 128 * 96 / 2) << "the scene must cover most of the image";
  }
}

}  // namespace
}  // namespace pineda::test
