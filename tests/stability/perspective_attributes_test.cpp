// Perspective-correct colours and texture coordinates against double-precision exact values
// (perspective_plane.h); the maximum error is reported in the table. Run in the normal mode
// and in the reference mode (PINEDA_REFERENCE=1, read when the context is created).
#include <GL/gl.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/stability/case_table.h"
#include "tests/stability/perspective_plane.h"
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class PerspectiveAttributes : public GlTest, public ::testing::WithParamInterface<bool> {
 protected:
  SurfaceSpec spec() const override { return {128, 64, 24, 8}; }
  void SetUp() override {
    if (GetParam()) setenv("PINEDA_REFERENCE", "1", 1);
    GlTest::SetUp();
    unsetenv("PINEDA_REFERENCE");
  }
  std::string mode() const { return GetParam() ? "reference mode" : "normal mode"; }

  void identity_matrices() {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }

  // Calls per_pixel(x, y, triangle, weights) for every pixel centre the plane covers, with the
  // triangle (of the two) that covers it; pixels within 1e-6 of the shared diagonal use either.
  template <typename F>
  void for_each_pixel(const std::array<ClipVertex4, 4>& q, F per_pixel) {
    const ClipVertex4* tris[2][3] = {{&q[0], &q[1], &q[2]}, {&q[0], &q[2], &q[3]}};
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x)
        for (const auto& t : tris) {
          const Weights w = screen_weights(*t[0], *t[1], *t[2], width(), height(), x + 0.5, y + 0.5);
          if (!w.inside(1e-6L)) continue;
          per_pixel(x, y, t, w);
          break;
        }
  }
};

// Red, green and blue vary from 0 to 1 across the receding plane; every pixel's byte must be
// the exact perspective-correct value rounded: within half a unit (1/510) plus float noise.
TEST_P(PerspectiveAttributes, ColoursMatchTheExactValues) {
  const auto q = receding_plane(0.1, 1000);
  const double colors[4][3] = {{1, 0, 0.2}, {0, 1, 0.9}, {0.3, 0.1, 0}, {0.7, 0.5, 1}};
  identity_matrices();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  for (int i : {0, 1, 2, 0, 2, 3}) {
    glColor3dv(colors[i]);
    glVertex4f(q[i].x, q[i].y, q[i].z, q[i].w);
  }
  glEnd();
  const std::vector<uint8_t> img = read_all();
  const ClipVertex4* base = &q[0];
  double max_error = 0;  // in units of 1/255
  int pixels = 0;
  for_each_pixel(q, [&](int x, int y, const ClipVertex4* const* t, const Weights& w) {
    ++pixels;
    for (int c = 0; c < 3; ++c) {
      double a[3];
      for (int i = 0; i < 3; ++i) a[i] = colors[t[i] - base][c];
      const long double exact = perspective_value(t, w, a);
      const double got = img[(size_t(y) * width() + x) * 4 + c];
      max_error = std::max(max_error, double(std::fabs(got - exact * 255)));
    }
  });
  expect_case(mode() + ": pixels compared", width() * height(), pixels);
  expect_case_at_most(mode() + ": max |colour - exact| in 1/255", 0.502, max_error);
}

// s runs from 0 to 1 across the plane's width and t from 0 to 1 along its depth; a 256x256
// NEAREST texture whose texel (i, j) holds (i, j, 0) shows which texel each pixel sampled.
// The texel centre must be within half a texel of the exact (s, t) (plus float noise).
TEST_P(PerspectiveAttributes, TextureCoordinatesMatchTheExactValues) {
  const auto q = receding_plane(0.1, 1000);
  const double st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<uint8_t> texels(256 * 256 * 4);
  for (int j = 0; j < 256; ++j)
    for (int i = 0; i < 256; ++i) {
      uint8_t* p = &texels[(size_t(j) * 256 + i) * 4];
      p[0] = uint8_t(i), p[1] = uint8_t(j), p[2] = 0, p[3] = 255;
    }
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 256, 256, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  identity_matrices();
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  for (int i : {0, 1, 2, 0, 2, 3}) {
    glTexCoord2dv(st[i]);
    glVertex4f(q[i].x, q[i].y, q[i].z, q[i].w);
  }
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
  const std::vector<uint8_t> img = read_all();
  const ClipVertex4* base = &q[0];
  double max_error = 0;  // in texels
  int pixels = 0;
  for_each_pixel(q, [&](int x, int y, const ClipVertex4* const* t, const Weights& w) {
    ++pixels;
    for (int c = 0; c < 2; ++c) {
      double a[3];
      for (int i = 0; i < 3; ++i) a[i] = st[t[i] - base][c];
      const long double exact = std::clamp(perspective_value(t, w, a) * 256, 0.5L, 255.5L);
      const double texel_centre = img[(size_t(y) * width() + x) * 4 + c] + 0.5;
      max_error = std::max(max_error, double(std::fabs(texel_centre - exact)));
    }
  });
  expect_case(mode() + ": pixels compared", width() * height(), pixels);
  expect_case_at_most(mode() + ": max |texel centre - exact (s, t)| in texels", 0.502, max_error);
}

INSTANTIATE_TEST_SUITE_P(Modes, PerspectiveAttributes, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Reference" : "Normal"; });

}  // namespace
}  // namespace pineda::test
