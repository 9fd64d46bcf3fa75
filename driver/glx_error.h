// GLX errors are X errors: they reach the application's XSetErrorHandler handler (or Xlib's
// default one, which exits) as if the server had sent them, as Mesa's libGL does.
#pragma once
#include "driver/glx_objects.h"

namespace pineda::glx {

// GLX's own error codes (offsets from the extension's error base).
enum class GlxError : unsigned char {
  GlxContext = 0,
  GlxContextState = 1,
  GlxDrawable = 2,
  GlxPixmap = 3,
  GlxFBConfig = 9,
  GlxPbuffer = 10,
  GlxWindow = 12,
  GlxProfileARB = 13,
};

// The GLX request (minor opcode) an error is reported for, as in GL/glxproto.h, whose
// protocol structures need Xlib's internal headers.
enum class GlxRequest : int {
  CreateContext = 3,
  DestroyContext = 4,
  MakeCurrent = 5,
  IsDirect = 6,
  WaitGL = 8,
  WaitX = 9,
  CopyContext = 10,
  SwapBuffers = 11,
  UseXFont = 12,
  CreateGLXPixmap = 13,
  DestroyGLXPixmap = 15,
  VendorPrivate = 16,
  GetFBConfigs = 21,
  CreatePixmap = 22,
  DestroyPixmap = 23,
  CreateNewContext = 24,
  QueryContext = 25,
  MakeContextCurrent = 26,
  CreatePbuffer = 27,
  DestroyPbuffer = 28,
  GetDrawableAttributes = 29,
  ChangeDrawableAttributes = 30,
  CreateWindow = 31,
  DestroyWindow = 32,
  CreateContextAttribsARB = 34,
};

// Reports a core X error (BadMatch, BadAccess, BadValue, BadAlloc...) for GLX request `request`.
void send_x_error(Display* dpy, unsigned char code, GlxRequest request, XID resource = 0);
void send_glx_error(Display* dpy, GlxError code, GlxRequest request, XID resource = 0);

}  // namespace pineda::glx
