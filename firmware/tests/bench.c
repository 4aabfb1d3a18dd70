/* The ISS speed benchmark's workload (bench_iss, BM_IssFirmware): integer kernels (CRC32,
 * insertion sort) and floating-point kernels (Mandelbrot, slab tests), about 60 M
 * instructions. It checks its own result, so a fast but wrong ISS does not pass. */
#include "strata_runtime.h"

static uint8_t data[8192];
static uint32_t keys[512];

static uint32_t crc32(const uint8_t* p, size_t n, uint32_t crc) {
  for (size_t i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc;
}

static uint32_t sort_round(uint32_t seed) {
  for (int i = 0; i < 512; ++i) {
    seed = seed * 1664525u + 1013904223u;
    keys[i] = seed >> 4;
  }
  for (int i = 1; i < 512; ++i) {
    const uint32_t key = keys[i];
    int j = i - 1;
    while (j >= 0 && keys[j] > key) {
      keys[j + 1] = keys[j];
      --j;
    }
    keys[j + 1] = key;
  }
  return keys[0] ^ keys[255] ^ keys[511];
}

static uint32_t mandelbrot(int width, int height, int max_iterations) {
  uint32_t total = 0;
  for (int py = 0; py < height; ++py) {
    const float ci = -1.2f + 2.4f * (float)py / (float)height;
    for (int px = 0; px < width; ++px) {
      const float cr = -2.0f + 3.0f * (float)px / (float)width;
      float zr = 0.0f, zi = 0.0f;
      int n = 0;
      while (n < max_iterations && zr * zr + zi * zi <= 4.0f) {
        const float t = zr * zr - zi * zi + cr;
        zi = 2.0f * zr * zi + ci;
        zr = t;
        ++n;
      }
      total += (uint32_t)n;
    }
  }
  return total;
}

/* Ray against a grid of boxes, written out as the firmware's software fallback would. */
static uint32_t slab_tests(int count) {
  uint32_t hits = 0;
  float ox = 0.1f, oy = 0.2f, oz = -5.0f;
  for (int i = 0; i < count; ++i) {
    const float dx = 0.001f * (float)(i % 97) - 0.05f, dy = 0.0013f * (float)(i % 89) - 0.06f, dz = 1.0f;
    const float ix = 1.0f / dx, iy = 1.0f / dy, iz = 1.0f / dz;
    const float bx = (float)(i % 7) - 3.0f, by = (float)(i % 5) - 2.0f;
    float t0 = (bx - ox) * ix, t1 = (bx + 1.0f - ox) * ix;
    float tn = t0 < t1 ? t0 : t1, tf = t0 < t1 ? t1 : t0;
    t0 = (by - oy) * iy;
    t1 = (by + 1.0f - oy) * iy;
    tn = tn > (t0 < t1 ? t0 : t1) ? tn : (t0 < t1 ? t0 : t1);
    tf = tf < (t0 < t1 ? t1 : t0) ? tf : (t0 < t1 ? t1 : t0);
    t0 = (0.0f - oz) * iz;
    t1 = (1.0f - oz) * iz;
    tn = tn > t0 ? tn : t0;
    tf = tf < t1 ? tf : t1;
    hits += tn <= tf;
  }
  return hits;
}

uint32_t bench_checksum(void) {
  uint32_t check = 0;
  for (size_t i = 0; i < sizeof data; ++i) data[i] = (uint8_t)(i * 131u + (i >> 7));
  uint32_t crc = 0xFFFFFFFFu;
  for (int round = 0; round < 20; ++round) crc = crc32(data, sizeof data, crc);
  check ^= crc;
  for (uint32_t round = 0; round < 6; ++round) check = check * 33u + sort_round(round);
  check = check * 33u + mandelbrot(96, 64, 256);
  check = check * 33u + slab_tests(200000);
  return check;
}

#ifndef BENCH_HOST
int main(void) { return bench_checksum() == 0x61E28FFEu ? 0 : 1; }
#endif
