// pineda-x11grab NAME OUT.png: writes the contents of the first mapped X window whose name
// (WM_NAME) is NAME as a PNG, whichever driver drew it (the same picture for Pineda and
// llvmpipe); NAME --root: the whole screen. Exit 1 when no such window exists, 2 on other errors.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "png_io.h"

namespace {

Window find_named(Display* dpy, Window w, const char* name) {
  char* window_name = nullptr;
  if (XFetchName(dpy, w, &window_name) && window_name) {
    const bool match = std::strcmp(window_name, name) == 0;
    XFree(window_name);
    XWindowAttributes attributes;
    if (match && XGetWindowAttributes(dpy, w, &attributes) && attributes.map_state == IsViewable) return w;
  }
  Window root, parent, *children = nullptr;
  unsigned int count = 0;
  if (!XQueryTree(dpy, w, &root, &parent, &children, &count)) return 0;
  Window found = 0;
  for (unsigned int i = 0; i < count && !found; ++i) found = find_named(dpy, children[i], name);
  if (children) XFree(children);
  return found;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: pineda-x11grab WINDOW_NAME|--root OUT.png\n");
    return 2;
  }
  Display* dpy = XOpenDisplay(nullptr);
  if (!dpy) {
    std::fprintf(stderr, "pineda-x11grab: cannot open the X display\n");
    return 2;
  }
  const bool whole_screen = std::strcmp(argv[1], "--root") == 0;
  const Window w = whole_screen ? DefaultRootWindow(dpy) : find_named(dpy, DefaultRootWindow(dpy), argv[1]);
  if (!w) {
    std::fprintf(stderr, "pineda-x11grab: no mapped window named '%s'\n", argv[1]);
    return 1;
  }
  XWindowAttributes attributes;
  XGetWindowAttributes(dpy, w, &attributes);
  XImage* image = XGetImage(dpy, w, 0, 0, attributes.width, attributes.height, AllPlanes, ZPixmap);
  if (!image) {
    std::fprintf(stderr, "pineda-x11grab: XGetImage failed\n");
    return 2;
  }
  pineda::tools::Image out;
  out.width = attributes.width;
  out.height = attributes.height;
  out.rgba.resize(static_cast<size_t>(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const unsigned long pixel = XGetPixel(image, x, y);
      uint8_t* o = &out.rgba[(static_cast<size_t>(y) * out.width + x) * 4];
      o[0] = static_cast<uint8_t>((pixel & image->red_mask) >> __builtin_ctzl(image->red_mask));
      o[1] = static_cast<uint8_t>((pixel & image->green_mask) >> __builtin_ctzl(image->green_mask));
      o[2] = static_cast<uint8_t>((pixel & image->blue_mask) >> __builtin_ctzl(image->blue_mask));
      o[3] = 255;
    }
  XDestroyImage(image);
  XCloseDisplay(dpy);
  std::string error;
  if (!pineda::tools::writePng(argv[2], out, error)) {
    std::fprintf(stderr, "pineda-x11grab: %s\n", error.c_str());
    return 2;
  }
  return 0;
}
