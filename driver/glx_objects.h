// The objects behind GLX handles and XIDs. A GLXContext or GLXFBConfig is the address of its
// object, but it is only dereferenced after it was found in the registry (glx_registry.h).
//
// Include this header before any X11 header: X.h defines macros (Always, None, ...) that
// collide with names in state/ and raster/.
#pragma once
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "raster/cache_line_vector.h"
#include "state/context.h"
#include "state/drawable.h"

#define GLX_GLXEXT_PROTOTYPES
#include <GL/glx.h>
#include <GL/glxext.h>

#include "driver/glx_shm.h"

#define PINEDA_GLX_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda::glx {

struct Config {
  int id = 0;  // GLX_FBCONFIG_ID
  int screen = 0;
  VisualID visual_id = 0;
  int visual_depth = 0;  // of the X visual: 24 or 32
  int red = 8, green = 8, blue = 8, alpha = 0;
  int depth = 0, stencil = 0;
  bool double_buffered = false;
  int samples = 0;  // GLX_SAMPLES: 0, or 4 with GLX_SAMPLE_BUFFERS 1 (double-buffered configs)
  // The first config of its visual: the one the visual-based calls (glXChooseVisual,
  // glXGetConfig, glXCreateContext) stand for.
  bool visual_canonical = false;

  int buffer_size() const { return red + green + blue + alpha; }
};

struct ContextObject {
  Display* dpy = nullptr;
  const Config* config = nullptr;
  bool direct = true;
  std::unique_ptr<pineda::Context> gl;
  const void* bound_thread = nullptr;  // guarded by the registry mutex
};

enum class DrawableKind { Window, Pixmap, Pbuffer };

struct DrawableObject {
  Display* dpy = nullptr;
  XID id = 0;                // the GLX drawable: a GLXWindow/GLXPixmap/GLXPbuffer, or a window
  ::Drawable x_drawable = 0;  // the X window or pixmap; 0 for a pbuffer
  DrawableKind kind = DrawableKind::Window;
  bool implicit = false;  // a plain X window made current without glXCreateWindow
  const Config* config = nullptr;
  Visual* visual = nullptr;
  int x_depth = 24;
  GC gc = nullptr;  // made with the drawable, while it surely exists (GCs outlive windows)
  unsigned long event_mask = 0;
  bool preserved_contents = true, largest_pbuffer = false;
  int swap_interval = 1;

  // Pineda's buffers; colour rows top-down in memory, so an XImage can point at them. The
  // front colour buffer (what X shows) is in `shm` when the server offers MIT-SHM, otherwise
  // in `color`; a double-buffered window or pbuffer also has `back`.
  int width = 0, height = 0;
  bool allocated = false;
  uint8_t* pixels = nullptr;  // the front buffer
  std::unique_ptr<SharedImage> shm;
  pineda::raster::CacheLineVector<uint8_t> color;
  pineda::raster::CacheLineVector<uint8_t> back;
  pineda::raster::CacheLineVector<uint8_t> sample_color;  // a multisampled config's 4 colour planes (back is their resolve)
  pineda::raster::CacheLineVector<uint32_t> depth;
  pineda::raster::CacheLineVector<uint8_t> stencil;
  pineda::Drawable drawable;

  int bindings = 0;  // threads that have it current as draw or read; guarded by the registry

  DrawableObject() = default;
  DrawableObject(const DrawableObject&) = delete;
  DrawableObject& operator=(const DrawableObject&) = delete;
  // The X window or pixmap belongs to the application; the GC is ours.
  ~DrawableObject() {
    if (dpy && gc) XFreeGC(dpy, gc);
  }
};

struct DisplayState {
  Display* dpy = nullptr;
  bool server_glx = false;
  int major_opcode = 0, event_base = 0, error_base = 0;
  std::vector<std::unique_ptr<Config>> configs;  // all screens, best first per screen
  std::unordered_map<GLXContext, std::shared_ptr<ContextObject>> contexts;
  std::unordered_map<XID, std::shared_ptr<DrawableObject>> drawables;
  // GLX drawables that were destroyed: naming one is GLXBadDrawable, not an X window.
  std::unordered_set<XID> retired;

  const Config* find_config(GLXFBConfig handle) const {
    for (auto& c : configs)
      if (reinterpret_cast<GLXFBConfig>(c.get()) == handle) return c.get();
    return nullptr;
  }
  std::shared_ptr<ContextObject> find_context(GLXContext handle) const {
    auto it = contexts.find(handle);
    return it == contexts.end() ? nullptr : it->second;
  }
  std::shared_ptr<DrawableObject> find_drawable(XID id) const {
    auto it = drawables.find(id);
    return it == drawables.end() ? nullptr : it->second;
  }
};

inline GLXFBConfig handle_of(const Config* c) {
  return reinterpret_cast<GLXFBConfig>(const_cast<Config*>(c));
}
inline GLXContext handle_of(const ContextObject* c) {
  return reinterpret_cast<GLXContext>(const_cast<ContextObject*>(c));
}

}  // namespace pineda::glx
