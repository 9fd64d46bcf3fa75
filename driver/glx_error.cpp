#include "driver/glx_error.h"

#include "driver/glx_registry.h"

// Last: Xlib's internal header defines min and max macros.
#include <X11/Xlibint.h>
#include <X11/Xproto.h>

namespace pineda::glx {
namespace {

struct Codes {
  bool server_glx = false;
  int major_opcode = 0, error_base = 0;
};

Codes codes_of(Display* dpy) {
  auto lock = Registry::instance().lock();
  DisplayState* d = Registry::instance().get(dpy);
  if (!d) return {};
  return {d->server_glx, d->major_opcode, d->error_base};
}

void send(Display* dpy, unsigned char code, int major, int minor, XID resource) {
  if (!dpy) return;
  xError error{};
  error.type = X_Error;
  error.errorCode = code;
  error.resourceID = static_cast<CARD32>(resource);
  error.minorCode = static_cast<CARD16>(minor);
  error.majorCode = static_cast<CARD8>(major);
  LockDisplay(dpy);
  error.sequenceNumber = static_cast<CARD16>(dpy->request);
  _XError(dpy, &error);  // calls the handler with the display unlocked
  UnlockDisplay(dpy);
}

}  // namespace

void send_x_error(Display* dpy, unsigned char code, GlxRequest request, XID resource) {
  Codes c = codes_of(dpy);
  send(dpy, code, c.major_opcode, static_cast<int>(request), resource);
}

void send_glx_error(Display* dpy, GlxError code, GlxRequest request, XID resource) {
  Codes c = codes_of(dpy);
  // Without the server's GLX extension there is no GLX error base: the nearest core error.
  unsigned char value = c.server_glx ? static_cast<unsigned char>(c.error_base + static_cast<int>(code))
                                     : static_cast<unsigned char>(code == GlxError::GlxContext ? BadValue : BadDrawable);
  send(dpy, value, c.major_opcode, static_cast<int>(request), resource);
}

}  // namespace pineda::glx
