#include "driver/glx_shm.h"

#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstdlib>
#include <cstring>
#include <mutex>

namespace pineda::glx {
namespace {

// Xlib's error handler is process-wide: XShmAttach fails (asynchronously) on a display
// that cannot reach the segment, and that must not reach the application's handler.
std::mutex& attach_mutex() {
  static std::mutex* m = new std::mutex;
  return *m;
}
bool attach_failed = false;

int on_attach_error(Display*, XErrorEvent*) {
  attach_failed = true;
  return 0;
}

bool attach(Display* dpy, XShmSegmentInfo* info) {
  std::lock_guard lock(attach_mutex());
  XSync(dpy, False);
  attach_failed = false;
  auto previous = XSetErrorHandler(on_attach_error);
  Bool ok = XShmAttach(dpy, info);
  XSync(dpy, False);
  XSetErrorHandler(previous);
  return ok && !attach_failed;
}

}  // namespace

struct SharedImage::Segment {
  XShmSegmentInfo info{};
  bool attached = false;
};

std::unique_ptr<SharedImage> SharedImage::create(Display* dpy, Visual* visual, int depth,
                                                 int width, int height) {
  // PINEDA_GLX_NO_SHM=1 forces the XPutImage path (tests, remote-like behaviour).
  static const bool disabled = [] {
    const char* v = std::getenv("PINEDA_GLX_NO_SHM");
    return v && *v && std::strcmp(v, "0") != 0;
  }();
  if (disabled || !dpy || !visual || width <= 0 || height <= 0 || !XShmQueryExtension(dpy))
    return nullptr;
  std::unique_ptr<SharedImage> result(new SharedImage);
  result->dpy_ = dpy;
  result->segment_ = std::make_unique<Segment>();
  XShmSegmentInfo& info = result->segment_->info;
  info.shmid = -1;
  info.shmaddr = reinterpret_cast<char*>(-1);
  result->image_ = XShmCreateImage(dpy, visual, depth, ZPixmap, nullptr, &info, width, height);
  XImage* image = result->image_;
  if (!image) return nullptr;
  if (image->bits_per_pixel != 32 || image->bytes_per_line != width * 4) return nullptr;
  info.shmid = shmget(IPC_PRIVATE, static_cast<size_t>(image->bytes_per_line) * height, IPC_CREAT | 0600);
  if (info.shmid < 0) return nullptr;
  info.shmaddr = static_cast<char*>(shmat(info.shmid, nullptr, 0));
  if (info.shmaddr == reinterpret_cast<char*>(-1)) return nullptr;
  image->data = info.shmaddr;
  info.readOnly = True;
  result->segment_->attached = attach(dpy, &info);
  // The segment goes away by itself once both sides have detached.
  shmctl(info.shmid, IPC_RMID, nullptr);
  if (!result->segment_->attached) return nullptr;
  return result;
}

SharedImage::~SharedImage() {
  if (!segment_) return;
  XShmSegmentInfo& info = segment_->info;
  if (dpy_ && segment_->attached) {
    XShmDetach(dpy_, &info);
    XSync(dpy_, False);
  }
  if (image_) {
    // The segment's memory and our segment record, not malloc's.
    image_->data = nullptr;
    image_->obdata = nullptr;
    XDestroyImage(image_);
  }
  if (info.shmaddr != reinterpret_cast<char*>(-1)) shmdt(info.shmaddr);
  else if (info.shmid >= 0) shmctl(info.shmid, IPC_RMID, nullptr);
}

uint8_t* SharedImage::pixels() const { return reinterpret_cast<uint8_t*>(image_->data); }

void SharedImage::put(::Drawable target, GC gc) {
  if (!dpy_) return;
  XShmPutImage(dpy_, target, gc, image_, 0, 0, 0, 0, image_->width, image_->height, False);
  XSync(dpy_, False);
}

}  // namespace pineda::glx
