// GLX framebuffer configurations: built from the X server's TrueColor visuals, described by
// GLX attributes, and chosen and sorted as glXChooseFBConfig and glXChooseVisual specify.
#pragma once
#include "driver/glx_objects.h"

#include <X11/Xutil.h>

namespace pineda::glx {

// Pbuffers (and window buffers) are limited to what the rasterizer addresses comfortably.
inline constexpr int kMaxDrawableSize = 16384;

// The TrueColor visuals of `depth` on `screen` that Pineda presents to: 8 bits per channel
// in X's native 32-bit pixel layout, the screen's default visual first.
std::vector<XVisualInfo> usable_visuals(Display* dpy, int screen, int depth);

// The configs of every screen of `dpy`, best first per screen, with unique ids from 1.
std::vector<std::unique_ptr<Config>> build_configs(Display* dpy);

// GLX_BAD_ATTRIBUTE when `attribute` is not a config attribute; Success otherwise.
int config_attribute(const Config& c, int attribute, int* value);

// glXChooseFBConfig: the configs of `screen` matching `attribs` (may be null), best first.
// Returns false (with `out` empty) when the list names an unknown attribute.
bool choose_fbconfigs(const DisplayState& d, int screen, const int* attribs,
                      std::vector<const Config*>* out);

// glXChooseVisual: the best visual-canonical config of `screen`, or nullptr.
const Config* choose_visual_config(const DisplayState& d, int screen, const int* attribs);

// The canonical config of a visual, or nullptr when the visual does not support GL.
const Config* config_of_visual(const DisplayState& d, VisualID id);

}  // namespace pineda::glx
