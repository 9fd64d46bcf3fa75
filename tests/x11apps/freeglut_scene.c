/* freeglut (GLX): a double-buffered RGB window with depth draws the test scene; exit status
 * 0 when glReadPixels returns exactly the expected pixels. */
#include <GL/freeglut.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

enum { kWidth = 64, kHeight = 48 };

static void display(void) {
  scene_draw(kWidth, kHeight);
  int failures = scene_names_pineda() + scene_check(kWidth, kHeight);
  glutSwapBuffers();
  glReadBuffer(GL_FRONT);
  failures += scene_check(kWidth, kHeight);
  exit(failures ? 1 : 0);
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
  glutInitWindowSize(kWidth, kHeight);
  glutCreateWindow("pineda freeglut test");
  glutDisplayFunc(display);
  glutMainLoop();
  return 1;
}
