// Quads in window pixels at depth z, for tests under GlTest::pixel_projection().
#pragma once
#include <GL/gl.h>

namespace pineda::test {

// A quad covering [x0, x1] x [y0, y1] at depth z.
inline void draw_rect(float x0, float y0, float x1, float y1, float z = 0.f) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

inline void draw_window_quad(float w, float h, float z = 0.f) { draw_rect(0, 0, w, h, z); }

// A quad covering [x0, x1] x [y0, y1] with texture coordinates [s0, s1] x [t0, t1].
inline void draw_textured_rect(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0);
  glVertex2f(x0, y0);
  glTexCoord2f(s1, t0);
  glVertex2f(x1, y0);
  glTexCoord2f(s1, t1);
  glVertex2f(x1, y1);
  glTexCoord2f(s0, t1);
  glVertex2f(x0, y1);
  glEnd();
}

}  // namespace pineda::test
