// The objects that contexts created with a share list (glXCreateContext's shareList,
// eglCreateContext's share_context, OSMesa's sharelist) hold in common: textures (the
// default ones too, as Mesa), buffer objects, display lists, shader and program objects,
// renderbuffers, sampler objects. Queries and framebuffer objects stay per context.
#pragma once
#include <atomic>
#include <memory>
#include <mutex>

#include "state/buffers/buffer_object.h"
#include "state/lists/display_list.h"
#include "state/framebuffers/renderbuffer.h"
#include "state/programs/program_objects.h"
#include "state/textures/texture_object.h"
#include "state/textures/sampler_object.h"

namespace pineda {

struct ShareGroup {
  TextureNamespace textures;
  ObjectNames<BufferObject> buffers;
  DisplayLists lists;
  ShaderProgramNames programs;
  RenderbufferNames renderbuffers;
  SamplerNames samplers;

  // Contexts of a group may run on different threads: while the group has more than one
  // member, every GL call holds this lock (glapi/), so calls on shared objects never race.
  std::recursive_mutex mutex;
  std::atomic<int> members{0};
  // Calls of the group's only member running without the lock (nested ones too); only the
  // thread that member is current on changes it.
  std::atomic<int> unlocked_calls{0};
  // A member joined a group of one: the first call under the lock waits for that member's
  // call in flight without it, if any (finish_join).
  std::atomic<bool> join_pending{false};
  // The calls made under the lock that may change state (StateKey); written with the lock held.
  std::atomic<uint64_t> changes{0};

  void join() {
    if (members.fetch_add(1, std::memory_order_seq_cst) >= 1) join_pending.store(true, std::memory_order_relaxed);
  }
  void leave() { members.fetch_sub(1, std::memory_order_acq_rel); }
  // Called with the lock held.
  void finish_join();
};

// Whether join() can make every thread pass a full fence (membarrier, registered when the
// library loads): then a call that found its group unshared needs only a compiler fence
// between counting itself and its second look at `members`; otherwise a full fence.
bool register_expedited_membarrier();
inline const bool kExpeditedMembarrier = register_expedited_membarrier();

// What a GL call holds: the group's lock while the context shares with another, otherwise
// its place in ShareGroup::unlocked_calls (the asymmetric Dekker handshake with join()).
class SharedCallGuard {
 public:
  explicit SharedCallGuard(ShareGroup& group) {
    if (group.members.load(std::memory_order_acquire) <= 1) {
      const int calls = group.unlocked_calls.load(std::memory_order_relaxed);
      group.unlocked_calls.store(calls + 1, std::memory_order_relaxed);
      if (kExpeditedMembarrier)
        std::atomic_signal_fence(std::memory_order_seq_cst);
      else
        std::atomic_thread_fence(std::memory_order_seq_cst);
      if (group.members.load(std::memory_order_relaxed) <= 1) [[likely]] {
        unlocked_ = &group;
        return;
      }
      group.unlocked_calls.store(calls, std::memory_order_release);
    }
    lock_ = std::unique_lock(group.mutex);
    if (group.join_pending.load(std::memory_order_relaxed)) group.finish_join();
  }
  ~SharedCallGuard() {
    if (unlocked_)
      unlocked_->unlocked_calls.store(unlocked_->unlocked_calls.load(std::memory_order_relaxed) - 1,
                                      std::memory_order_release);
  }
  // Whether the call holds the group's lock (the group has more than one member).
  bool locked() const { return lock_.owns_lock(); }
  SharedCallGuard(const SharedCallGuard&) = delete;
  SharedCallGuard& operator=(const SharedCallGuard&) = delete;

 private:
  ShareGroup* unlocked_ = nullptr;
  std::unique_lock<std::recursive_mutex> lock_;
};

inline SharedCallGuard lock_if_shared(ShareGroup& group) { return SharedCallGuard(group); }

}  // namespace pineda
