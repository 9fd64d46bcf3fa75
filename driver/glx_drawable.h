// A GLX drawable's buffers (Pineda memory) and their presentation to the X window or pixmap.
//
// Colour is BGRA8, which is the pixel layout of X's 24- and 32-bit TrueColor visuals on a
// little-endian client, stored top row first so that an XImage can point at it; the
// framebuffer sees it bottom-up through a negative stride. A window has one colour buffer,
// which is the back buffer of a double-buffered config (the front buffer is the window
// itself): glXSwapBuffers copies it to the window. Drawing to GL_FRONT renders into the same
// buffer and reaches the window at glFlush/glFinish, and reading GL_FRONT reads it too, which
// is exact right after a swap and approximate after more drawing to the back buffer.
#pragma once
#include "driver/glx_objects.h"

namespace pineda::glx {

// Allocates the buffers for `width` x `height` (contents undefined, cleared to zero) and
// describes them in `d.drawable`. Throws std::bad_alloc.
void allocate_buffers(DrawableObject& d, int width, int height);

// The size (and depth) of an X drawable, or false when it does not exist (no X error is
// reported).
bool x_drawable_size(Display* dpy, ::Drawable x, int* width, int* height, int* x_depth = nullptr);

// Copies the colour buffer to the X window or pixmap (pbuffers have nothing to copy to).
// `checked`: X errors (a window destroyed meanwhile) are caught instead of reported.
void present(DrawableObject& d, bool checked = false);

// Pixmaps start with the X pixmap's contents.
void load_from_x(DrawableObject& d);

// The Visual* of a visual id on `screen`, or nullptr.
Visual* find_visual(Display* dpy, int screen, VisualID id);

}  // namespace pineda::glx

namespace pineda::glx {

// The attributes of an X window, or false when `w` is not a window (no X error is reported).
bool x_window_attributes(Display* dpy, Window w, XWindowAttributes* attributes);

}  // namespace pineda::glx
