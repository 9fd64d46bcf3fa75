// The fuzzed EGL calls: displays of the surfaceless and X11 platforms (no X server: X11's
// initialisation fails), configs chosen with random attribute lists, contexts of every API
// and version, pbuffers of random sizes, images, fence syncs, made current and destroyed with
// handles that are valid, stale (destroyed or terminated) or foreign (any pointer). Attribute
// lists carry bogus keys and values but always end with EGL_NONE. A context made current
// stays current for the GL calls that follow (an OpenGL ES 1.1 context runs es1_fixed_calls.cpp
// for real); when none is, the fuzzer's own context is made current again.
#define GL_GLEXT_PROTOTYPES
#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

// Everything EGL handed out during one input, destroyed or not: drawn from as stale handles.
struct EglSession {
  void (*restore_context)() = nullptr;  // makes the fuzzer's OSMesa context current
  std::vector<EGLDisplay> displays;
  std::vector<EGLConfig> configs;
  std::vector<EGLContext> contexts;
  std::vector<EGLSurface> surfaces;
  std::vector<EGLSync> syncs;
  std::vector<EGLImage> images;
};

EglSession session;

// Not EGL objects: no call may take them for one.
uint8_t foreign_object[64];

// One of `made` (most often), none, or a pointer to no object of the kind.
template <typename Handle>
Handle handle(FuzzInput& in, const std::vector<Handle>& made, Handle none) {
  const uint8_t pick = in.byte();
  if (pick % 8 == 7) return reinterpret_cast<Handle>(foreign_object + pick % 64);
  if (pick % 8 == 6 || made.empty()) return none;
  return made[(pick / 8) % made.size()];
}

EGLDisplay display(FuzzInput& in) { return handle<EGLDisplay>(in, session.displays, EGL_NO_DISPLAY); }
EGLConfig config(FuzzInput& in) { return handle<EGLConfig>(in, session.configs, nullptr); }
EGLContext context(FuzzInput& in) { return handle<EGLContext>(in, session.contexts, EGL_NO_CONTEXT); }
EGLSurface surface(FuzzInput& in) { return handle<EGLSurface>(in, session.surfaces, EGL_NO_SURFACE); }
EGLSync sync(FuzzInput& in) { return handle<EGLSync>(in, session.syncs, EGL_NO_SYNC); }

// An attribute list of up to 6 pairs of `keys` (or bogus keys) and values, EGL_NONE-terminated.
template <typename Attrib>
std::vector<Attrib> attributes(FuzzInput& in, std::initializer_list<GLenum> keys,
                               std::initializer_list<GLenum> values) {
  std::vector<Attrib> list;
  const int pairs = in.byte() % 7;
  for (int i = 0; i < pairs; ++i) {
    list.push_back(Attrib(in.enumeration(keys)));
    list.push_back(in.boolean() ? Attrib(in.enumeration(values)) : Attrib(in.integer(-2, 64)));
  }
  list.push_back(EGL_NONE);
  return list;
}

constexpr auto kConfigKeys = {
    GLenum(EGL_RED_SIZE),        GLenum(EGL_ALPHA_SIZE),      GLenum(EGL_DEPTH_SIZE),     GLenum(EGL_STENCIL_SIZE),
    GLenum(EGL_SURFACE_TYPE),    GLenum(EGL_RENDERABLE_TYPE), GLenum(EGL_CONFIG_ID),      GLenum(EGL_CONFORMANT),
    GLenum(EGL_SAMPLES),         GLenum(EGL_COLOR_BUFFER_TYPE), GLenum(EGL_CONFIG_CAVEAT), GLenum(EGL_BUFFER_SIZE),
    GLenum(EGL_MATCH_NATIVE_PIXMAP), GLenum(EGL_TRANSPARENT_TYPE), GLenum(EGL_MAX_PBUFFER_WIDTH),
    GLenum(EGL_BIND_TO_TEXTURE_RGBA), GLenum(EGL_LEVEL), GLenum(EGL_NATIVE_RENDERABLE)};
constexpr auto kConfigValues = {GLenum(EGL_DONT_CARE),     GLenum(EGL_PBUFFER_BIT),    GLenum(EGL_WINDOW_BIT),
                                GLenum(EGL_OPENGL_ES_BIT), GLenum(EGL_OPENGL_ES2_BIT), GLenum(EGL_OPENGL_BIT),
                                GLenum(EGL_RGB_BUFFER),    GLenum(EGL_NONE),           GLenum(EGL_TRUE)};
constexpr auto kContextKeys = {GLenum(EGL_CONTEXT_CLIENT_VERSION), GLenum(EGL_CONTEXT_MINOR_VERSION),
                               GLenum(EGL_CONTEXT_OPENGL_PROFILE_MASK), GLenum(EGL_CONTEXT_OPENGL_DEBUG),
                               GLenum(EGL_CONTEXT_OPENGL_ROBUST_ACCESS),
                               GLenum(EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY),
                               GLenum(EGL_CONTEXT_FLAGS_KHR), GLenum(EGL_CONTEXT_OPENGL_NO_ERROR_KHR)};
constexpr auto kContextValues = {GLenum(1), GLenum(2), GLenum(3), GLenum(EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT),
                                 GLenum(EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT),
                                 GLenum(EGL_LOSE_CONTEXT_ON_RESET), GLenum(EGL_NO_RESET_NOTIFICATION)};
constexpr auto kSurfaceKeys = {GLenum(EGL_WIDTH), GLenum(EGL_HEIGHT), GLenum(EGL_LARGEST_PBUFFER),
                               GLenum(EGL_TEXTURE_FORMAT), GLenum(EGL_TEXTURE_TARGET), GLenum(EGL_MIPMAP_TEXTURE),
                               GLenum(EGL_GL_COLORSPACE), GLenum(EGL_VG_ALPHA_FORMAT), GLenum(EGL_RENDER_BUFFER)};
constexpr auto kSurfaceValues = {GLenum(EGL_TEXTURE_RGBA), GLenum(EGL_TEXTURE_RGB), GLenum(EGL_TEXTURE_2D),
                                 GLenum(EGL_NO_TEXTURE),   GLenum(EGL_GL_COLORSPACE_SRGB), GLenum(EGL_BACK_BUFFER),
                                 GLenum(EGL_TRUE)};

void initialize(FuzzInput& in, ClientMemory&) {
  EGLint major = 0, minor = 0;
  const EGLDisplay dpy = display(in);
  if (in.boolean()) eglInitialize(dpy, &major, &minor);
  else eglInitialize(dpy, nullptr, nullptr);
}

void choose_config(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = display(in);
  const std::vector<EGLint> list = attributes<EGLint>(in, kConfigKeys, kConfigValues);
  const EGLint size = std::min(in.integer(0, 4), 4);
  std::vector<EGLConfig> configs(size_t(std::max(size, 0)) + (size <= 0));
  EGLint found = 0;
  const bool into_array = in.boolean();
  if (!eglChooseConfig(dpy, in.byte() % 8 ? list.data() : nullptr, into_array ? configs.data() : nullptr, size, &found))
    return;
  // A negative size (the fuzzer's extremes) returns no config, and clamping to it would not.
  if (into_array && size > 0)
    session.configs.insert(session.configs.end(), configs.begin(), configs.begin() + std::clamp(found, 0, size));
}

void get_configs(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = display(in);
  const EGLint size = std::min(in.integer(0, 8), 8);
  std::vector<EGLConfig> configs(size_t(std::max(size, 0)) + (size <= 0));
  EGLint found = 0;
  if (eglGetConfigs(dpy, in.boolean() ? configs.data() : nullptr, size, &found) && found > 0 && size > 0)
    session.configs.push_back(configs[0]);
}

void create_context(FuzzInput& in, ClientMemory&) {
  eglBindAPI(in.enumeration({EGL_OPENGL_ES_API, EGL_OPENGL_API, EGL_OPENVG_API}));
  const EGLDisplay dpy = display(in);
  const EGLConfig cfg = in.byte() % 8 ? config(in) : EGL_NO_CONFIG_KHR;
  const EGLContext share = context(in);
  const std::vector<EGLint> list = attributes<EGLint>(in, kContextKeys, kContextValues);
  const EGLContext made = eglCreateContext(dpy, cfg, share, list.data());
  if (made != EGL_NO_CONTEXT) session.contexts.push_back(made);
}

void create_pbuffer(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = display(in);
  const EGLConfig cfg = config(in);
  // A width and height within 64 or beyond every limit (8192): a 8192x8192 pbuffer is valid
  // but takes half a gigabyte.
  std::vector<EGLint> list = attributes<EGLint>(in, kSurfaceKeys, kSurfaceValues);
  for (size_t i = 0; i + 1 < list.size(); i += 2)
    if (list[i] == EGL_WIDTH || list[i] == EGL_HEIGHT) list[i + 1] = in.checked_size(64).value;
  const EGLSurface made = eglCreatePbufferSurface(dpy, cfg, list.data());
  if (made != EGL_NO_SURFACE) session.surfaces.push_back(made);
}

void make_current(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = display(in);
  const EGLSurface draw = surface(in), read = in.boolean() ? draw : surface(in);
  eglMakeCurrent(dpy, draw, read, context(in));
}

void query_context(FuzzInput& in, ClientMemory&) {
  EGLint value = 0;
  const EGLDisplay dpy = display(in);
  const EGLContext ctx = context(in);
  eglQueryContext(dpy, ctx,
                  EGLint(in.enumeration({EGL_CONFIG_ID, EGL_CONTEXT_CLIENT_TYPE, EGL_CONTEXT_CLIENT_VERSION,
                                         EGL_RENDER_BUFFER})),
                  &value);
}

void query_surface(FuzzInput& in, ClientMemory&) {
  EGLint value = 0;
  const EGLDisplay dpy = display(in);
  const EGLSurface surf = surface(in);
  eglQuerySurface(dpy, surf,
                  EGLint(in.enumeration({EGL_WIDTH, EGL_HEIGHT, EGL_CONFIG_ID, EGL_LARGEST_PBUFFER, EGL_TEXTURE_FORMAT,
                                         EGL_MIPMAP_LEVEL, EGL_RENDER_BUFFER, EGL_SWAP_BEHAVIOR,
                                         EGL_HORIZONTAL_RESOLUTION, EGL_MULTISAMPLE_RESOLVE})),
                  &value);
}

void surface_attrib(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = display(in);
  const EGLSurface surf = surface(in);
  const EGLint attribute =
      EGLint(in.enumeration({EGL_MIPMAP_LEVEL, EGL_SWAP_BEHAVIOR, EGL_MULTISAMPLE_RESOLVE}));
  eglSurfaceAttrib(dpy, surf, attribute,
                   in.boolean() ? EGLint(in.enumeration({EGL_BUFFER_PRESERVED, EGL_BUFFER_DESTROYED}))
                                : in.integer(-1, 8));
}

// A name of an EGL or GL entry point, a near miss, or bytes of the input (up to 24).
std::string proc_name(FuzzInput& in) {
  static const char* const kNames[] = {"eglCreateContext", "glDrawArrays", "glOrthofOES", "eglGetProcAddress",
                                       "OSMesaMakeCurrent", "glXGetProcAddress", "gl", "egl", "", "glDrawArrays "};
  const uint8_t pick = in.byte();
  if (pick % 2 == 0) return kNames[(pick / 2) % std::size(kNames)];
  std::string name = pick & 2 ? "gl" : "";
  for (int n = in.byte() % 24; n > 0 && !in.empty(); --n) name += char(in.byte() | 1);  // no terminator inside
  return name;
}

void create_sync(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = display(in);
  const EGLenum type = in.enumeration({EGL_SYNC_FENCE, EGL_SYNC_REUSABLE_KHR, EGL_SYNC_NATIVE_FENCE_ANDROID});
  const std::vector<EGLAttrib> list =
      attributes<EGLAttrib>(in, {GLenum(EGL_SYNC_STATUS), GLenum(EGL_SYNC_CONDITION)}, {GLenum(EGL_SIGNALED)});
  const EGLSync made = eglCreateSync(dpy, type, list.data());
  if (made != EGL_NO_SYNC) session.syncs.push_back(made);
}

void create_image(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = display(in);
  const EGLContext ctx = context(in);
  const EGLenum target = in.enumeration({EGL_GL_TEXTURE_2D, EGL_GL_RENDERBUFFER, EGL_GL_TEXTURE_CUBE_MAP_POSITIVE_X});
  const auto buffer = reinterpret_cast<EGLClientBuffer>(uintptr_t(in.name()));
  const std::vector<EGLAttrib> list = attributes<EGLAttrib>(
      in, {GLenum(EGL_GL_TEXTURE_LEVEL), GLenum(EGL_IMAGE_PRESERVED)}, {GLenum(EGL_TRUE), GLenum(EGL_FALSE)});
  const EGLImage made = eglCreateImage(dpy, ctx, target, buffer, list.data());
  if (made != EGL_NO_IMAGE) session.images.push_back(made);
}

// What an application does to draw with EGL, in one call (the separate calls rarely meet on
// the same handles): the surfaceless display, a config of the API, a context of a version the
// config allows, a pbuffer, all made current for the GL calls that follow.
void context_from_scratch(FuzzInput& in, ClientMemory&) {
  const EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, nullptr, nullptr);
  if (!eglInitialize(dpy, nullptr, nullptr)) return;
  session.displays.push_back(dpy);
  const uint8_t kind = in.byte() % 3;  // OpenGL ES 1.1, OpenGL ES 2.0, OpenGL 2.1
  const EGLint renderable[] = {EGL_OPENGL_ES_BIT, EGL_OPENGL_ES2_BIT, EGL_OPENGL_BIT};
  const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, renderable[kind],
                                      EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
  EGLConfig cfg = nullptr;
  EGLint found = 0;
  if (!eglChooseConfig(dpy, config_attributes, &cfg, 1, &found) || found < 1) return;
  session.configs.push_back(cfg);
  eglBindAPI(kind == 2 ? EGL_OPENGL_API : EGL_OPENGL_ES_API);
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, kind == 0 ? 1 : 2, EGL_NONE};
  const EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, context_attributes);
  if (ctx == EGL_NO_CONTEXT) return;
  session.contexts.push_back(ctx);
  const EGLint size = in.integer(0, 64) & 63;
  const EGLint surface_attributes[] = {EGL_WIDTH, size, EGL_HEIGHT, size, EGL_NONE};
  const EGLSurface surf = eglCreatePbufferSurface(dpy, cfg, surface_attributes);
  if (surf == EGL_NO_SURFACE) return;
  session.surfaces.push_back(surf);
  eglMakeCurrent(dpy, surf, surf, ctx);
}

const GlCall kCalls[] = {
    {"egl context from scratch", context_from_scratch},
    {"egl context from scratch", context_from_scratch},
    {"eglGetDisplay", [](FuzzInput&, ClientMemory&) { session.displays.push_back(eglGetDisplay(EGL_DEFAULT_DISPLAY)); }},
    {"eglGetPlatformDisplay",
     [](FuzzInput& in, ClientMemory&) {
       const EGLenum platform = in.enumeration({EGL_PLATFORM_SURFACELESS_MESA, EGL_PLATFORM_X11_KHR,
                                                EGL_PLATFORM_DEVICE_EXT, EGL_PLATFORM_GBM_KHR});
       const std::vector<EGLAttrib> list =
           attributes<EGLAttrib>(in, {GLenum(EGL_PLATFORM_X11_SCREEN_KHR), GLenum(EGL_DEVICE_EXT)}, {0, 1});
       const EGLDisplay made = eglGetPlatformDisplay(platform, nullptr, in.boolean() ? list.data() : nullptr);
       if (made != EGL_NO_DISPLAY) session.displays.push_back(made);
     }},
    {"eglGetPlatformDisplayEXT",
     [](FuzzInput& in, ClientMemory&) {
       const EGLenum platform = in.enumeration({EGL_PLATFORM_SURFACELESS_MESA, EGL_PLATFORM_X11_EXT});
       const std::vector<EGLint> list = attributes<EGLint>(in, {GLenum(EGL_PLATFORM_X11_SCREEN_EXT)}, {0, 1});
       const EGLDisplay made = eglGetPlatformDisplayEXT(platform, nullptr, list.data());
       if (made != EGL_NO_DISPLAY) session.displays.push_back(made);
     }},
    {"eglInitialize", initialize},
    {"eglInitialize", initialize},
    {"eglTerminate", [](FuzzInput& in, ClientMemory&) { eglTerminate(display(in)); }},
    {"eglChooseConfig", choose_config},
    {"eglChooseConfig", choose_config},
    {"eglGetConfigs", get_configs},
    {"eglGetConfigAttrib",
     [](FuzzInput& in, ClientMemory&) {
       EGLint value = 0;
       const EGLDisplay dpy = display(in);
       const EGLConfig cfg = config(in);
       eglGetConfigAttrib(dpy, cfg, EGLint(in.enumeration(kConfigKeys)), &value);
     }},
    {"eglBindAPI", [](FuzzInput& in, ClientMemory&) { eglBindAPI(in.enumeration({EGL_OPENGL_ES_API, EGL_OPENGL_API})); }},
    {"eglQueryAPI", [](FuzzInput&, ClientMemory&) { eglQueryAPI(); }},
    {"eglCreateContext", create_context},
    {"eglCreateContext", create_context},
    {"eglCreatePbufferSurface", create_pbuffer},
    {"eglCreatePbufferSurface", create_pbuffer},
    {"eglMakeCurrent", make_current},
    {"eglMakeCurrent", make_current},
    {"eglMakeCurrent", make_current},
    {"eglQueryContext", query_context},
    {"eglQuerySurface", query_surface},
    {"eglSurfaceAttrib", surface_attrib},
    {"eglSwapBuffers", [](FuzzInput& in, ClientMemory&) { eglSwapBuffers(display(in), surface(in)); }},
    {"eglSwapInterval", [](FuzzInput& in, ClientMemory&) { eglSwapInterval(display(in), in.integer(-1, 4)); }},
    {"eglBindTexImage",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLSurface surf = surface(in);
       eglBindTexImage(dpy, surf, EGLint(in.enumeration({EGL_BACK_BUFFER})));
     }},
    {"eglReleaseTexImage",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLSurface surf = surface(in);
       eglReleaseTexImage(dpy, surf, EGLint(in.enumeration({EGL_BACK_BUFFER})));
     }},
    {"eglDestroyContext", [](FuzzInput& in, ClientMemory&) { eglDestroyContext(display(in), context(in)); }},
    {"eglDestroySurface", [](FuzzInput& in, ClientMemory&) { eglDestroySurface(display(in), surface(in)); }},
    {"eglQueryString",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       eglQueryString(dpy, EGLint(in.enumeration({EGL_VENDOR, EGL_VERSION, EGL_EXTENSIONS, EGL_CLIENT_APIS})));
     }},
    {"eglGetProcAddress", [](FuzzInput& in, ClientMemory&) { eglGetProcAddress(proc_name(in).c_str()); }},
    {"eglGetCurrentContext", [](FuzzInput&, ClientMemory&) { eglGetCurrentContext(); }},
    {"eglGetCurrentDisplay", [](FuzzInput&, ClientMemory&) { eglGetCurrentDisplay(); }},
    {"eglGetCurrentSurface",
     [](FuzzInput& in, ClientMemory&) { eglGetCurrentSurface(EGLint(in.enumeration({EGL_DRAW, EGL_READ}))); }},
    {"eglGetError", [](FuzzInput&, ClientMemory&) { eglGetError(); }},
    {"eglReleaseThread", [](FuzzInput&, ClientMemory&) { eglReleaseThread(); }},
    {"eglWaitClient", [](FuzzInput&, ClientMemory&) { eglWaitClient(); }},
    {"eglWaitGL", [](FuzzInput&, ClientMemory&) { eglWaitGL(); }},
    {"eglWaitNative", [](FuzzInput& in, ClientMemory&) { eglWaitNative(EGLint(in.enumeration({EGL_CORE_NATIVE_ENGINE}))); }},
    {"eglCreateSync", create_sync},
    {"eglClientWaitSync",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLSync s = sync(in);
       eglClientWaitSync(dpy, s, in.boolean() ? EGL_SYNC_FLUSH_COMMANDS_BIT : 0, EGLTime(in.integer(0, 1000)));
     }},
    {"eglWaitSync", [](FuzzInput& in, ClientMemory&) { eglWaitSync(display(in), sync(in), in.integer(0, 1)); }},
    {"eglGetSyncAttrib",
     [](FuzzInput& in, ClientMemory&) {
       EGLAttrib value = 0;
       const EGLDisplay dpy = display(in);
       const EGLSync s = sync(in);
       eglGetSyncAttrib(dpy, s, EGLint(in.enumeration({EGL_SYNC_TYPE, EGL_SYNC_STATUS, EGL_SYNC_CONDITION})), &value);
     }},
    {"eglDestroySync", [](FuzzInput& in, ClientMemory&) { eglDestroySync(display(in), sync(in)); }},
    {"eglCreateImage", create_image},
    {"eglDestroyImage",
     [](FuzzInput& in, ClientMemory&) {
       eglDestroyImage(display(in), handle<EGLImage>(in, session.images, EGL_NO_IMAGE));
     }},
    {"eglCreatePbufferFromClientBuffer",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLenum type = in.enumeration({EGL_OPENVG_IMAGE});
       const EGLConfig cfg = config(in);
       const std::vector<EGLint> list = attributes<EGLint>(in, kSurfaceKeys, kSurfaceValues);
       eglCreatePbufferFromClientBuffer(dpy, type, reinterpret_cast<EGLClientBuffer>(foreign_object), cfg, list.data());
     }},
    // The surfaceless platform has no windows or pixmaps: every native handle must be refused
    // before it is used (0 and 1 are no X drawable either).
    {"eglCreateWindowSurface",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLConfig cfg = config(in);
       eglCreateWindowSurface(dpy, cfg, EGLNativeWindowType(in.byte() % 2), nullptr);
     }},
    {"eglCreatePixmapSurface",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLConfig cfg = config(in);
       eglCreatePixmapSurface(dpy, cfg, EGLNativePixmapType(in.byte() % 2), nullptr);
     }},
    {"eglCreatePlatformWindowSurface",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLConfig cfg = config(in);
       eglCreatePlatformWindowSurface(dpy, cfg, nullptr, nullptr);
     }},
    {"eglCreatePlatformWindowSurfaceEXT",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLConfig cfg = config(in);
       eglCreatePlatformWindowSurfaceEXT(dpy, cfg, nullptr, nullptr);
     }},
    {"eglCreatePlatformPixmapSurface",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLConfig cfg = config(in);
       eglCreatePlatformPixmapSurface(dpy, cfg, nullptr, nullptr);
     }},
    {"eglCreatePlatformPixmapSurfaceEXT",
     [](FuzzInput& in, ClientMemory&) {
       const EGLDisplay dpy = display(in);
       const EGLConfig cfg = config(in);
       eglCreatePlatformPixmapSurfaceEXT(dpy, cfg, nullptr, nullptr);
     }},
    {"eglCopyBuffers",
     [](FuzzInput& in, ClientMemory&) { eglCopyBuffers(display(in), surface(in), EGLNativePixmapType(0)); }},
};

}  // namespace

std::span<const GlCall> egl_calls() { return kCalls; }

void begin_egl_session(void (*restore_context)()) {
  session = EglSession{};
  session.restore_context = restore_context;
}

void run_egl_call(const GlCall& call, FuzzInput& in, ClientMemory& memory) {
  const bool egl_context_was_current = eglGetCurrentContext() != EGL_NO_CONTEXT;
  call.run(in, memory);
  if (egl_context_was_current && eglGetCurrentContext() == EGL_NO_CONTEXT) session.restore_context();
}

void end_egl_session() {
  for (EGLDisplay dpy : session.displays) {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
  }
  eglReleaseThread();
  session = EglSession{};
}

}  // namespace pineda::fuzz
