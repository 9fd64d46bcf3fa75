#include "driver/glx_current.h"

#include <optional>
#include <utility>

#include "driver/glx_drawable.h"
#include "driver/glx_error.h"
#include "driver/glx_registry.h"
#include "driver/thread_slot.h"
#include "glapi/current.h"

namespace pineda::glx {
namespace {


bool compatible(const Config& a, const Config& b) {
  return a.red == b.red && a.green == b.green && a.blue == b.blue && a.alpha == b.alpha &&
         a.depth == b.depth && a.stencil == b.stencil && a.screen == b.screen;
}

struct Failure {
  unsigned char code;
  bool glx;
  XID resource = 0;
};

// The GLX drawable named `id`; a plain X window becomes one on first use. A window's
// existence is checked: destroying an X window destroys its GLX drawable. Caller holds the
// registry lock.
std::shared_ptr<DrawableObject> resolve(DisplayState& d, XID id, const ContextObject& context,
                                        std::optional<Failure>* failure) {
  auto bad_drawable = [&] {
    *failure = Failure{static_cast<unsigned char>(GlxError::GlxDrawable), true, id};
    return nullptr;
  };
  std::shared_ptr<DrawableObject> found = Registry::instance().find_drawable(d.dpy, id);
  if (found && found->kind != DrawableKind::Window) return found;
  if (!found && d.retired.contains(id)) return bad_drawable();
  XWindowAttributes attributes;
  if (!x_window_attributes(d.dpy, found ? found->x_drawable : id, &attributes)) {
    if (found && d.drawables.erase(id) && !found->implicit) d.retired.insert(id);
    return bad_drawable();
  }
  if (attributes.depth != context.config->visual_depth ||
      XScreenNumberOfScreen(attributes.screen) != context.config->screen) {
    *failure = Failure{BadMatch, false, id};
    return nullptr;
  }
  if (found) {
    // The id of a destroyed window may have been given to a new one.
    if (found->implicit) found->visual = attributes.visual;
    return found;
  }
  auto object = std::make_shared<DrawableObject>();
  object->dpy = d.dpy;
  object->id = object->x_drawable = id;
  object->kind = DrawableKind::Window;
  object->implicit = true;
  object->config = context.config;
  object->visual = attributes.visual;
  object->x_depth = attributes.depth;
  object->gc = XCreateGC(d.dpy, id, 0, nullptr);
  d.drawables.emplace(id, object);
  return object;
}

// Follows the X window's size; other drawables keep theirs. A drawable that another thread
// renders to keeps its buffers until that thread lets go.
void track_window_size(DrawableObject& d, int other_bindings) {
  if (d.kind != DrawableKind::Window || !d.dpy) return;
  int width = 0, height = 0;
  if (!x_drawable_size(d.dpy, d.x_drawable, &width, &height)) return;
  if (width == d.width && height == d.height) return;
  if (other_bindings > 0 && d.allocated) return;
  allocate_buffers(d, width, height);
}

int bindings_of(const ThreadState& t, const DrawableObject* d) {
  return (t.draw.get() == d) + (t.read.get() == d && t.read != t.draw);
}

// Caller holds the registry lock.
void unbind_drawables(const std::shared_ptr<DrawableObject>& draw,
                      const std::shared_ptr<DrawableObject>& read) {
  if (draw) --draw->bindings;
  if (read && read != draw) --read->bindings;
}

void bind_drawables(const std::shared_ptr<DrawableObject>& draw,
                    const std::shared_ptr<DrawableObject>& read) {
  if (draw) ++draw->bindings;
  if (read && read != draw) ++read->bindings;
}

// Ends the thread's binding. `flush`: GL's implicit glFlush, which shows front drawing.
void release(ThreadState& t, bool flush) {
  if (!t.context) return;
  if (flush) flush_front(t, true);
  std::shared_ptr<ContextObject> context = std::move(t.context);
  std::shared_ptr<DrawableObject> draw = std::move(t.draw), read = std::move(t.read);
  t.dpy = nullptr;
  t.context_handle = nullptr;
  t.draw_id = t.read_id = None;
  context->gl->release_current();
  glapi::set_flush_listener(nullptr, nullptr);
  set_current_context(nullptr);
  auto lock = Registry::instance().lock();
  context->bound_thread = nullptr;
  unbind_drawables(draw, read);
  // The references drop here: a destroyed context or drawable is freed now.
}

}  // namespace

ThreadState& thread_state() { return driver::thread_slot<ThreadState>(); }

ThreadState::~ThreadState() { release(*this, false); }

void ThreadState::flushed() { flush_front(*this, false); }

void flush_front(ThreadState& t, bool checked) {
  if (!t.context) return;
  t.context->gl->finish();
  if (t.draw && t.draw->drawable.front_drawn) present(*t.draw, checked);
}

Bool make_current(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx,
                  GlxRequest minor_opcode) {
  ThreadState& t = thread_state();
  if (!ctx) {
    if (draw != None || read != None) {
      send_x_error(dpy, BadMatch, minor_opcode);
      return False;
    }
    release(t, true);
    return True;
  }

  std::optional<Failure> failure;
  std::shared_ptr<ContextObject> context;
  std::shared_ptr<DrawableObject> draw_object, read_object;
  {
    Registry& registry = Registry::instance();
    auto lock = registry.lock();
    DisplayState* d = registry.get(dpy);
    context = d ? d->find_context(ctx) : nullptr;
    // A destroyed context lives on while it is current, and can be made current again.
    if (!context && ctx == t.context_handle && dpy == t.dpy) context = t.context;
    if (!context) {
      failure = Failure{static_cast<unsigned char>(GlxError::GlxContext), true};
    } else if (draw == None || read == None) {
      // A GL 1.x context cannot be current without a drawable.
      failure = Failure{BadMatch, false};
    } else if (context->bound_thread && context->bound_thread != &t) {
      failure = Failure{BadAccess, false};
    } else {
      draw_object = resolve(*d, draw, *context, &failure);
      if (draw_object) read_object = read == draw ? draw_object : resolve(*d, read, *context, &failure);
      for (const auto& object : {draw_object, read_object})
        if (object && !failure && !compatible(*object->config, *context->config))
          failure = Failure{BadMatch, false};
    }
    if (!failure) {
      context->bound_thread = &t;
      bind_drawables(draw_object, read_object);
    }
  }
  if (failure) {
    if (failure->glx)
      send_glx_error(dpy, static_cast<GlxError>(failure->code), minor_opcode, failure->resource);
    else
      send_x_error(dpy, failure->code, minor_opcode, failure->resource);
    return False;
  }

  // The previous binding gets its implicit flush and lets go.
  std::shared_ptr<ContextObject> old_context = t.context;
  std::shared_ptr<DrawableObject> old_draw = t.draw, old_read = t.read;
  if (old_context) {
    flush_front(t, true);
    if (old_context != context) old_context->gl->release_current();
  }
  try {
    for (const auto& object : {draw_object, read_object}) {
      const int others = object->bindings - 1 - bindings_of(t, object.get());
      track_window_size(*object, others);
      if (!object->allocated) allocate_buffers(*object, std::max(object->width, 1), std::max(object->height, 1));
    }
  } catch (const std::bad_alloc&) {
    // Keep the thread's old binding bookkeeping consistent: release everything.
    {
      auto lock = Registry::instance().lock();
      if (old_context != context) context->bound_thread = nullptr;
      unbind_drawables(draw_object, read_object);
    }
    release(t, false);
    send_x_error(dpy, BadAlloc, minor_opcode);
    return False;
  }

  t.dpy = dpy;
  t.context_handle = ctx;
  t.draw_id = draw;
  t.read_id = read;
  t.context = context;
  t.draw = draw_object;
  t.read = read_object;
  set_current_context(context->gl.get());
  context->gl->make_current(&draw_object->drawable, &read_object->drawable);
  glapi::set_flush_listener(context->gl.get(), &t);

  auto lock = Registry::instance().lock();
  if (old_context && old_context != context) old_context->bound_thread = nullptr;
  unbind_drawables(old_draw, old_read);
  return True;
}

}  // namespace pineda::glx
