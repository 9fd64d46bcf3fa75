// The configs every display offers, and their attribute values.
#pragma once
#include <span>

#include "driver/egl_objects.h"

namespace pineda::egl {

inline constexpr EGLint kMaxPbufferWidth = 8192;
inline constexpr EGLint kMaxPbufferHeight = 8192;
inline constexpr EGLint kMaxPbufferPixels = kMaxPbufferWidth * kMaxPbufferHeight;
inline constexpr EGLint kMinSwapInterval = 0;
inline constexpr EGLint kMaxSwapInterval = 1;

std::span<const Config> all_configs();
// nullptr when `handle` is not one of all_configs().
const Config* find_config(EGLConfig handle);
// false when `attribute` is not a config attribute.
bool config_attribute(const Config& config, EGLint attribute, EGLint* value);

}  // namespace pineda::egl
