// The configs every display offers, and their attribute values.
#pragma once
#include <vector>

#include "driver/egl_objects.h"

namespace pineda::egl {

inline constexpr EGLint kMaxPbufferWidth = 8192;
inline constexpr EGLint kMaxPbufferHeight = 8192;
inline constexpr EGLint kMaxPbufferPixels = kMaxPbufferWidth * kMaxPbufferHeight;
inline constexpr EGLint kMinSwapInterval = 0;
inline constexpr EGLint kMaxSwapInterval = 1;

// The configs of the surfaceless platform (pbuffers); the X11 platform's add windows and
// pixmaps (egl_x11.h).
std::vector<Config> surfaceless_configs();
// nullptr when `handle` is not one of the display's configs.
const Config* find_config(const Display& display, EGLConfig handle);
// false when `attribute` is not a config attribute.
bool config_attribute(const Config& config, EGLint attribute, EGLint* value);

}  // namespace pineda::egl
