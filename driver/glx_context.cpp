// GLX contexts: glXCreateContext, glXCreateNewContext, glXCreateContextAttribsARB,
// glXDestroyContext, glXQueryContext, glXIsDirect, glXCopyContext.
#include "driver/glx_objects.h"

#include <optional>

#include "driver/gl_version.h"
#include "driver/glx_config.h"
#include "driver/glx_current.h"
#include "driver/glx_error.h"
#include "driver/glx_registry.h"

namespace pineda::glx {
namespace {

struct Failure {
  unsigned char code;
  bool glx;
};

std::optional<Failure> x_failure(unsigned char code) { return Failure{code, false}; }
std::optional<Failure> glx_failure(GlxError code) {
  return Failure{static_cast<unsigned char>(code), true};
}

void report(Display* dpy, const Failure& f, GlxRequest minor_opcode) {
  if (f.glx)
    send_glx_error(dpy, static_cast<GlxError>(f.code), minor_opcode);
  else
    send_x_error(dpy, f.code, minor_opcode);
}

struct Request {
  int major = 1, minor = 0;
  int flags = 0;
  int profile = GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
  int render_type = GLX_RGBA_TYPE;
  int reset_strategy = GLX_NO_RESET_NOTIFICATION_ARB;
};

bool es_profile(const Request& r) { return r.profile == GLX_CONTEXT_ES_PROFILE_BIT_EXT; }

// GLX_EXT_create_context_es_profile (and its older es2 form): ES 1.0 and 1.1 (a 1.1 context),
// 2.0. A version ES never had is GLXBadProfileARB (piglit's glx-create-context-invalid-es-version);
// ES 3.0-3.2, which Pineda does not have, GLXBadFBConfig, as for desktop versions.
std::optional<Failure> check_es(const Request& r) {
  if (!driver::gles_version_supported(r.major, r.minor))
    return glx_failure(r.major == 3 && r.minor >= 0 && r.minor <= 2 ? GlxError::GlxFBConfig : GlxError::GlxProfileARB);
  if (r.flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB) return x_failure(BadMatch);
  // ES 1.1 has no robustness extension (EGL refuses the same request with EGL_BAD_CONFIG).
  if (r.major == 1 && ((r.flags & GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB) || r.reset_strategy != GLX_NO_RESET_NOTIFICATION_ARB))
    return x_failure(BadMatch);
  return std::nullopt;
}

// GLX_ARB_create_context(_profile, _robustness)'s attribute rules.
std::optional<Failure> parse(const int* attribs, Request* r) {
  bool profile_given = false;
  for (const int* a = attribs; a && a[0] != None; a += 2) {
    switch (a[0]) {
      case GLX_CONTEXT_MAJOR_VERSION_ARB: r->major = a[1]; break;
      case GLX_CONTEXT_MINOR_VERSION_ARB: r->minor = a[1]; break;
      case GLX_CONTEXT_FLAGS_ARB: r->flags = a[1]; break;
      case GLX_CONTEXT_PROFILE_MASK_ARB: r->profile = a[1]; profile_given = true; break;
      case GLX_RENDER_TYPE: r->render_type = a[1]; break;
      case GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB: r->reset_strategy = a[1]; break;
      default: return x_failure(BadValue);
    }
  }
  if (r->flags & ~(GLX_CONTEXT_DEBUG_BIT_ARB | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB |
                   GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB))
    return x_failure(BadValue);
  // A strategy GLX does not define (piglit's glx-create-context-invalid-reset-strategy).
  if (r->reset_strategy != GLX_NO_RESET_NOTIFICATION_ARB && r->reset_strategy != GLX_LOSE_CONTEXT_ON_RESET_ARB)
    return x_failure(BadMatch);
  if (r->render_type != GLX_RGBA_TYPE) return x_failure(BadValue);
  if (profile_given && es_profile(*r)) return check_es(*r);
  if (!driver::is_gl_version(r->major, r->minor)) return x_failure(BadMatch);
  // Profiles exist from GL 3.2; before it the mask is ignored, but must still be valid.
  const int known = GLX_CONTEXT_CORE_PROFILE_BIT_ARB | GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
  if (profile_given && (r->profile == 0 || (r->profile & ~known) || r->profile == known))
    return glx_failure(GlxError::GlxProfileARB);
  if ((r->flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB) && r->major < 3) return x_failure(BadMatch);
  // GLX_ARB_create_context: a defined version the config cannot provide is GLXBadFBConfig
  // (BadMatch is for versions GL does not define).
  if (!driver::gl_version_supported(r->major, r->minor)) return glx_failure(GlxError::GlxFBConfig);
  return std::nullopt;
}

// The pineda::Context of a request; the version is always the highest (GL may return a later
// version compatible with the one asked for), or for an ES profile the ES version asked for.
ContextAttribs context_attribs(const Request& r) {
  ContextAttribs attribs{.major = driver::kMaxGLMajor, .minor = driver::kMaxGLMinor,
                         .debug = (r.flags & GLX_CONTEXT_DEBUG_BIT_ARB) != 0,
                         .robust_access = (r.flags & GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB) != 0,
                         .lose_context_on_reset = r.reset_strategy == GLX_LOSE_CONTEXT_ON_RESET_ARB};
  if (es_profile(r)) {  // the version asked for: ES 1.0 gets 1.1
    attribs.major = r.major;
    attribs.minor = r.major == 1 ? 1 : r.minor;
    attribs.gles = true;
  }
  return attribs;
}

// Caller holds the registry lock.
GLXContext create(DisplayState& d, const Config* config, GLXContext share, bool direct,
                  std::optional<Failure>* failure, const ContextAttribs& attribs = context_attribs({})) {
  std::shared_ptr<pineda::ShareGroup> share_group;
  if (share) {
    const std::shared_ptr<ContextObject> shared = d.find_context(share);
    if (!shared) {
      *failure = glx_failure(GlxError::GlxContext);
      return nullptr;
    }
    // GLX_ARB_create_context_robustness: shared contexts have the same reset strategy.
    if (shared->gl->attribs().lose_context_on_reset != attribs.lose_context_on_reset) {
      *failure = x_failure(BadMatch);
      return nullptr;
    }
    share_group = shared->gl->share_group();
  }
  auto object = std::make_shared<ContextObject>();
  object->dpy = d.dpy;
  object->config = config;
  object->direct = direct;
  try {
    object->gl = std::make_unique<pineda::Context>(attribs, std::move(share_group));
  } catch (const std::bad_alloc&) {
    *failure = x_failure(BadAlloc);
    return nullptr;
  }
  GLXContext handle = handle_of(object.get());
  d.contexts.emplace(handle, std::move(object));
  return handle;
}

template <class Body>
GLXContext create_reporting(Display* dpy, GlxRequest minor_opcode, Body body) {
  std::optional<Failure> failure;
  GLXContext result = nullptr;
  {
    auto lock = Registry::instance().lock();
    DisplayState* d = Registry::instance().get(dpy);
    if (!d) return nullptr;
    result = body(*d, &failure);
  }
  if (failure) report(dpy, *failure, minor_opcode);
  return failure ? nullptr : result;
}

}  // namespace

}  // namespace pineda::glx

using namespace pineda::glx;

PINEDA_GLX_EXPORT GLXContext glXCreateContext(Display* dpy, XVisualInfo* vis, GLXContext share,
                                              Bool direct) {
  return create_reporting(dpy, GlxRequest::CreateContext, [&](DisplayState& d, std::optional<Failure>* f) -> GLXContext {
    const Config* config = vis ? config_of_visual(d, vis->visualid) : nullptr;
    if (!config) {
      *f = x_failure(BadValue);
      return nullptr;
    }
    return create(d, config, share, direct, f);
  });
}

PINEDA_GLX_EXPORT GLXContext glXCreateNewContext(Display* dpy, GLXFBConfig fbconfig, int render_type,
                                                 GLXContext share, Bool direct) {
  return create_reporting(dpy, GlxRequest::CreateNewContext, [&](DisplayState& d, std::optional<Failure>* f) -> GLXContext {
    const Config* config = d.find_config(fbconfig);
    if (!config) {
      *f = glx_failure(GlxError::GlxFBConfig);
      return nullptr;
    }
    if (render_type != GLX_RGBA_TYPE) {
      *f = x_failure(render_type == GLX_COLOR_INDEX_TYPE ? BadMatch : BadValue);
      return nullptr;
    }
    return create(d, config, share, direct, f);
  });
}

PINEDA_GLX_EXPORT GLXContext glXCreateContextAttribsARB(Display* dpy, GLXFBConfig fbconfig,
                                                        GLXContext share, Bool direct,
                                                        const int* attribs) {
  return create_reporting(dpy, GlxRequest::CreateContextAttribsARB, [&](DisplayState& d, std::optional<Failure>* f) -> GLXContext {
    const Config* config = d.find_config(fbconfig);
    if (!config) {
      *f = glx_failure(GlxError::GlxFBConfig);
      return nullptr;
    }
    Request request;
    if ((*f = parse(attribs, &request))) return nullptr;
    return create(d, config, share, direct, f, context_attribs(request));
  });
}

PINEDA_GLX_EXPORT void glXDestroyContext(Display* dpy, GLXContext ctx) {
  std::shared_ptr<ContextObject> doomed;  // freed after the lock is released
  {
    auto lock = Registry::instance().lock();
    DisplayState* d = Registry::instance().get(dpy);
    if (!d) return;
    auto it = d->contexts.find(ctx);
    if (it != d->contexts.end()) {
      // A context current to a thread lives on through that thread's reference.
      doomed = std::move(it->second);
      d->contexts.erase(it);
    }
  }
  // Destroying the calling thread's current context again is harmless: it is still alive.
  const ThreadState& t = thread_state();
  const bool current_here = ctx && ctx == t.context_handle && dpy == t.dpy;
  if (!doomed && dpy && !current_here)
    send_glx_error(dpy, GlxError::GlxContext, GlxRequest::DestroyContext);
}

PINEDA_GLX_EXPORT int glXQueryContext(Display* dpy, GLXContext ctx, int attribute, int* value) {
  std::shared_ptr<ContextObject> object;
  {
    auto lock = Registry::instance().lock();
    DisplayState* d = Registry::instance().get(dpy);
    if (d) object = d->find_context(ctx);
  }
  if (!object) {
    send_glx_error(dpy, GlxError::GlxContext, GlxRequest::QueryContext);
    return GLX_BAD_CONTEXT;
  }
  if (!value) return GLX_BAD_VALUE;
  switch (attribute) {
    case GLX_FBCONFIG_ID: *value = object->config->id; return Success;
    case GLX_RENDER_TYPE: *value = GLX_RGBA_TYPE; return Success;
    case GLX_SCREEN: *value = object->config->screen; return Success;
    default: return GLX_BAD_ATTRIBUTE;
  }
}

PINEDA_GLX_EXPORT Bool glXIsDirect(Display* dpy, GLXContext ctx) {
  bool found;
  {
    auto lock = Registry::instance().lock();
    DisplayState* d = Registry::instance().get(dpy);
    found = d && d->find_context(ctx);
  }
  if (!found) {
    send_glx_error(dpy, GlxError::GlxContext, GlxRequest::IsDirect);
    return False;
  }
  // Every Pineda context renders in the client, whatever `direct` asked for.
  return True;
}

PINEDA_GLX_EXPORT void glXCopyContext(Display* dpy, GLXContext src, GLXContext dst,
                                      unsigned long mask) {
  std::shared_ptr<ContextObject> from, to;
  {
    auto lock = Registry::instance().lock();
    DisplayState* d = Registry::instance().get(dpy);
    if (d) {
      from = d->find_context(src);
      to = d->find_context(dst);
    }
  }
  if (!from || !to) {
    send_glx_error(dpy, GlxError::GlxContext, GlxRequest::CopyContext);
    return;
  }
  if (from == to || from->config->screen != to->config->screen) {
    send_x_error(dpy, BadMatch, GlxRequest::CopyContext);
    return;
  }
  {
    auto lock = Registry::instance().lock();
    if (to->bound_thread) {
      lock.unlock();
      send_x_error(dpy, BadAccess, GlxRequest::CopyContext);
      return;
    }
  }
  // The attribute groups whose state is plain values; the others are not copied yet.
  pineda::Context& s = *from->gl;
  pineda::Context& t = *to->gl;
  if (from->bound_thread == &thread_state()) s.finish();
  if (mask & GL_CURRENT_BIT) {
    std::copy(std::begin(s.current_color), std::end(s.current_color), t.current_color);
    std::copy(std::begin(s.current_normal), std::end(s.current_normal), t.current_normal);
    t.current_edge_flag = s.current_edge_flag;
  }
  if (mask & GL_COLOR_BUFFER_BIT)
    std::copy(std::begin(s.clear_color), std::end(s.clear_color), t.clear_color);
  if (mask & GL_DEPTH_BUFFER_BIT) t.clear_depth = s.clear_depth;
  if (mask & GL_STENCIL_BUFFER_BIT) t.clear_stencil = s.clear_stencil;
  if (mask & GL_TRANSFORM_BIT) {
    t.matrix_mode = s.matrix_mode;
    t.normalize = s.normalize;
    t.rescale_normal = s.rescale_normal;
  }
  if (mask & GL_VIEWPORT_BIT) t.viewport = s.viewport;
  if (mask & GL_HINT_BIT) {
    t.hint_perspective = s.hint_perspective;
    t.hint_point = s.hint_point;
    t.hint_line = s.hint_line;
    t.hint_polygon = s.hint_polygon;
    t.hint_fog = s.hint_fog;
  }
  if (mask & GL_LIGHTING_BIT) {
    t.lighting = s.lighting;
    t.shade_model = s.shade_model;
    t.color_material_face = s.color_material_face;
    t.color_material_mode = s.color_material_mode;
  }
}
