// AddressSanitizer and SystemC's coroutines. libsystemc announces its stack switches to ASan,
// but once sc_start() returns ASan's idea of the main stack's bounds is no longer right (clang's
// runtime says so: "ASan is ignoring requested __asan_handle_no_return ... stack top ... size
// 0xffffff...", a negative size). So a throw does not unpoison the frames it unwinds, their
// redzones stay poisoned, and GCC 12's runtime reports a stack-buffer-overflow in its own
// frame at the next throw or unwinding step (PlatformUnpoisonStacks checks the stack_t it
// passes to the intercepted sigaltstack before it unpoisons anything). docs/testing.md has the
// report. After the simulation, the run tells ASan the main stack again (a switch from it to
// itself) and clears the poison below the caller's frame, where nothing lives, so no finding is
// hidden. A no-op without ASan (the compilers' own feature macros).
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define STRATA_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define STRATA_ASAN 1
#endif
#endif

#ifdef STRATA_ASAN
#include <pthread.h>
#include <sanitizer/asan_interface.h>
#include <sanitizer/common_interface_defs.h>

#include <cstddef>
#include <cstdint>
#endif

namespace strata::sim {

// Call on the main thread once sc_start() has returned.
#ifdef STRATA_ASAN
__attribute__((noinline)) inline void restore_main_stack_for_asan() {
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) == 0) {
    void* bottom = nullptr;
    size_t size = 0;
    const bool known = pthread_attr_getstack(&attr, &bottom, &size) == 0;
    pthread_attr_destroy(&attr);
    if (known) {
      void* fake_stack = nullptr;
      __sanitizer_start_switch_fiber(&fake_stack, bottom, size);
      __sanitizer_finish_switch_fiber(fake_stack, nullptr, nullptr);
    }
  }
  constexpr uintptr_t kBelow = uintptr_t{1} << 20;  // deeper than any throw path below the caller
  volatile char here = 0;
  const uintptr_t top = reinterpret_cast<uintptr_t>(&here) & ~uintptr_t{63};
  __asan_unpoison_memory_region(reinterpret_cast<void*>(top - kBelow), kBelow);
}
#else
inline void restore_main_stack_for_asan() {}
#endif

}  // namespace strata::sim
