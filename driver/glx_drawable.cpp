#include "driver/glx_drawable.h"

#include <X11/Xutil.h>

#include "driver/frame_capture.h"
#include "raster/multisample.h"

#include <cstring>
#include <mutex>

namespace pineda::glx {
namespace {

// Xlib's error handler is process-wide: a query that may fail swaps in a quiet handler
// for its duration, one query at a time.
std::mutex& trap_mutex() {
  static std::mutex* m = new std::mutex;
  return *m;
}
bool trapped_error = false;

int quiet_handler(Display*, XErrorEvent*) {
  trapped_error = true;
  return 0;
}

}  // namespace

void allocate_buffers(DrawableObject& d, int width, int height) {
  const size_t count = static_cast<size_t>(width) * height;
  d.shm.reset();
  d.color.clear();
  d.back.clear();
  // A pixmap has one colour buffer, which is its contents.
  const bool double_buffered = d.config->double_buffered && d.kind != DrawableKind::Pixmap;
  if (d.kind != DrawableKind::Pbuffer && d.dpy)
    d.shm = SharedImage::create(d.dpy, d.visual, d.x_depth, width, height);
  if (d.shm) {
    d.pixels = d.shm->pixels();
    std::memset(d.pixels, 0, count * 4);
  } else {
    d.color.assign(count * 4, 0);
    d.pixels = d.color.data();
  }
  if (double_buffered) d.back.assign(count * 4, 0);
  d.allocated = true;
  // A multisampled config renders into 4 planes of colour, depth and stencil; `back` is the
  // resolved colour.
  const int samples = double_buffered && d.config->samples > 1 ? d.config->samples : 1;
  d.sample_color.assign(samples > 1 ? count * 4 * samples : 0, 0);
  d.depth.assign(d.config->depth ? count * samples : 0, 0);
  d.stencil.assign(d.config->stencil ? count * samples : 0, 0);
  d.width = width;
  d.height = height;

  raster::Framebuffer& fb = d.drawable.framebuffer;
  fb.width = width;
  fb.height = height;
  const ptrdiff_t row_bytes = static_cast<ptrdiff_t>(width) * 4;
  // Framebuffer row 0 (the bottom) is the last row in memory.
  auto bottom_up = [&](uint8_t* top_row) -> raster::ColorBuffer {
    return {count ? top_row + (height - 1) * row_bytes : nullptr, -row_bytes, raster::ColorFormat::BGRA8, {}, 0};
  };
  fb.color = bottom_up(double_buffered ? d.back.data() : d.pixels);
  d.drawable.front = double_buffered ? bottom_up(d.pixels) : raster::ColorBuffer{};
  fb.depth = {d.depth.empty() ? nullptr : d.depth.data(), width, d.config->depth};
  fb.stencil = {d.stencil.empty() ? nullptr : d.stencil.data(), width, d.config->stencil};
  fb.samples = samples;
  d.drawable.resolved = {};
  if (samples > 1) {
    d.drawable.resolved = fb.color;
    fb.color = bottom_up(d.sample_color.data());
    fb.color.sample_stride = static_cast<ptrdiff_t>(count) * 4;
    fb.depth.sample_stride = fb.stencil.sample_stride = static_cast<ptrdiff_t>(count);
  }
  d.drawable.red_bits = d.config->red;
  d.drawable.green_bits = d.config->green;
  d.drawable.blue_bits = d.config->blue;
  d.drawable.alpha_bits = d.config->alpha;
  d.drawable.double_buffered = double_buffered;
  // A single-buffered drawable's colour buffer is the one X reads back (glXWaitX).
  d.drawable.track_cleared_tiles(double_buffered);
}

namespace {

// Runs `query` with Xlib errors caught; false when it failed or raised an error.
template <class Query>
bool trapped(Display* dpy, Query query) {
  std::lock_guard lock(trap_mutex());
  XSync(dpy, False);  // earlier errors still go to the application's handler
  trapped_error = false;
  auto previous = XSetErrorHandler(quiet_handler);
  Status ok = query();
  XSync(dpy, False);
  XSetErrorHandler(previous);
  return ok && !trapped_error;
}

}  // namespace

bool x_drawable_size(Display* dpy, ::Drawable x, int* width, int* height, int* x_depth) {
  Window root;
  int px, py;
  unsigned int w = 0, h = 0, border, depth = 0;
  if (!trapped(dpy, [&] { return XGetGeometry(dpy, x, &root, &px, &py, &w, &h, &border, &depth); }))
    return false;
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  if (x_depth) *x_depth = static_cast<int>(depth);
  return true;
}

bool x_window_attributes(Display* dpy, Window w, XWindowAttributes* attributes) {
  return trapped(dpy, [&] { return XGetWindowAttributes(dpy, w, attributes); });
}

namespace {

XImage* wrap_color(DrawableObject& d) {
  XImage* image = XCreateImage(d.dpy, d.visual, d.x_depth, ZPixmap, 0,
                               reinterpret_cast<char*>(d.pixels), d.width, d.height, 32,
                               d.width * 4);
  return image;
}

void unwrap(XImage* image) {
  image->data = nullptr;  // the memory is the drawable's
  XDestroyImage(image);
}

}  // namespace

void present(DrawableObject& d, bool checked) {
  if (!d.dpy || d.kind == DrawableKind::Pbuffer || d.width == 0 || d.height == 0) return;
  if (!d.gc) return;
  d.drawable.front_drawn = false;
  if (d.kind == DrawableKind::Window) driver::capture_frame(d.drawable.front_color(), d.width, d.height);
  auto put = [&] {
    if (d.shm) {
      d.shm->put(d.x_drawable, d.gc);
      return 1;
    }
    XImage* image = wrap_color(d);
    if (!image) return 0;
    XPutImage(d.dpy, d.x_drawable, d.gc, image, 0, 0, 0, 0, d.width, d.height);
    unwrap(image);
    return 1;
  };
  if (checked) {
    trapped(d.dpy, put);
  } else {
    put();
    if (!d.shm) XFlush(d.dpy);  // a shared image put has already waited for the server
  }
}

void swap_and_present(DrawableObject& d) {
  const raster::Framebuffer& fb = d.drawable.framebuffer;
  if (fb.samples > 1 && d.drawable.resolved.base) raster::resolve_color(fb, d.drawable.resolved);
  if (!d.back.empty()) std::memcpy(d.pixels, d.back.data(), d.back.size());
  present(d);
}

void load_from_x(DrawableObject& d) {
  if (!d.dpy || d.width == 0 || d.height == 0) return;
  XImage* image = XGetImage(d.dpy, d.x_drawable, 0, 0, d.width, d.height, AllPlanes, ZPixmap);
  if (!image) return;
  if (image->bits_per_pixel == 32) {
    for (int y = 0; y < d.height; ++y)
      std::memcpy(d.pixels + static_cast<size_t>(y) * d.width * 4,
                  image->data + static_cast<ptrdiff_t>(y) * image->bytes_per_line, d.width * 4);
    // X leaves the byte above a 24-bit pixel undefined; GL's alpha starts opaque.
    if (d.x_depth == 24)
      for (size_t i = 3; i < static_cast<size_t>(d.width) * d.height * 4; i += 4) d.pixels[i] = 0xff;
  }
  XDestroyImage(image);
}

Visual* find_visual(Display* dpy, int screen, VisualID id) {
  XVisualInfo tmpl{};
  tmpl.visualid = id;
  tmpl.screen = screen;
  int count = 0;
  XVisualInfo* infos = XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &tmpl, &count);
  Visual* visual = count > 0 ? infos[0].visual : nullptr;
  if (infos) XFree(infos);
  return visual;
}

}  // namespace pineda::glx
