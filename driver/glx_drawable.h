// A GLX drawable's buffers (Pineda memory) and their presentation to the X window or pixmap.
//
// Colour is BGRA8, which is the pixel layout of X's 24- and 32-bit TrueColor visuals on a
// little-endian client, stored top row first so that an XImage can point at it; the
// framebuffer sees it bottom-up through a negative stride. A double-buffered window has a
// front buffer (what was last presented) and a back buffer; glXSwapBuffers copies the back
// buffer to the front, as Mesa's llvmpipe does, and presents the front. Drawing to GL_FRONT
// renders into the front buffer, which reaches the window at glFlush/glFinish.
#pragma once
#include "driver/glx_objects.h"

namespace pineda::glx {

// Allocates the buffers for `width` x `height` (contents undefined, cleared to zero) and
// describes them in `d.drawable`. Throws std::bad_alloc.
void allocate_buffers(DrawableObject& d, int width, int height);

// The size (and depth) of an X drawable, or false when it does not exist (no X error is
// reported).
bool x_drawable_size(Display* dpy, ::Drawable x, int* width, int* height, int* x_depth = nullptr);

// Copies the front colour buffer to the X window or pixmap (pbuffers have nothing to copy
// to). `checked`: X errors (a window destroyed meanwhile) are caught instead of reported.
void present(DrawableObject& d, bool checked = false);

// The swap of a double-buffered drawable: the back buffer becomes the front, and is presented.
void swap_and_present(DrawableObject& d);

// Pixmaps start with the X pixmap's contents.
void load_from_x(DrawableObject& d);

// The Visual* of a visual id on `screen`, or nullptr.
Visual* find_visual(Display* dpy, int screen, VisualID id);

}  // namespace pineda::glx

namespace pineda::glx {

// The attributes of an X window, or false when `w` is not a window (no X error is reported).
bool x_window_attributes(Display* dpy, Window w, XWindowAttributes* attributes);

}  // namespace pineda::glx
