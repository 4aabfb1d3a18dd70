// A minimal float 3-vector for freestanding code (firmware, pipeline models, host tools).
// Every operation is written out so the order of floating-point operations is fixed; with
// -ffp-contract=off no compiler may fuse a multiply and an add, on the host or on RISC-V.
#pragma once

// For the few tiny functions on the traversal's hot path: GCC for RV32 at -O2 otherwise
// keeps some of them as calls, which costs the firmware a call, spills and a return per box.
#define STRATA_INLINE inline __attribute__((always_inline))

namespace strata {

struct Vec3f {
  float x, y, z;
};

STRATA_INLINE Vec3f operator-(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
STRATA_INLINE Vec3f operator+(Vec3f a, Vec3f b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
STRATA_INLINE Vec3f operator*(Vec3f a, float s) { return {a.x * s, a.y * s, a.z * s}; }
STRATA_INLINE float dot(Vec3f a, Vec3f b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
STRATA_INLINE Vec3f cross(Vec3f a, Vec3f b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
STRATA_INLINE Vec3f load_vec3(const float* p) { return {p[0], p[1], p[2]}; }

}  // namespace strata
