// eglGetConfigs, eglChooseConfig (EGL 1.5, 3.4.1: matching and sorting), eglGetConfigAttrib.
#include "driver/egl_config.h"

#include <algorithm>
#include <vector>

#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "driver/gl_version.h"
#include "glapi/egl_entry_points.h"
#include "raster/multisample.h"

namespace pineda::egl {
namespace {

// RGBA8888 with each depth/stencil combination the rasterizer stores; every config serves
// every API.
constexpr EGLint kRenderable = EGL_OPENGL_BIT | (driver::kHasGLES1 ? EGL_OPENGL_ES_BIT : 0) |
                               (driver::kHasGLES2 ? EGL_OPENGL_ES2_BIT : 0);
// EGL_CONFORMANT claims desktop OpenGL and, since it has every feature ES 1.1 requires (paletted
// compressed textures were the last), OpenGL ES 1.1; ES 2.0 is not claimed until it has been
// checked against its own list the same way.
constexpr EGLint kConformant = EGL_OPENGL_BIT | (driver::kHasGLES1 ? EGL_OPENGL_ES_BIT : 0);
constexpr Config kConfigs[] = {
    {1, 8, 8, 8, 8, 0, 0, EGL_PBUFFER_BIT, kRenderable},  {2, 8, 8, 8, 8, 0, 8, EGL_PBUFFER_BIT, kRenderable},
    {3, 8, 8, 8, 8, 16, 0, EGL_PBUFFER_BIT, kRenderable}, {4, 8, 8, 8, 8, 24, 0, EGL_PBUFFER_BIT, kRenderable},
    {5, 8, 8, 8, 8, 24, 8, EGL_PBUFFER_BIT, kRenderable}, {6, 8, 8, 8, 8, 32, 0, EGL_PBUFFER_BIT, kRenderable},
    {7, 8, 8, 8, 8, 32, 8, EGL_PBUFFER_BIT, kRenderable},
    // 4x multisampled (sorted after the single-sampled ones of the same colour buffer).
    {8, 8, 8, 8, 8, 0, 0, EGL_PBUFFER_BIT, kRenderable, 0, EGL_NONE, raster::kMaxSamples},
    {9, 8, 8, 8, 8, 24, 8, EGL_PBUFFER_BIT, kRenderable, 0, EGL_NONE, raster::kMaxSamples},
};

enum class Match { AtLeast, Exact, Mask, Ignore };

struct Criterion {
  EGLint attribute;
  EGLint default_value;
  Match match;
};

// EGL 1.5, Table 3.4.
constexpr Criterion kCriteria[] = {
    {EGL_BUFFER_SIZE, 0, Match::AtLeast},
    {EGL_RED_SIZE, 0, Match::AtLeast},
    {EGL_GREEN_SIZE, 0, Match::AtLeast},
    {EGL_BLUE_SIZE, 0, Match::AtLeast},
    {EGL_LUMINANCE_SIZE, 0, Match::AtLeast},
    {EGL_ALPHA_SIZE, 0, Match::AtLeast},
    {EGL_ALPHA_MASK_SIZE, 0, Match::AtLeast},
    {EGL_BIND_TO_TEXTURE_RGB, EGL_DONT_CARE, Match::Exact},
    {EGL_BIND_TO_TEXTURE_RGBA, EGL_DONT_CARE, Match::Exact},
    {EGL_COLOR_BUFFER_TYPE, EGL_RGB_BUFFER, Match::Exact},
    {EGL_CONFIG_CAVEAT, EGL_DONT_CARE, Match::Exact},
    {EGL_CONFIG_ID, EGL_DONT_CARE, Match::Exact},
    {EGL_CONFORMANT, 0, Match::Mask},
    {EGL_DEPTH_SIZE, 0, Match::AtLeast},
    {EGL_LEVEL, 0, Match::Exact},
    {EGL_MATCH_NATIVE_PIXMAP, EGL_NONE, Match::Ignore},  // no native pixmaps
    {EGL_MAX_PBUFFER_WIDTH, 0, Match::Ignore},
    {EGL_MAX_PBUFFER_HEIGHT, 0, Match::Ignore},
    {EGL_MAX_PBUFFER_PIXELS, 0, Match::Ignore},
    {EGL_MAX_SWAP_INTERVAL, EGL_DONT_CARE, Match::Exact},
    {EGL_MIN_SWAP_INTERVAL, EGL_DONT_CARE, Match::Exact},
    {EGL_NATIVE_RENDERABLE, EGL_DONT_CARE, Match::Exact},
    {EGL_NATIVE_VISUAL_ID, 0, Match::Ignore},
    {EGL_NATIVE_VISUAL_TYPE, EGL_DONT_CARE, Match::Exact},
    {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, Match::Mask},
    {EGL_SAMPLE_BUFFERS, 0, Match::AtLeast},
    {EGL_SAMPLES, 0, Match::AtLeast},
    {EGL_STENCIL_SIZE, 0, Match::AtLeast},
    {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, Match::Mask},
    {EGL_TRANSPARENT_TYPE, EGL_NONE, Match::Exact},
    {EGL_TRANSPARENT_RED_VALUE, EGL_DONT_CARE, Match::Exact},
    {EGL_TRANSPARENT_GREEN_VALUE, EGL_DONT_CARE, Match::Exact},
    {EGL_TRANSPARENT_BLUE_VALUE, EGL_DONT_CARE, Match::Exact},
};
constexpr size_t kCriteriaCount = sizeof(kCriteria) / sizeof(kCriteria[0]);

int criterion_index(EGLint attribute) {
  for (size_t i = 0; i < kCriteriaCount; ++i)
    if (kCriteria[i].attribute == attribute) return static_cast<int>(i);
  return -1;
}

EGLint get(const Config& c, EGLint attribute) {
  EGLint value = 0;
  config_attribute(c, attribute, &value);
  return value;
}

bool matches(const Config& c, const std::vector<EGLint>& wanted) {
  for (size_t i = 0; i < kCriteriaCount; ++i) {
    EGLint want = wanted[i];
    if (want == EGL_DONT_CARE || kCriteria[i].match == Match::Ignore) continue;
    EGLint have = get(c, kCriteria[i].attribute);
    switch (kCriteria[i].match) {
      case Match::AtLeast: if (have < want) return false; break;
      case Match::Exact: if (have != want) return false; break;
      case Match::Mask: if ((have & want) != want) return false; break;
      case Match::Ignore: break;
    }
  }
  return true;
}

// EGL 1.5, 3.4.1.2: the sort keys, most important first.
bool sorts_before(const Config& a, const Config& b, const std::vector<EGLint>& wanted) {
  auto color_bits = [&](const Config& c) {
    EGLint sum = 0;
    for (EGLint attribute : {EGL_RED_SIZE, EGL_GREEN_SIZE, EGL_BLUE_SIZE, EGL_ALPHA_SIZE}) {
      EGLint want = wanted[criterion_index(attribute)];
      if (want != 0 && want != EGL_DONT_CARE) sum += get(c, attribute);
    }
    return sum;
  };
  if (color_bits(a) != color_bits(b)) return color_bits(a) > color_bits(b);
  for (EGLint attribute : {EGL_BUFFER_SIZE, EGL_SAMPLE_BUFFERS, EGL_SAMPLES, EGL_DEPTH_SIZE,
                           EGL_STENCIL_SIZE, EGL_ALPHA_MASK_SIZE, EGL_CONFIG_ID}) {
    if (get(a, attribute) != get(b, attribute)) return get(a, attribute) < get(b, attribute);
  }
  return false;  // caveat, buffer type and visual type are the same for all configs
}

EGLBoolean copy_out(const std::vector<const Config*>& list, EGLConfig* configs, EGLint size,
                    EGLint* num_config) {
  EGLint n = static_cast<EGLint>(list.size());
  if (configs) {
    n = std::clamp<EGLint>(size, 0, n);
    for (EGLint i = 0; i < n; ++i) configs[i] = const_cast<Config*>(list[i]);
  }
  *num_config = n;
  return succeed(EGL_TRUE);
}

}  // namespace

std::vector<Config> surfaceless_configs() { return {std::begin(kConfigs), std::end(kConfigs)}; }

const Config* find_config(const Display& display, EGLConfig handle) {
  for (const Config& c : display.configs)
    if (&c == handle) return &c;
  return nullptr;
}

bool config_attribute(const Config& c, EGLint attribute, EGLint* value) {
  switch (attribute) {
    case EGL_BUFFER_SIZE: *value = c.red + c.green + c.blue + c.alpha; return true;
    case EGL_RED_SIZE: *value = c.red; return true;
    case EGL_GREEN_SIZE: *value = c.green; return true;
    case EGL_BLUE_SIZE: *value = c.blue; return true;
    case EGL_ALPHA_SIZE: *value = c.alpha; return true;
    case EGL_DEPTH_SIZE: *value = c.depth; return true;
    case EGL_STENCIL_SIZE: *value = c.stencil; return true;
    case EGL_CONFIG_ID: *value = c.id; return true;
    case EGL_SURFACE_TYPE: *value = c.surface_type; return true;
    case EGL_SAMPLE_BUFFERS: *value = c.samples > 0; return true;
    case EGL_SAMPLES: *value = c.samples; return true;
    case EGL_RENDERABLE_TYPE: *value = c.renderable_type; return true;
    case EGL_CONFORMANT: *value = c.renderable_type & kConformant; return true;
    case EGL_COLOR_BUFFER_TYPE: *value = EGL_RGB_BUFFER; return true;
    case EGL_CONFIG_CAVEAT: *value = EGL_NONE; return true;
    case EGL_TRANSPARENT_TYPE: *value = EGL_NONE; return true;
    case EGL_NATIVE_VISUAL_TYPE: *value = c.native_visual_type; return true;
    case EGL_NATIVE_VISUAL_ID: *value = c.native_visual_id; return true;
    case EGL_BIND_TO_TEXTURE_RGB:
    case EGL_BIND_TO_TEXTURE_RGBA:
    case EGL_NATIVE_RENDERABLE: *value = EGL_FALSE; return true;
    case EGL_MAX_PBUFFER_WIDTH: *value = kMaxPbufferWidth; return true;
    case EGL_MAX_PBUFFER_HEIGHT: *value = kMaxPbufferHeight; return true;
    case EGL_MAX_PBUFFER_PIXELS: *value = kMaxPbufferPixels; return true;
    case EGL_MIN_SWAP_INTERVAL: *value = kMinSwapInterval; return true;
    case EGL_MAX_SWAP_INTERVAL: *value = kMaxSwapInterval; return true;
    case EGL_ALPHA_MASK_SIZE:
    case EGL_LUMINANCE_SIZE:
    case EGL_LEVEL:
    case EGL_TRANSPARENT_RED_VALUE:
    case EGL_TRANSPARENT_GREEN_VALUE:
    case EGL_TRANSPARENT_BLUE_VALUE: *value = 0; return true;
    default: return false;
  }
}

EGLBoolean GetConfigs(EGLDisplay dpy, EGLConfig* configs, EGLint config_size, EGLint* num_config) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  if (!num_config) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  std::vector<const Config*> list;
  for (const Config& c : display->configs) list.push_back(&c);
  return copy_out(list, configs, config_size, num_config);
}

EGLBoolean ChooseConfig(EGLDisplay dpy, const EGLint* attrib_list, EGLConfig* configs,
                        EGLint config_size, EGLint* num_config) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  if (!num_config) return fail(EGL_BAD_PARAMETER, EGL_FALSE);

  std::vector<EGLint> wanted(kCriteriaCount);
  for (size_t i = 0; i < kCriteriaCount; ++i) wanted[i] = kCriteria[i].default_value;
  for (const EGLint* a = attrib_list; a && a[0] != EGL_NONE; a += 2) {
    int index = criterion_index(a[0]);
    if (index < 0) return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
    wanted[index] = a[1];
  }
  // A given config ID overrides every other attribute.
  EGLint id = wanted[criterion_index(EGL_CONFIG_ID)];
  std::vector<const Config*> list;
  for (const Config& c : display->configs) {
    if (id != EGL_DONT_CARE ? c.id == id : matches(c, wanted)) list.push_back(&c);
  }
  std::stable_sort(list.begin(), list.end(), [&](const Config* a, const Config* b) {
    return sorts_before(*a, *b, wanted);
  });
  return copy_out(list, configs, config_size, num_config);
}

EGLBoolean GetConfigAttrib(EGLDisplay dpy, EGLConfig config, EGLint attribute, EGLint* value) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  const Config* c = find_config(*display, config);
  if (!c) return fail(EGL_BAD_CONFIG, EGL_FALSE);
  EGLint result = 0;
  if (!config_attribute(*c, attribute, &result)) return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  *value = result;
  return succeed(EGL_TRUE);
}

}  // namespace pineda::egl
