/* Integer arithmetic: the M extension's edge cases (through inline asm, since C leaves
 * INT_MIN / -1 and division by zero undefined), shifts, 64-bit helpers from libgcc, CRC32. */
#include "strata_runtime.h"

#define RR(op, a, b)                                                        \
  __extension__({                                                           \
    uint32_t r_;                                                            \
    __asm__ volatile(op " %0, %1, %2" : "=r"(r_) : "r"((uint32_t)(a)), "r"((uint32_t)(b))); \
    r_;                                                                     \
  })

static uint32_t crc32(const uint8_t* p, size_t n) {
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

int main(void) {
  const uint32_t int_min = 0x80000000u, minus1 = 0xFFFFFFFFu;

  STRATA_CHECK(RR("div", int_min, minus1) == int_min);
  STRATA_CHECK(RR("rem", int_min, minus1) == 0);
  STRATA_CHECK(RR("div", 7, 0) == minus1);
  STRATA_CHECK(RR("divu", 7, 0) == 0xFFFFFFFFu);
  STRATA_CHECK(RR("rem", 7, 0) == 7);
  STRATA_CHECK(RR("remu", 0xFFFFFFF9u, 0) == 0xFFFFFFF9u);
  STRATA_CHECK(RR("div", -7, 2) == (uint32_t)-3);
  STRATA_CHECK(RR("rem", -7, 2) == (uint32_t)-1);
  STRATA_CHECK(RR("div", 7, -2) == (uint32_t)-3);
  STRATA_CHECK(RR("rem", 7, -2) == 1);
  STRATA_CHECK(RR("divu", 0xFFFFFFFEu, 3) == 0x55555554u);
  STRATA_CHECK(RR("remu", 0xFFFFFFFEu, 3) == 2);

  STRATA_CHECK(RR("mul", 0x7FFFFFFF, 2) == 0xFFFFFFFEu);
  STRATA_CHECK(RR("mulh", int_min, int_min) == 0x40000000u);
  STRATA_CHECK(RR("mulh", int_min, 1) == 0xFFFFFFFFu);
  STRATA_CHECK(RR("mulh", minus1, minus1) == 0);
  STRATA_CHECK(RR("mulhu", minus1, minus1) == 0xFFFFFFFEu);
  STRATA_CHECK(RR("mulhsu", minus1, minus1) == 0xFFFFFFFFu);
  STRATA_CHECK(RR("mulhsu", int_min, 0xFFFFFFFFu) == 0x80000000u);
  STRATA_CHECK(RR("mulhsu", 1, 0xFFFFFFFFu) == 0);

  STRATA_CHECK(RR("sll", 1, 31) == 0x80000000u);
  STRATA_CHECK(RR("sll", 1, 32 + 3) == 8);  /* only the low five bits count */
  STRATA_CHECK(RR("sra", int_min, 31) == 0xFFFFFFFFu);
  STRATA_CHECK(RR("srl", int_min, 31) == 1);
  STRATA_CHECK(RR("slt", minus1, 0) == 1);
  STRATA_CHECK(RR("sltu", minus1, 0) == 0);

  /* Ordinary C arithmetic with values the compiler cannot fold. */
  volatile int32_t a = -1234567, b = 89;
  STRATA_CHECK(a / b == -13871);
  STRATA_CHECK(a % b == -48);
  volatile uint64_t big = 0x123456789ABCDEF0ull, divisor = 0x12345ull;
  STRATA_CHECK(big / divisor == 0x100005B00205ull);  /* __udivdi3 from libgcc */
  STRATA_CHECK(big % divisor == 0xA497ull);
  volatile int64_t sbig = -0x123456789ABCDEFll;
  STRATA_CHECK(sbig * 3 == -0x369D0369D0369CDll);

  static const char check[] = "123456789";
  STRATA_CHECK(crc32((const uint8_t*)check, 9) == 0xCBF43926u);

  /* Insertion sort of a pseudo-random sequence. */
  uint32_t v[64];
  uint32_t x = 12345, sum = 0;
  for (int i = 0; i < 64; ++i) {
    x = x * 1103515245u + 12345u;
    v[i] = x >> 8;
    sum += v[i];
  }
  for (int i = 1; i < 64; ++i) {
    const uint32_t key = v[i];
    int j = i - 1;
    while (j >= 0 && v[j] > key) {
      v[j + 1] = v[j];
      --j;
    }
    v[j + 1] = key;
  }
  uint32_t sum_after = 0;
  for (int i = 0; i < 64; ++i) {
    if (i > 0) STRATA_CHECK(v[i - 1] <= v[i]);
    sum_after += v[i];
  }
  STRATA_CHECK(sum == sum_after);
  return 0;
}
