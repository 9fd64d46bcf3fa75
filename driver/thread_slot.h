// Per-thread driver state that stays valid for as long as the thread can still call in.
#pragma once
#include <pthread.h>

namespace pineda::driver {

// The calling thread's State, made on first use. A thread_local State would be destroyed
// before the program's own thread_local destructors of earlier objects and, on the main thread,
// before atexit handlers: a GL/GLX/EGL call from those would touch a destroyed object. Here
// the State is freed by a pthread key destructor, which runs after all of the thread's
// thread_local destructors (and once more if one of them makes the state again); the main
// thread's State is never freed, since exit() runs no key destructors and atexit handlers
// may still use it.
template <typename State>
State& thread_slot() {
  thread_local State* state = nullptr;  // trivially destructible: readable until the thread is gone
  if (state) return *state;
  static const pthread_key_t key = [] {
    pthread_key_t k{};
    pthread_key_create(&k, [](void* p) {
      state = nullptr;
      delete static_cast<State*>(p);
    });
    return k;
  }();
  state = new State;
  pthread_setspecific(key, state);
  return *state;
}

}  // namespace pineda::driver
