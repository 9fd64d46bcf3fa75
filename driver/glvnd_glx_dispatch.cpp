// The GLX extension functions through libglvnd: each stub finds the vendor that owns the
// call's display, config, drawable or current context, and calls that vendor's function from
// libGLX's dynamic table (the slot libGLX gave through setDispatchIndex).
#include "driver/glvnd_glx_dispatch.h"

#include <GL/glxext.h>

#include <atomic>
#include <cstring>

namespace pineda::glx {
namespace {

enum Stub {
  kCreateContextAttribsARB,
  kSwapIntervalEXT,
  kSwapIntervalMESA,
  kGetSwapIntervalMESA,
  kSwapIntervalSGI,
  kStubCount
};

// What libGLX hands the vendor when it loads it. The ABI makes this per process, not per
// context: one exports table, and one slot per function that every vendor shares.
struct GlvndLink {
  std::atomic<const __GLXapiExports*> exports{nullptr};
  std::atomic<int> index[kStubCount];
  GlvndLink() {
    for (std::atomic<int>& i : index) i = -1;
  }
};

GlvndLink& link() {
  static GlvndLink instance;
  return instance;
}

const __GLXapiExports& exports() { return *link().exports.load(); }

template <class Function>
Function fetch(__GLXvendorInfo* vendor, Stub stub) {
  const int index = link().index[stub];
  if (!vendor || index < 0) return nullptr;
  return reinterpret_cast<Function>(exports().fetchDispatchEntry(vendor, index));
}

// Debian 12's libGLX (libglvnd 1.6.0) dispatches glXCreateContextAttribsARB itself; a libGLX
// that does not know the function asks the vendor for this stub (Mesa's vendor has one too).
GLXContext create_context_attribs(Display* dpy, GLXFBConfig config, GLXContext share,
                                  Bool direct, const int* attribs) {
  __GLXvendorInfo* vendor = config ? exports().vendorFromFBConfig(dpy, config) : nullptr;
  // A config no vendor made: the screen's vendor reports the error.
  if (!vendor) vendor = exports().getDynDispatch(dpy, DefaultScreen(dpy));
  auto create = fetch<PFNGLXCREATECONTEXTATTRIBSARBPROC>(vendor, kCreateContextAttribsARB);
  if (!create) return nullptr;
  GLXContext context = create(dpy, config, share, direct, attribs);
  // libGLX fails to record a context only when out of memory; without the record no GLX call
  // could reach the context, so the program gets none.
  if (context && exports().addVendorContextMapping(dpy, context, vendor) != 0) return nullptr;
  return context;
}

void swap_interval_ext(Display* dpy, GLXDrawable drawable, int interval) {
  auto swap_interval = fetch<PFNGLXSWAPINTERVALEXTPROC>(
      exports().vendorFromDrawable(dpy, drawable), kSwapIntervalEXT);
  if (swap_interval) swap_interval(dpy, drawable, interval);
}

int swap_interval_mesa(unsigned int interval) {
  auto swap_interval = fetch<PFNGLXSWAPINTERVALMESAPROC>(exports().getCurrentDynDispatch(),
                                                         kSwapIntervalMESA);
  return swap_interval ? swap_interval(interval) : GLX_BAD_CONTEXT;
}

int get_swap_interval_mesa() {
  auto get_swap_interval = fetch<PFNGLXGETSWAPINTERVALMESAPROC>(
      exports().getCurrentDynDispatch(), kGetSwapIntervalMESA);
  return get_swap_interval ? get_swap_interval() : 0;
}

int swap_interval_sgi(int interval) {
  auto swap_interval = fetch<PFNGLXSWAPINTERVALSGIPROC>(exports().getCurrentDynDispatch(),
                                                        kSwapIntervalSGI);
  return swap_interval ? swap_interval(interval) : GLX_BAD_CONTEXT;
}

struct StubEntry {
  const char* name;
  void* stub;
};

// In the order of enum Stub.
const StubEntry kStubs[kStubCount] = {
    {"glXCreateContextAttribsARB", reinterpret_cast<void*>(&create_context_attribs)},
    {"glXSwapIntervalEXT", reinterpret_cast<void*>(&swap_interval_ext)},
    {"glXSwapIntervalMESA", reinterpret_cast<void*>(&swap_interval_mesa)},
    {"glXGetSwapIntervalMESA", reinterpret_cast<void*>(&get_swap_interval_mesa)},
    {"glXSwapIntervalSGI", reinterpret_cast<void*>(&swap_interval_sgi)},
};

int find_stub(const char* name) {
  for (int i = 0; i < kStubCount; ++i)
    if (name && std::strcmp(kStubs[i].name, name) == 0) return i;
  return -1;
}

}  // namespace

void glvnd_set_exports(const __GLXapiExports* exports) { link().exports = exports; }

void* glvnd_dispatch_stub(const char* name) {
  const int stub = find_stub(name);
  return stub < 0 ? nullptr : kStubs[stub].stub;
}

void glvnd_set_dispatch_index(const char* name, int index) {
  const int stub = find_stub(name);
  if (stub >= 0) link().index[stub] = index;
}

}  // namespace pineda::glx
