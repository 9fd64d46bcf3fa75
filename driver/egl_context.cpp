// eglBindAPI, eglQueryAPI, eglCreateContext (with EGL_KHR_create_context and
// EGL_EXT_create_context_robustness attributes),
// eglDestroyContext, eglQueryContext.
#include "driver/egl_config.h"
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "driver/gl_version.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {
namespace {

struct Request {
  EGLint major = 1, minor = 0;
  EGLint flags = 0;
  bool robust = false;
  bool debug = false;
  EGLint reset_strategy = EGL_NO_RESET_NOTIFICATION;
};

// Returns EGL_SUCCESS or the error for the attribute list. The OpenGL-only attributes are
// errors for OpenGL ES (EGL 1.5, 3.7.1.1), and so are, as in Mesa, the forward-compatible and
// robust access bits of EGL_CONTEXT_FLAGS_KHR (EGL_KHR_create_context, issue 10: ES asks for
// robust access through EGL_EXT_create_context_robustness); that extension's reset strategy
// is an error for OpenGL.
EGLint parse_attributes(const EGLint* attribs, bool gles, Request* r) {
  constexpr EGLint kKnownFlags = EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR |
                                 EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR |
                                 EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR;
  for (const EGLint* a = attribs; a && a[0] != EGL_NONE; a += 2) {
    EGLint value = a[1];
    switch (a[0]) {
      case EGL_CONTEXT_MAJOR_VERSION: r->major = value; break;  // = EGL_CONTEXT_CLIENT_VERSION
      case EGL_CONTEXT_MINOR_VERSION: r->minor = value; break;
      case EGL_CONTEXT_FLAGS_KHR:
        if (value & ~kKnownFlags) return EGL_BAD_ATTRIBUTE;
        if (gles && (value & (EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR | EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR)))
          return EGL_BAD_ATTRIBUTE;
        r->flags = value;
        if (value & EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR) r->robust = true;
        if (value & EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR) r->debug = true;
        break;
      case EGL_CONTEXT_OPENGL_PROFILE_MASK:
        if (gles) return EGL_BAD_ATTRIBUTE;
        if (!(value & (EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT |
                       EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT)))
          return EGL_BAD_ATTRIBUTE;
        break;  // below GL 3.2 the profile is ignored
      case EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE:
        if (gles) return EGL_BAD_ATTRIBUTE;
        [[fallthrough]];
      case EGL_CONTEXT_OPENGL_DEBUG:
        if (value != EGL_TRUE && value != EGL_FALSE) return EGL_BAD_ATTRIBUTE;
        if (a[0] == EGL_CONTEXT_OPENGL_DEBUG) r->debug = value == EGL_TRUE;
        break;
      case EGL_CONTEXT_OPENGL_ROBUST_ACCESS:
      case EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT:
        if (value != EGL_TRUE && value != EGL_FALSE) return EGL_BAD_ATTRIBUTE;
        r->robust = value == EGL_TRUE;
        break;
      case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT:
        if (!gles) return EGL_BAD_ATTRIBUTE;
        [[fallthrough]];
      case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY:
        // The two names share their values (EGL_NO_RESET_NOTIFICATION_EXT = EGL_NO_RESET_NOTIFICATION).
        if (value != EGL_NO_RESET_NOTIFICATION && value != EGL_LOSE_CONTEXT_ON_RESET)
          return EGL_BAD_ATTRIBUTE;
        r->reset_strategy = value;
        break;
      default: return EGL_BAD_ATTRIBUTE;
    }
  }
  return EGL_SUCCESS;
}

}  // namespace

EGLBoolean BindAPI(EGLenum api) {
  const bool supported = api == EGL_OPENGL_API || (api == EGL_OPENGL_ES_API && driver::kHasGLES);
  if (!supported) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  thread_state().api = api;
  return succeed(EGL_TRUE);
}

EGLenum QueryAPI() { return succeed(thread_state().api); }

EGLContext CreateContext(EGLDisplay dpy, EGLConfig config, EGLContext share_context,
                         const EGLint* attrib_list) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_NO_CONTEXT;
  const EGLenum api = thread_state().api;
  if (api == EGL_NONE) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  const bool gles = api == EGL_OPENGL_ES_API;
  const Config* c = find_config(*display, config);
  if (!c) return fail(EGL_BAD_CONFIG, EGL_NO_CONTEXT);
  std::shared_ptr<pineda::ShareGroup> share_group;
  bool shared_lose_context_on_reset = false;
  if (share_context != EGL_NO_CONTEXT) {
    const std::shared_ptr<ContextObject> shared = display->find_context(share_context);
    // Objects are shared within one client API only (Mesa: EGL_BAD_CONTEXT otherwise).
    if (!shared || shared->api != api) return fail(EGL_BAD_CONTEXT, EGL_NO_CONTEXT);
    share_group = shared->gl->share_group();
    shared_lose_context_on_reset = shared->gl->attribs().lose_context_on_reset;
  }
  Request request;
  if (EGLint error = parse_attributes(attrib_list, gles, &request); error != EGL_SUCCESS)
    return fail(error, EGL_NO_CONTEXT);
  const bool version_ok = gles ? driver::gles_version_supported(request.major, request.minor)
                               : driver::gl_version_supported(request.major, request.minor);
  if (!version_ok) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  // A config that cannot render the API: EGL 1.5, 3.7.1.
  const EGLint needed = !gles ? EGL_OPENGL_BIT : request.major == 1 ? EGL_OPENGL_ES_BIT : EGL_OPENGL_ES2_BIT;
  if (!(c->renderable_type & needed)) return fail(EGL_BAD_CONFIG, EGL_NO_CONTEXT);
  // Robustness is GL_ARB_robustness / GL_EXT_robustness, which OpenGL ES 1.1 lacks
  // (EGL_EXT_create_context_robustness: EGL_BAD_CONFIG).
  const bool lose_context_on_reset = request.reset_strategy == EGL_LOSE_CONTEXT_ON_RESET;
  if (gles && request.major == 1 && (request.robust || lose_context_on_reset))
    return fail(EGL_BAD_CONFIG, EGL_NO_CONTEXT);
  if (share_group && shared_lose_context_on_reset != lose_context_on_reset)
    return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);

  auto object = std::make_shared<ContextObject>();
  object->config = c;
  object->api = api;
  if (gles) {
    object->major = request.major;
    object->minor = request.major == 1 ? 1 : request.minor;
  } else {
    // GL may return a later version compatible with the one asked for: the highest one.
    object->major = driver::kMaxGLMajor;
    object->minor = driver::kMaxGLMinor;
  }
  try {
    object->gl = std::make_unique<pineda::Context>(
        ContextAttribs{.major = object->major, .minor = object->minor, .gles = gles, .debug = request.debug,
                       .robust_access = request.robust, .lose_context_on_reset = lose_context_on_reset},
        std::move(share_group));
  } catch (const std::bad_alloc&) {
    return fail(EGL_BAD_ALLOC, EGL_NO_CONTEXT);
  }
  EGLContext handle = object.get();
  display->contexts.emplace(handle, std::move(object));
  return succeed(handle);
}

EGLBoolean DestroyContext(EGLDisplay dpy, EGLContext ctx) {
  std::shared_ptr<ContextObject> doomed;  // destroyed after the lock is released
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  auto it = display->contexts.find(ctx);
  if (it == display->contexts.end()) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  // A context current to a thread lives on through that thread's reference.
  doomed = std::move(it->second);
  display->contexts.erase(it);
  lock.unlock();
  return succeed(EGL_TRUE);
}

EGLBoolean QueryContext(EGLDisplay dpy, EGLContext ctx, EGLint attribute, EGLint* value) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_FALSE;
  auto object = display->find_context(ctx);
  if (!object) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  EGLint result;
  switch (attribute) {
    case EGL_CONFIG_ID: result = object->config->id; break;
    case EGL_CONTEXT_CLIENT_TYPE: result = static_cast<EGLint>(object->api); break;
    case EGL_CONTEXT_CLIENT_VERSION: result = object->major; break;
    case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT:  // the extension's revision 4
      result = object->gl->attribs().lose_context_on_reset ? EGL_LOSE_CONTEXT_ON_RESET : EGL_NO_RESET_NOTIFICATION;
      break;
    case EGL_RENDER_BUFFER:
      // Pbuffers render to their back buffer; an unbound context reports EGL_NONE.
      result = object->bound_to_surface ? EGL_BACK_BUFFER : EGL_NONE;
      break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  *value = result;
  return succeed(EGL_TRUE);
}

}  // namespace pineda::egl
