/* Freestanding support for RV32IMF firmware: the C string functions the compiler may call,
 * CSR access, and helpers for self-checking test programs. */
#ifndef STRATA_FIRMWARE_RUNTIME_H
#define STRATA_FIRMWARE_RUNTIME_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void* memcpy(void* dst, const void* src, size_t n);
void* memmove(void* dst, const void* src, size_t n);
void* memset(void* dst, int value, size_t n);
int memcmp(const void* a, const void* b, size_t n);

#ifdef __cplusplus
}
#endif

#define STRATA_CSR_READ(csr)                              \
  __extension__({                                         \
    uint32_t strata_v_;                                   \
    __asm__ volatile("csrr %0, " #csr : "=r"(strata_v_)); \
    strata_v_;                                            \
  })
#define STRATA_CSR_WRITE(csr, value) __asm__ volatile("csrw " #csr ", %0" : : "r"((uint32_t)(value)))

/* A failed check makes main return its line number, which becomes the exit code. */
#define STRATA_CHECK(cond)  \
  do {                      \
    if (!(cond)) return __LINE__; \
  } while (0)

/* Bit patterns, so float results can be checked exactly. */
static inline uint32_t strata_float_bits(float f) {
  union {
    float f;
    uint32_t u;
  } v;
  v.f = f;
  return v.u;
}

static inline float strata_bits_float(uint32_t u) {
  union {
    float f;
    uint32_t u;
  } v;
  v.u = u;
  return v.f;
}

#endif /* STRATA_FIRMWARE_RUNTIME_H */
