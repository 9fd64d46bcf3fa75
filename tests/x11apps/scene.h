/* The scene every test program draws, and its exact expected pixels: a blue clear and a red
 * window-aligned rectangle over the left half (with pixel centres well inside its edges),
 * drawn in GL window coordinates with a depth test on. */
#ifndef PINEDA_X11APPS_SCENE_H
#define PINEDA_X11APPS_SCENE_H
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

static void scene_draw(int width, int height) {
  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, 0, height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  glBegin(GL_QUADS);
  glVertex2i(0, 0);
  glVertex2i(width / 2, 0);
  glVertex2i(width / 2, height);
  glVertex2i(0, height);
  glEnd();
}

/* 0 when (x, y) of the read buffer holds r, g, b (0..255), else prints what it holds. */
static int scene_expect(int x, int y, int r, int g, int b) {
  unsigned char p[4] = {0, 0, 0, 0};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  if (p[0] == r && p[1] == g && p[2] == b) return 0;
  fprintf(stderr, "pixel (%d, %d): got %d %d %d, expected %d %d %d\n", x, y, p[0], p[1], p[2], r, g, b);
  return 1;
}

/* Checks the scene at the corners and around the edge of the rectangle; 0 when exact. */
static int scene_check(int width, int height) {
  int failures = 0;
  failures += scene_expect(0, 0, 255, 0, 0);
  failures += scene_expect(width / 2 - 1, height - 1, 255, 0, 0);
  failures += scene_expect(width / 2, 0, 0, 0, 255);
  failures += scene_expect(width - 1, height - 1, 0, 0, 255);
  if (glGetError() != GL_NO_ERROR) {
    fprintf(stderr, "GL error\n");
    ++failures;
  }
  return failures;
}

static int scene_names_pineda(void) {
  const char* renderer = (const char*)glGetString(GL_RENDERER);
  printf("GL_RENDERER: %s\n", renderer ? renderer : "(null)");
  if (renderer && strstr(renderer, "Pineda")) return 0;
  fprintf(stderr, "not running on Pineda\n");
  return 1;
}
#endif
