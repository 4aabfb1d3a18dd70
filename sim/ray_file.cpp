#include "sim/ray_file.h"

#include "sim/output_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <system_error>

#include "firmware/common/traverse.h"
#include "scenes/procedural/random.h"

namespace strata::sim {
namespace {

// Explicit little-endian encoding, so the files are the same on any host.
void put_u32(uint8_t* p, uint32_t v) {
  p[0] = uint8_t(v);
  p[1] = uint8_t(v >> 8);
  p[2] = uint8_t(v >> 16);
  p[3] = uint8_t(v >> 24);
}
uint32_t get_u32(const uint8_t* p) {
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
void put_f32(uint8_t* p, float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  put_u32(p, u);
}
float get_f32(const uint8_t* p) {
  const uint32_t u = get_u32(p);
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// What distinguishes the two formats.
struct Format {
  const char* magic;  // 8 characters
  const char* kind;   // "ray file" / "hit file"
  const char* noun;   // "rays" / "hits"
  uint64_t record_bytes;
};
constexpr Format kRayFormat{kRayFileMagic, "ray file", "rays", kRayRecordBytes};
constexpr Format kHitFormat{kHitFileMagic, "hit file", "hits", kHitRecordBytes};

std::string name_of(const std::filesystem::path& file) { return file.string(); }

// The 8 magic bytes, printable, with anything else escaped as \xNN.
std::string quoted_magic(const uint8_t* p) {
  std::string s = "\"";
  for (int i = 0; i < 8; ++i) {
    if (p[i] >= 0x20 && p[i] < 0x7f && p[i] != '"' && p[i] != '\\') {
      s += char(p[i]);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", unsigned(p[i]));
      s += buf;
    }
  }
  return s + "\"";
}

// Reads and checks the whole file; returns the count and the bytes (header included).
std::vector<uint8_t> read_checked(const std::filesystem::path& file, const Format& f,
                                  uint32_t* count) {
  const std::string name = name_of(file);
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status))
    throw RayFileError(name + ": cannot open " + f.kind + ": no such file");
  if (!std::filesystem::is_regular_file(status))
    throw RayFileError(name + ": cannot open " + f.kind + ": not a regular file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw RayFileError(name + ": cannot open " + f.kind + ": " + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  in.seekg(0, std::ios::beg);
  if (end < 0) throw RayFileError(name + ": cannot read " + f.kind);
  std::vector<uint8_t> bytes(static_cast<size_t>(end));
  if (!bytes.empty() && !in.read(reinterpret_cast<char*>(bytes.data()), end))
    throw RayFileError(name + ": cannot read " + f.kind);
  const uint64_t size = bytes.size();

  if (size < kFileHeaderBytes)
    throw RayFileError(name + ": not a " + f.kind + ": " + std::to_string(size) +
                       " bytes, shorter than the " + std::to_string(kFileHeaderBytes) +
                       "-byte header");
  if (std::memcmp(bytes.data(), f.magic, 8) != 0) {
    std::string msg = name + ": not a " + f.kind + ": magic is " + quoted_magic(bytes.data()) +
                      ", expected \"" + f.magic + "\"";
    if (std::memcmp(bytes.data(), kRayFileMagic, 8) == 0) msg += " (this is a ray file)";
    if (std::memcmp(bytes.data(), kHitFileMagic, 8) == 0) msg += " (this is a hit file)";
    throw RayFileError(msg);
  }
  *count = get_u32(bytes.data() + 8);
  const uint32_t flags = get_u32(bytes.data() + 12);
  if (flags != 0) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08x", unsigned(flags));
    throw RayFileError(name + ": unsupported flags " + buf + " in the header (must be 0)");
  }
  const uint64_t expected = kFileHeaderBytes + f.record_bytes * *count;
  if (size != expected)
    throw RayFileError(name + ": " + (size < expected ? "truncated" : "trailing bytes") +
                       ": header says " + std::to_string(*count) + " " + f.noun + " (" +
                       std::to_string(expected) + " bytes) but the file has " +
                       std::to_string(size) + " bytes");
  return bytes;
}

std::vector<uint8_t> make_header(const std::filesystem::path& file, const Format& f,
                                 size_t count) {
  if (count > std::numeric_limits<uint32_t>::max())
    throw RayFileError(name_of(file) + ": cannot write " + std::to_string(count) + " " + f.noun +
                       ": a " + f.kind + " holds at most 4294967295");
  std::vector<uint8_t> bytes(kFileHeaderBytes + f.record_bytes * count);
  std::memcpy(bytes.data(), f.magic, 8);
  put_u32(bytes.data() + 8, uint32_t(count));
  put_u32(bytes.data() + 12, 0);
  return bytes;
}

void write_bytes(const std::filesystem::path& file, const Format& f,
                 const std::vector<uint8_t>& bytes) {
  try {
    write_file_atomically(file, bytes, f.kind);
  } catch (const std::runtime_error& e) {
    throw RayFileError(e.what());
  }
}

struct CountingObserver {
  uint64_t node_visits = 0, triangle_tests = 0;
  void node_visited(uint32_t) { ++node_visits; }
  void leaf_visited(uint32_t) {}
  void triangle_tested() { ++triangle_tests; }
};

}  // namespace

std::vector<RayRecord> read_ray_file(const std::filesystem::path& file) {
  uint32_t count = 0;
  const std::vector<uint8_t> bytes = read_checked(file, kRayFormat, &count);
  std::vector<RayRecord> rays(count);
  const uint8_t* p = bytes.data() + kFileHeaderBytes;
  for (RayRecord& r : rays) {
    for (int k = 0; k < 3; ++k) r.origin[k] = get_f32(p + 4 * k);
    for (int k = 0; k < 3; ++k) r.dir[k] = get_f32(p + 12 + 4 * k);
    r.tmin = get_f32(p + 24);
    r.tmax = get_f32(p + 28);
    p += kRayRecordBytes;
  }
  return rays;
}

std::vector<HitRecord> read_hit_file(const std::filesystem::path& file) {
  uint32_t count = 0;
  const std::vector<uint8_t> bytes = read_checked(file, kHitFormat, &count);
  std::vector<HitRecord> hits(count);
  const uint8_t* p = bytes.data() + kFileHeaderBytes;
  for (HitRecord& h : hits) {
    h.t = get_f32(p);
    h.primitive = get_u32(p + 4);
    h.b1 = get_f32(p + 8);
    h.b2 = get_f32(p + 12);
    p += kHitRecordBytes;
  }
  return hits;
}

void write_ray_file(const std::filesystem::path& file, const std::vector<RayRecord>& rays) {
  std::vector<uint8_t> bytes = make_header(file, kRayFormat, rays.size());
  uint8_t* p = bytes.data() + kFileHeaderBytes;
  for (const RayRecord& r : rays) {
    for (int k = 0; k < 3; ++k) put_f32(p + 4 * k, r.origin[k]);
    for (int k = 0; k < 3; ++k) put_f32(p + 12 + 4 * k, r.dir[k]);
    put_f32(p + 24, r.tmin);
    put_f32(p + 28, r.tmax);
    p += kRayRecordBytes;
  }
  write_bytes(file, kRayFormat, bytes);
}

void write_hit_file(const std::filesystem::path& file, const std::vector<HitRecord>& hits) {
  std::vector<uint8_t> bytes = make_header(file, kHitFormat, hits.size());
  uint8_t* p = bytes.data() + kFileHeaderBytes;
  for (const HitRecord& h : hits) {
    put_f32(p, h.t);
    put_u32(p + 4, h.primitive);
    put_f32(p + 8, h.b1);
    put_f32(p + 12, h.b2);
    p += kHitRecordBytes;
  }
  write_bytes(file, kHitFormat, bytes);
}

bool ray_is_valid(const RayRecord& r) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(r.origin[k]) || !std::isfinite(r.dir[k])) return false;
  if (r.dir[0] == 0.0f && r.dir[1] == 0.0f && r.dir[2] == 0.0f) return false;
  if (!std::isfinite(r.tmin) || std::isnan(r.tmax)) return false;
  return r.tmin >= 0.0f && r.tmin <= r.tmax;
}

std::vector<RayRecord> generate_random_rays(const scenes::Bounds& bounds, uint32_t count,
                                            uint64_t seed) {
  scenes::Pcg32 rng = scenes::Pcg32::keyed(seed, 0x7374726179730000ull);  // "strays"
  std::vector<RayRecord> rays(count);
  for (RayRecord& r : rays) {
    r.origin[0] = rng.uniform(bounds.min.x, bounds.max.x);
    r.origin[1] = rng.uniform(bounds.min.y, bounds.max.y);
    r.origin[2] = rng.uniform(bounds.min.z, bounds.max.z);
    // Uniform on the sphere: z uniform in [-1, 1), azimuth uniform (Archimedes).
    const float z = rng.uniform(-1.0f, 1.0f);
    const float phi = rng.uniform(0.0f, 6.28318530718f);
    const float rxy = std::sqrt(std::max(0.0f, 1.0f - z * z));
    r.dir[0] = rxy * std::cos(phi);
    r.dir[1] = rxy * std::sin(phi);
    r.dir[2] = z;
    r.tmin = 0.0f;
    r.tmax = std::numeric_limits<float>::infinity();
  }
  return rays;
}

std::vector<HitRecord> trace_rays(const scenes::SceneImage& image,
                                  const std::vector<RayRecord>& rays, TraceStats* stats) {
  const uint32_t root = image.header().root_node;
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<HitRecord> hits(rays.size());
  TraceStats s;
  CountingObserver obs;
  for (size_t i = 0; i < rays.size(); ++i) {
    const RayRecord& r = rays[i];
    HitRecord& out = hits[i];
    out = {inf, kMissPrimitive, 0.0f, 0.0f};
    if (!ray_is_valid(r)) {
      if (s.invalid++ == 0) s.first_invalid = i;
      continue;
    }
    const TraceRay ray{{r.origin[0], r.origin[1], r.origin[2]},
                       {r.dir[0], r.dir[1], r.dir[2]},
                       r.tmin,
                       r.tmax};
    const ClosestHit h = trace_closest(image, root, ray, obs);
    if (h.hit) {
      out = {h.t, h.primitive, h.b1, h.b2};
      ++s.hits;
    }
  }
  s.rays = rays.size();
  s.misses = s.rays - s.hits;
  s.node_visits = obs.node_visits;
  s.triangle_tests = obs.triangle_tests;
  if (stats) *stats = s;
  return hits;
}

}  // namespace strata::sim
