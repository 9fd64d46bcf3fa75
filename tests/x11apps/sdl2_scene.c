/* SDL2 (X11, GLX through SDL's own loading of libGL.so.1): draws the test scene; exit status 0
 * when glReadPixels returns exactly the expected pixels, before and after the swap. */
#include <SDL2/SDL.h>
#include <string.h>

#include "scene.h"

int main(int argc, char** argv) {
  (void)argc;
  (void)argv;
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    fprintf(stderr, "SDL_Init: %s\n", SDL_GetError());
    return 2;
  }
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
  SDL_Window* window = SDL_CreateWindow("pineda sdl2 test", 0, 0, 64, 48, SDL_WINDOW_OPENGL | SDL_WINDOW_SHOWN);
  if (!window) {
    fprintf(stderr, "SDL_CreateWindow: %s\n", SDL_GetError());
    return 2;
  }
  SDL_GLContext context = SDL_GL_CreateContext(window);
  if (!context) {
    fprintf(stderr, "SDL_GL_CreateContext: %s\n", SDL_GetError());
    return 2;
  }
  int failures = scene_names_pineda();
  scene_draw(64, 48);
  failures += scene_check(64, 48);
  SDL_GL_SwapWindow(window);
  glReadBuffer(GL_FRONT);
  failures += scene_check(64, 48);
  printf("sdl2: %d failures\n", failures);
  SDL_GL_DeleteContext(context);
  SDL_DestroyWindow(window);
  SDL_Quit();
  return failures ? 1 : 0;
}
