// An LD_PRELOAD shim for tools/xscreensaver-fps.sh: counts a program's eglSwapBuffers calls and
// writes "COUNT SECONDS" (swaps so far, seconds since the first) over $SWAPCOUNT_FILE after
// each one, so that the count survives the program being killed. (The lines only grow, so
// each write covers the one before.)
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

typedef unsigned (*SwapBuffers)(void* display, void* surface);

static double seconds_now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

unsigned eglSwapBuffers(void* display, void* surface) {
  static SwapBuffers next;
  static long count;
  static double first;
  static int fd = -1;
  if (!next) next = (SwapBuffers)dlsym(RTLD_NEXT, "eglSwapBuffers");
  const unsigned result = next(display, surface);
  if (fd < 0) {
    const char* file = getenv("SWAPCOUNT_FILE");
    fd = file ? open(file, O_WRONLY | O_CREAT | O_TRUNC, 0644) : 2;
    first = seconds_now();
  }
  char line[64];
  const int n = snprintf(line, sizeof line, "%ld %.3f\n", ++count, seconds_now() - first);
  if (pwrite(fd, line, (size_t)n, 0) < 0) fd = 2;
  return result;
}
