// Batch ray queries (`strata-sim trace`): the binary ray and hit file formats, random ray
// generation, and closest-hit tracing of a whole batch against a scene image.
//
// Both files are little-endian: a 16-byte header, then fixed-size records.
//   ray file:  "STRAYS01", uint32 count, uint32 flags (0);
//              per ray 32 bytes: float origin[3], dir[3], tmin, tmax
//   hit file:  "STRHITS1", uint32 count, uint32 flags (0);
//              per ray 16 bytes: float t, uint32 primitive, float b1, float b2
// A miss has primitive = kMissPrimitive, t = +inf, b1 = b2 = 0. The README ("Batch ray
// queries") documents the formats and the semantics of tmin, tmax and invalid rays.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "scenes/scene_image.h"

namespace strata::sim {

// Thrown for an unreadable or malformed file. The message starts with the file name.
class RayFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr char kRayFileMagic[9] = "STRAYS01";
constexpr char kHitFileMagic[9] = "STRHITS1";
constexpr uint64_t kFileHeaderBytes = 16;
constexpr uint64_t kRayRecordBytes = 32;
constexpr uint64_t kHitRecordBytes = 16;
constexpr uint32_t kMissPrimitive = 0xFFFFFFFFu;

struct RayRecord {
  float origin[3];
  float dir[3];  // need not be unit length: the hit point is origin + t * dir
  float tmin, tmax;
};

struct HitRecord {
  float t;             // +inf for a miss
  uint32_t primitive;  // index into the loaded scene's triangles; kMissPrimitive for a miss
  float b1, b2;        // barycentric weights of v1 and v2 (v0 gets 1 - b1 - b2); 0 for a miss
};

// Read and validate a whole file; throw RayFileError("<file>: <what is wrong>").
std::vector<RayRecord> read_ray_file(const std::filesystem::path& file);
std::vector<HitRecord> read_hit_file(const std::filesystem::path& file);
// Throw RayFileError if the file cannot be written (or more than 2^32 - 1 records).
void write_ray_file(const std::filesystem::path& file, const std::vector<RayRecord>& rays);
void write_hit_file(const std::filesystem::path& file, const std::vector<HitRecord>& hits);

// A ray is traced only if every component is finite except tmax (which may be +inf), the
// direction is not zero, and 0 <= tmin <= tmax. Any other ray is reported as a miss.
bool ray_is_valid(const RayRecord& ray);

// `count` incoherent rays: origins uniform in `bounds`, directions uniform on the unit
// sphere, tmin 0, tmax +inf. Deterministic in `seed` (PCG32, the same on every platform);
// the first n rays of a larger batch equal the n rays of a smaller one.
std::vector<RayRecord> generate_random_rays(const scenes::Bounds& bounds, uint32_t count,
                                            uint64_t seed);

struct TraceStats {
  uint64_t rays = 0, hits = 0, misses = 0;
  uint64_t invalid = 0;                  // counted among the misses
  uint64_t first_invalid = UINT64_MAX;   // index of the first invalid ray
  uint64_t node_visits = 0, triangle_tests = 0;
};

// Closest hit of every ray (firmware/common/traverse.h: trace_closest), one thread, in
// order. A hit needs tmin < t < tmax; among equally close triangles the first found wins.
std::vector<HitRecord> trace_rays(const scenes::SceneImage& image,
                                  const std::vector<RayRecord>& rays, TraceStats* stats);

}  // namespace strata::sim
