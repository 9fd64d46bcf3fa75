// The objects behind EGL handles. A handle is the address of its object, but it is only
// dereferenced after it was found in the registry (egl_registry.h).
#pragma once
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "state/context.h"
#include "state/drawable.h"

namespace pineda::egl {

struct Config {
  EGLint id;
  EGLint red, green, blue, alpha;
  EGLint depth, stencil;
  EGLint surface_type;
  EGLint renderable_type;
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
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  pineda::Drawable drawable;
  const ThreadState* bound_thread = nullptr;  // guarded by the registry mutex
};

// A fence: Pineda completes the rendering when the fence is created, so it is born signaled.
struct Sync {
  EGLenum type = EGL_SYNC_FENCE;
};

struct Display {
  EGLenum platform = 0;
  void* native = nullptr;
  bool initialized = false;
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
