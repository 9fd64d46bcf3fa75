#include "state/share_group.h"

#include <linux/membarrier.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <thread>

namespace pineda {

bool register_expedited_membarrier() {
  return syscall(__NR_membarrier, MEMBARRIER_CMD_REGISTER_PRIVATE_EXPEDITED, 0, 0) == 0;
}

void ShareGroup::finish_join() {
  // Every thread passes a full fence: a call of the first member either is counted in
  // unlocked_calls by now or has seen the new member and waits for this lock.
  if (kExpeditedMembarrier) syscall(__NR_membarrier, MEMBARRIER_CMD_PRIVATE_EXPEDITED, 0, 0);
  while (unlocked_calls.load(std::memory_order_acquire) != 0) std::this_thread::yield();
  join_pending.store(false, std::memory_order_relaxed);
}

}  // namespace pineda
