/* GLFW: `glfw_scene x11` (GLX) or `glfw_scene egl` (EGL on X11) draws the test scene, checks
 * the exact pixels, then resizes the window mid-run and checks that rendering follows the new
 * size after the next swap. Exit status 0 when every check passes. */
#include <GLFW/glfw3.h>
#include <stdio.h>
#include <string.h>

#include "scene.h"

static int frame(GLFWwindow* window, int* width, int* height) {
  glfwGetFramebufferSize(window, width, height);
  scene_draw(*width, *height);
  int failures = scene_check(*width, *height);
  glfwSwapBuffers(window);
  return failures;
}

int main(int argc, char** argv) {
  const int egl = argc > 1 && strcmp(argv[1], "egl") == 0;
  if (!glfwInit()) return 2;
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, egl ? GLFW_EGL_CONTEXT_API : GLFW_NATIVE_CONTEXT_API);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(64, 48, "pineda glfw test", NULL, NULL);
  if (!window) {
    fprintf(stderr, "glfwCreateWindow failed\n");
    return 2;
  }
  glfwMakeContextCurrent(window);
  int failures = scene_names_pineda();
  int width = 0, height = 0;
  failures += frame(window, &width, &height);

  glfwSetWindowSize(window, 100, 80);
  for (int i = 0; i < 200 && (width != 100 || height != 80); ++i) {
    glfwWaitEventsTimeout(0.01);
    glfwGetFramebufferSize(window, &width, &height);
  }
  /* The swap after the resize gives the next frame buffers of the new size. */
  glfwSwapBuffers(window);
  int new_width = 0, new_height = 0;
  failures += frame(window, &new_width, &new_height);
  if (new_width != 100 || new_height != 80) {
    fprintf(stderr, "window is %dx%d after the resize\n", new_width, new_height);
    ++failures;
  }
  printf("%s: %d failures\n", egl ? "glfw egl" : "glfw x11", failures);
  glfwDestroyWindow(window);
  glfwTerminate();
  return failures ? 1 : 0;
}
