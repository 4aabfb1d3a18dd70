/* memcpy, memmove, memset and memcmp across alignments and lengths, and load sign extension. */
#include "strata_runtime.h"

static uint8_t src[300], dst[300];

static void fill_pattern(uint8_t* p, size_t n, uint8_t seed) {
  for (size_t i = 0; i < n; ++i) p[i] = (uint8_t)(seed + i * 7u);
}

int main(void) {
  for (size_t offset_src = 0; offset_src < 4; ++offset_src) {
    for (size_t offset_dst = 0; offset_dst < 4; ++offset_dst) {
      for (size_t n = 0; n < 70; n += 3) {
        fill_pattern(src, sizeof src, (uint8_t)(n + offset_src));
        memset(dst, 0xEE, sizeof dst);
        memcpy(dst + offset_dst, src + offset_src, n);
        for (size_t i = 0; i < offset_dst; ++i) STRATA_CHECK(dst[i] == 0xEE);
        for (size_t i = 0; i < n; ++i) STRATA_CHECK(dst[offset_dst + i] == src[offset_src + i]);
        STRATA_CHECK(dst[offset_dst + n] == 0xEE);
        STRATA_CHECK(memcmp(dst + offset_dst, src + offset_src, n) == 0);
      }
    }
  }

  for (size_t offset = 0; offset < 4; ++offset) {
    for (size_t n = 0; n < 40; ++n) {
      memset(dst, 0, sizeof dst);
      memset(dst + offset, 0xA5, n);
      for (size_t i = 0; i < 60; ++i) STRATA_CHECK(dst[i] == ((i >= offset && i < offset + n) ? 0xA5 : 0));
    }
  }

  /* Overlapping moves in both directions. */
  fill_pattern(dst, 64, 1);
  memmove(dst + 5, dst, 40);
  for (size_t i = 0; i < 40; ++i) STRATA_CHECK(dst[5 + i] == (uint8_t)(1 + i * 7u));
  fill_pattern(dst, 64, 1);
  memmove(dst, dst + 9, 40);
  for (size_t i = 0; i < 40; ++i) STRATA_CHECK(dst[i] == (uint8_t)(1 + (i + 9) * 7u));

  STRATA_CHECK(memcmp("abc", "abd", 3) < 0);
  STRATA_CHECK(memcmp("abd", "abc", 3) > 0);

  /* Sign and zero extension of byte and halfword loads. */
  static volatile int8_t bytes[2] = {-128, 127};
  static volatile int16_t halves[2] = {-32768, 32767};
  static volatile uint8_t ubytes[1] = {0xFF};
  static volatile uint16_t uhalves[1] = {0xFFFF};
  STRATA_CHECK((int32_t)bytes[0] == -128);
  STRATA_CHECK((int32_t)bytes[1] == 127);
  STRATA_CHECK((int32_t)halves[0] == -32768);
  STRATA_CHECK((int32_t)halves[1] == 32767);
  STRATA_CHECK((uint32_t)ubytes[0] == 255u);
  STRATA_CHECK((uint32_t)uhalves[0] == 65535u);

  /* Byte stores into a word, read back as a word (little-endian). */
  static volatile uint32_t word;
  volatile uint8_t* b = (volatile uint8_t*)&word;
  b[0] = 0x11;
  b[1] = 0x22;
  b[2] = 0x33;
  b[3] = 0x44;
  STRATA_CHECK(word == 0x44332211u);
  ((volatile uint16_t*)&word)[1] = 0xBEEF;
  STRATA_CHECK(word == 0xBEEF2211u);

  /* A struct copy the compiler turns into a memcpy call or an inline sequence. */
  struct big {
    uint32_t v[37];
  } a, c;
  for (uint32_t i = 0; i < 37; ++i) a.v[i] = i * i;
  c = a;
  for (uint32_t i = 0; i < 37; ++i) STRATA_CHECK(c.v[i] == i * i);
  return 0;
}
