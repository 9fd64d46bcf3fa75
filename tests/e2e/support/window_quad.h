// A quad covering [0, w] x [0, h] at depth z, for tests under GlTest::pixel_projection().
#pragma once
#include <GL/gl.h>

namespace pineda::test {

inline void draw_window_quad(float w, float h, float z = 0.f) {
  glBegin(GL_QUADS);
  glVertex3f(0, 0, z);
  glVertex3f(w, 0, z);
  glVertex3f(w, h, z);
  glVertex3f(0, h, z);
  glEnd();
}

}  // namespace pineda::test
