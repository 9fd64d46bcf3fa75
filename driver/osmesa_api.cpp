// The OSMesa API (GL/osmesa.h): contexts that render into the caller's memory.
#include <GL/osmesa.h>

#include <cstring>
#include <mutex>

#include "driver/gl_version.h"
#include "driver/osmesa_context.h"
#include "glapi/current.h"
#include "glapi/proc_table.h"

#define PINEDA_EXPORT extern "C" __attribute__((visibility("default")))

namespace {

using pineda::osmesa::bytes_per_pixel;

std::mutex& owner_mutex() {
  static std::mutex* m = new std::mutex;
  return *m;
}

thread_local osmesa_context* current = nullptr;
// Its address tells threads apart in osmesa_context::owner.
thread_local char thread_token;

struct Request {
  GLenum format = OSMESA_RGBA;
  int depth_bits = 24, stencil_bits = 8;
  int major = 1, minor = 0;
  bool core = false;
};

// The depth sizes the rasterizer stores; a request is rounded up to one of them.
int depth_size(int bits) {
  if (bits <= 0) return 0;
  if (bits <= 16) return 16;
  if (bits <= 24) return 24;
  return 32;
}

OSMesaContext create(const Request& r, OSMesaContext sharelist) {
  if (bytes_per_pixel(r.format) == 0) return nullptr;  // colour index, RGB_565
  if (r.core || !pineda::driver::gl_version_supported(r.major, r.minor)) return nullptr;
  try {
    auto ctx = std::make_unique<osmesa_context>();
    ctx->format = r.format;
    ctx->depth_bits = depth_size(r.depth_bits);
    ctx->stencil_bits = r.stencil_bits > 0 ? 8 : 0;
    ctx->gl = std::make_unique<pineda::Context>(
        pineda::ContextAttribs{.major = pineda::driver::kMaxGLMajor, .minor = pineda::driver::kMaxGLMinor},
        sharelist ? sharelist->gl->share_group() : nullptr);
    return ctx.release();
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

bool destroy_if_unowned(OSMesaContext ctx) {
  std::unique_lock lock(owner_mutex());
  if (ctx->owner) {
    ctx->destroy_pending = true;  // the owning thread frees it when it lets go
    return false;
  }
  lock.unlock();
  delete ctx;
  return true;
}

// Ends the calling thread's binding: the user's image is brought up to date first.
void unbind_current() {
  osmesa_context* ctx = current;
  if (!ctx) return;
  ctx->update_user_image();
  ctx->gl->release_current();
  pineda::glapi::set_flush_listener(nullptr, nullptr);
  pineda::set_current_context(nullptr);
  current = nullptr;
  bool destroy;
  {
    std::lock_guard lock(owner_mutex());
    ctx->owner = nullptr;
    destroy = ctx->destroy_pending;
  }
  if (destroy) delete ctx;
}

// A thread that ends with a context current lets go of it, so that another thread can
// bind it and OSMesaDestroyContext can free it.
struct ThreadExit {
  ~ThreadExit() { unbind_current(); }
};
thread_local ThreadExit thread_exit;

void note_binding() { (void)&thread_exit; }  // odr-use: constructs the thread's guard

}  // namespace

PINEDA_EXPORT OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist) {
  return create(Request{.format = format}, sharelist);
}

PINEDA_EXPORT OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits,
                                                              GLint stencilBits, GLint accumBits,
                                                              OSMesaContext sharelist) {
  // Every context has a 16-bit accumulation buffer (state/accum.h): accumBits asks for no more.
  return create(Request{.format = format, .depth_bits = depthBits, .stencil_bits = stencilBits},
                sharelist);
}

PINEDA_EXPORT OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int* attribList,
                                                                  OSMesaContext sharelist) {
  Request r{.depth_bits = 0, .stencil_bits = 0};
  for (const int* a = attribList; a && a[0] != 0; a += 2) {
    switch (a[0]) {
      case OSMESA_FORMAT: r.format = static_cast<GLenum>(a[1]); break;
      case OSMESA_DEPTH_BITS: r.depth_bits = a[1]; break;
      case OSMESA_STENCIL_BITS: r.stencil_bits = a[1]; break;
      case OSMESA_ACCUM_BITS: break;
      case OSMESA_PROFILE:
        if (a[1] != OSMESA_CORE_PROFILE && a[1] != OSMESA_COMPAT_PROFILE) return nullptr;
        r.core = a[1] == OSMESA_CORE_PROFILE;
        break;
      case OSMESA_CONTEXT_MAJOR_VERSION: r.major = a[1]; break;
      case OSMESA_CONTEXT_MINOR_VERSION: r.minor = a[1]; break;
      default: return nullptr;
    }
  }
  return create(r, sharelist);
}

PINEDA_EXPORT void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx) {
  if (!ctx) return;
  if (ctx == current) unbind_current();
  destroy_if_unowned(ctx);
}

PINEDA_EXPORT GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type,
                                                     GLsizei width, GLsizei height) {
  // As in Mesa, (NULL, NULL) releases the current context.
  if (!ctx && !buffer) {
    unbind_current();
    return GL_TRUE;
  }
  if (!ctx || !buffer || type != GL_UNSIGNED_BYTE) return GL_FALSE;
  if (width < 1 || height < 1 || width > pineda::osmesa::kMaxSize ||
      height > pineda::osmesa::kMaxSize)
    return GL_FALSE;
  {
    // A context current to another thread cannot be bound here.
    std::lock_guard lock(owner_mutex());
    if (ctx->destroy_pending || (ctx->owner && ctx->owner != &thread_token)) return GL_FALSE;
    ctx->owner = &thread_token;  // keeps it from being freed by the unbind below
  }
  if (current == ctx) {
    ctx->update_user_image();  // the old image gets what was drawn into it
  } else {
    unbind_current();
  }
  try {
    ctx->attach(static_cast<uint8_t*>(buffer), width, height);
  } catch (const std::bad_alloc&) {
    if (current == ctx) unbind_current();
    std::lock_guard lock(owner_mutex());
    ctx->owner = nullptr;
    return GL_FALSE;
  }
  current = ctx;
  note_binding();
  pineda::set_current_context(ctx->gl.get());
  ctx->gl->make_current(&ctx->drawable, &ctx->drawable);
  pineda::glapi::set_flush_listener(ctx->gl.get(), ctx);
  return GL_TRUE;
}

PINEDA_EXPORT OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void) { return current; }

PINEDA_EXPORT void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value) {
  osmesa_context* ctx = current;
  if (!ctx) return;
  switch (pname) {
    case OSMESA_ROW_LENGTH:
      if (value < 0) return ctx->gl->record_error(GL_INVALID_VALUE, "value is negative");
      ctx->update_user_image();
      ctx->row_length = value;
      break;
    case OSMESA_Y_UP:
      ctx->update_user_image();
      ctx->user.y_up = value != 0;
      break;
    default: return ctx->gl->record_error(GL_INVALID_ENUM, "pname is not an OSMesa pixel store parameter");
  }
  ctx->relayout();
  ctx->gl->drawable_changed();
}

PINEDA_EXPORT void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint* value) {
  osmesa_context* ctx = current;
  if (!value) return;
  switch (pname) {
    case OSMESA_MAX_WIDTH:
    case OSMESA_MAX_HEIGHT: *value = pineda::osmesa::kMaxSize; return;
    default: break;
  }
  if (!ctx) return;
  switch (pname) {
    case OSMESA_WIDTH: *value = ctx->user.width; break;
    case OSMESA_HEIGHT: *value = ctx->user.height; break;
    case OSMESA_FORMAT: *value = static_cast<GLint>(ctx->format); break;
    case OSMESA_TYPE: *value = GL_UNSIGNED_BYTE; break;
    case OSMESA_ROW_LENGTH: *value = ctx->row_length; break;
    case OSMESA_Y_UP: *value = ctx->user.y_up ? 1 : 0; break;
    default: ctx->gl->record_error(GL_INVALID_ENUM, "pname is not an OSMesa integer"); break;
  }
}

PINEDA_EXPORT GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint* width,
                                                        GLint* height, GLint* bytesPerValue,
                                                        void** buffer) {
  const bool ok = c && c->user.pixels && c->depth_bits > 0;
  if (ok && c == current) c->gl->finish();
  // Depth is stored as one 32-bit unsigned value per pixel, whatever its bit count.
  if (width) *width = ok ? c->user.width : 0;
  if (height) *height = ok ? c->user.height : 0;
  if (bytesPerValue) *bytesPerValue = ok ? 4 : 0;
  if (buffer) *buffer = ok ? c->depth.data() : nullptr;
  return ok ? GL_TRUE : GL_FALSE;
}

PINEDA_EXPORT GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint* width,
                                                        GLint* height, GLint* format,
                                                        void** buffer) {
  const bool ok = c && c->user.pixels;
  if (ok && c == current) c->update_user_image();
  if (width) *width = ok ? c->user.width : 0;
  if (height) *height = ok ? c->user.height : 0;
  if (format) *format = ok ? static_cast<GLint>(c->format) : 0;
  if (buffer) *buffer = ok ? c->user.pixels : nullptr;
  return ok ? GL_TRUE : GL_FALSE;
}

PINEDA_EXPORT void GLAPIENTRY OSMesaColorClamp(GLboolean enable) {
  // Colours are always clamped: every colour buffer is 8-bit unsigned normalized.
}

PINEDA_EXPORT void GLAPIENTRY OSMesaPostprocess(OSMesaContext osmesa, const char* filter,
                                                unsigned enable_value) {
  // No post-processing filters.
}

PINEDA_EXPORT OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char* funcName) {
  struct Entry {
    const char* name;
    OSMESAproc proc;
  };
  static const Entry kOSMesa[] = {
      {"OSMesaColorClamp", reinterpret_cast<OSMESAproc>(&OSMesaColorClamp)},
      {"OSMesaCreateContext", reinterpret_cast<OSMESAproc>(&OSMesaCreateContext)},
      {"OSMesaCreateContextAttribs", reinterpret_cast<OSMESAproc>(&OSMesaCreateContextAttribs)},
      {"OSMesaCreateContextExt", reinterpret_cast<OSMESAproc>(&OSMesaCreateContextExt)},
      {"OSMesaDestroyContext", reinterpret_cast<OSMESAproc>(&OSMesaDestroyContext)},
      {"OSMesaGetColorBuffer", reinterpret_cast<OSMESAproc>(&OSMesaGetColorBuffer)},
      {"OSMesaGetCurrentContext", reinterpret_cast<OSMESAproc>(&OSMesaGetCurrentContext)},
      {"OSMesaGetDepthBuffer", reinterpret_cast<OSMESAproc>(&OSMesaGetDepthBuffer)},
      {"OSMesaGetIntegerv", reinterpret_cast<OSMESAproc>(&OSMesaGetIntegerv)},
      {"OSMesaGetProcAddress", reinterpret_cast<OSMESAproc>(&OSMesaGetProcAddress)},
      {"OSMesaMakeCurrent", reinterpret_cast<OSMESAproc>(&OSMesaMakeCurrent)},
      {"OSMesaPixelStore", reinterpret_cast<OSMESAproc>(&OSMesaPixelStore)},
      {"OSMesaPostprocess", reinterpret_cast<OSMESAproc>(&OSMesaPostprocess)},
  };
  if (!funcName) return nullptr;
  for (const Entry& e : kOSMesa)
    if (std::strcmp(e.name, funcName) == 0) return e.proc;
  return reinterpret_cast<OSMESAproc>(pineda::glapi::lookup_gl_proc(funcName));
}
