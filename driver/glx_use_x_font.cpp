// glXUseXFont: display lists of glBitmap calls, one per glyph of an X font, as Mesa's
// xfont.c builds them: each glyph is drawn by the X server into a 1-bit pixmap, read back
// with XGetImage and turned into GL's bitmap layout (rows bottom-up, most significant bit
// first); the bitmap's origin is the glyph's origin and the raster position advances by the
// glyph's width.
#include "driver/glx_current.h"

#include <X11/Xutil.h>

#include <algorithm>
#include <vector>

#include "driver/glx_error.h"

namespace pineda::glx {
namespace {

// The metrics of character `c`, or nullptr when the font has none for it.
const XCharStruct* char_metrics(const XFontStruct& fs, unsigned c) {
  const unsigned byte1 = c >> 8, byte2 = c & 0xff;
  if (byte1 < fs.min_byte1 || byte1 > fs.max_byte1) return nullptr;
  if (byte2 < fs.min_char_or_byte2 || byte2 > fs.max_char_or_byte2) return nullptr;
  if (!fs.per_char) return &fs.min_bounds;  // every glyph has the same metrics
  const unsigned columns = fs.max_char_or_byte2 - fs.min_char_or_byte2 + 1;
  const XCharStruct* ch =
      &fs.per_char[(byte1 - fs.min_byte1) * columns + (byte2 - fs.min_char_or_byte2)];
  // A glyph the font does not have has all-zero metrics.
  if (ch->width == 0 && ch->lbearing == 0 && ch->rbearing == 0 && ch->ascent == 0 && ch->descent == 0)
    return nullptr;
  return ch;
}

// Draws `c` with its origin at (-lbearing, ascent) of the cleared pixmap and returns the
// glyph's pixels in GL's unpack layout with alignment 1.
std::vector<GLubyte> glyph_bitmap(Display* dpy, Pixmap pixmap, GC gc, unsigned c, const XCharStruct& ch,
                                  int width, int height) {
  XSetForeground(dpy, gc, 0);
  XFillRectangle(dpy, pixmap, gc, 0, 0, width, height);
  XSetForeground(dpy, gc, 1);
  XChar2b glyph{static_cast<unsigned char>(c >> 8), static_cast<unsigned char>(c & 0xff)};
  XDrawString16(dpy, pixmap, gc, -ch.lbearing, ch.ascent, &glyph, 1);
  const int row_bytes = (width + 7) / 8;
  std::vector<GLubyte> bits(static_cast<size_t>(row_bytes) * height, 0);
  XImage* image = XGetImage(dpy, pixmap, 0, 0, width, height, 1, XYPixmap);
  if (!image) return bits;
  for (int y = 0; y < height; ++y) {
    GLubyte* row = &bits[static_cast<size_t>(height - 1 - y) * row_bytes];  // GL rows bottom-up
    for (int x = 0; x < width; ++x)
      if (XGetPixel(image, x, y)) row[x / 8] |= static_cast<GLubyte>(0x80 >> (x % 8));
  }
  XDestroyImage(image);
  return bits;
}

}  // namespace
}  // namespace pineda::glx

using namespace pineda::glx;

PINEDA_GLX_EXPORT void glXUseXFont(Font font, int first, int count, int list_base) {
  ThreadState& t = thread_state();
  if (!t.context || !t.dpy) return;
  Display* dpy = t.dpy;
  GLint compiling = 0;
  glGetIntegerv(GL_LIST_INDEX, &compiling);
  if (compiling) {
    send_glx_error(dpy, GlxError::GlxContextState, GlxRequest::UseXFont);
    return;
  }
  XFontStruct* fs = XQueryFont(dpy, font);
  if (!fs) {
    send_x_error(dpy, BadFont, GlxRequest::UseXFont, font);
    return;
  }
  if (count <= 0) {
    XFreeFontInfo(nullptr, fs, 1);
    return;
  }
  // One pixmap that holds the largest glyph.
  const int max_width = std::max(1, fs->max_bounds.rbearing - fs->min_bounds.lbearing);
  const int max_height = std::max(1, fs->max_bounds.ascent + fs->max_bounds.descent);
  Pixmap pixmap = XCreatePixmap(dpy, RootWindow(dpy, DefaultScreen(dpy)), max_width, max_height, 1);
  XGCValues values{};
  values.font = font;
  values.background = 0;
  GC gc = XCreateGC(dpy, pixmap, GCFont | GCBackground, &values);

  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < count; ++i) {
    // A character the font lacks is drawn as its default character, if it has one.
    unsigned c = static_cast<unsigned>(first + i);
    const XCharStruct* ch = char_metrics(*fs, c);
    if (!ch && fs->default_char != 0) ch = char_metrics(*fs, c = fs->default_char);
    glNewList(static_cast<GLuint>(list_base + i), GL_COMPILE);
    if (ch) {
      const int width = std::clamp(ch->rbearing - ch->lbearing, 0, max_width);
      const int height = std::clamp(ch->ascent + ch->descent, 0, max_height);
      std::vector<GLubyte> bits;
      if (width > 0 && height > 0) bits = glyph_bitmap(dpy, pixmap, gc, c, *ch, width, height);
      glBitmap(width, height, static_cast<GLfloat>(-ch->lbearing), static_cast<GLfloat>(ch->descent),
               static_cast<GLfloat>(ch->width), 0.0f, bits.empty() ? nullptr : bits.data());
    }
    glEndList();
  }
  glPopClientAttrib();
  XFreeGC(dpy, gc);
  XFreePixmap(dpy, pixmap);
  XFreeFontInfo(nullptr, fs, 1);
}
