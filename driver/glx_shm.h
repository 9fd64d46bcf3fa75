// A colour buffer in MIT-SHM memory that the X server reads directly: presenting it costs one
// request instead of sending the pixels through the socket. Only for local displays that
// offer the extension; otherwise create() returns nullptr and the drawable uses XPutImage.
#pragma once
#include <X11/Xlib.h>

#include <cstdint>
#include <memory>

namespace pineda::glx {

class SharedImage {
 public:
  // An image of width x height 32-bit pixels, rows top-down and tightly packed, or nullptr.
  static std::unique_ptr<SharedImage> create(Display* dpy, Visual* visual, int depth, int width,
                                             int height);
  ~SharedImage();
  SharedImage(const SharedImage&) = delete;
  SharedImage& operator=(const SharedImage&) = delete;

  uint8_t* pixels() const;
  // Copies the image to `target` and waits until the server has read it, so that rendering
  // may write the memory again.
  void put(::Drawable target, GC gc);
  // The connection is closing: the server frees its side; only the memory is left to free.
  void forget_display() { dpy_ = nullptr; }

 private:
  SharedImage() = default;

  struct Segment;
  Display* dpy_ = nullptr;
  XImage* image_ = nullptr;
  std::unique_ptr<Segment> segment_;
};

}  // namespace pineda::glx
