// The objects behind EGL handles. A handle is the address of its object, but it is only
// dereferenced after it was found in the registry (egl_registry.h).
#pragma once
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "raster/cache_line_vector.h"
#include "state/context.h"
#include "state/drawable.h"

namespace pineda::glx {
struct Config;
struct DrawableObject;
}  // namespace pineda::glx

namespace pineda::egl {

struct Config {
  EGLint id;
  EGLint red, green, blue, alpha;
  EGLint depth, stencil;
  EGLint surface_type;
  EGLint renderable_type;
  // On the X11 platform: the X visual that windows and pixmaps of this config use.
  EGLint native_visual_id = 0;
  EGLint native_visual_type = EGL_NONE;
  EGLint samples = 0;  // EGL_SAMPLES: 0, or 4 with EGL_SAMPLE_BUFFERS 1
};

struct Surface;
struct ThreadState;

struct ContextObject {
  const Config* config = nullptr;
  EGLenum api = EGL_OPENGL_API;
  int major = 1, minor = 0;
  std::unique_ptr<pineda::Context> gl;
  const ThreadState* bound_thread = nullptr;  // guarded by the registry mutex
  bool bound_to_surface = false;              // guarded by the registry mutex
};

struct Surface {
  const Config* config = nullptr;
  int width = 0, height = 0;
  bool largest_pbuffer = false;
  EGLint swap_interval = 1;
  pineda::raster::CacheLineVector<uint8_t> color;
  pineda::raster::CacheLineVector<uint8_t> sample_color;  // a multisampled config's 4 colour planes (color is their resolve)
  pineda::raster::CacheLineVector<uint32_t> depth;
  pineda::raster::CacheLineVector<uint8_t> stencil;
  pineda::Drawable drawable;
  const ThreadState* bound_thread = nullptr;  // guarded by the registry mutex
  // A window or pixmap surface (X11 platform): its buffers and presentation are GLX's
  // (egl_x11.h); `drawable` above is then unused.
  std::shared_ptr<glx::DrawableObject> native;
  std::shared_ptr<glx::Config> native_config;

  pineda::Drawable* gl_drawable();
};

// A fence: Pineda completes the rendering when the fence is created, so it is born signaled.
struct Sync {
  EGLenum type = EGL_SYNC_FENCE;
};

struct Display {
  EGLenum platform = 0;
  void* native = nullptr;  // EGL_PLATFORM_X11_KHR: the Display* (null: the default display)
  void* x11 = nullptr;     // the Display* in use, once initialized
  int screen = 0;
  bool initialized = false;
  // Made at the first eglInitialize; a config handle is the address of one of them.
  std::vector<Config> configs;
  std::unordered_map<EGLContext, std::shared_ptr<ContextObject>> contexts;
  std::unordered_map<EGLSurface, std::shared_ptr<Surface>> surfaces;
  std::unordered_map<EGLSync, std::unique_ptr<Sync>> syncs;

  std::shared_ptr<ContextObject> find_context(EGLContext handle) const {
    auto it = contexts.find(handle);
    return it == contexts.end() ? nullptr : it->second;
  }
  std::shared_ptr<Surface> find_surface(EGLSurface handle) const {
    auto it = surfaces.find(handle);
    return it == surfaces.end() ? nullptr : it->second;
  }
};

}  // namespace pineda::egl
