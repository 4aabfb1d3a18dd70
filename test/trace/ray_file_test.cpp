// The ray and hit file formats: exact on-disk layout, bit-exact round trips, and an error
// naming the file for every kind of malformed file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "sim/ray_file.h"
#include "test/support/test_files.h"

namespace strata::sim {
namespace {

using testing::TempDir;
using testing::read_bytes;
using testing::write_bytes;

constexpr float kInf = std::numeric_limits<float>::infinity();

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

uint32_t le32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) | (uint32_t(b[at + 1]) << 8) | (uint32_t(b[at + 2]) << 16) |
         (uint32_t(b[at + 3]) << 24);
}

void put_le32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  for (int k = 0; k < 4; ++k) b[at + k] = uint8_t(v >> (8 * k));
}

// The message of the RayFileError `f` throws, or "no error".
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const RayFileError& e) {
    return e.what();
  }
  return "no error";
}

std::vector<RayRecord> sample_rays() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  return {
      {{1.0f, -2.0f, 3.5f}, {0.0f, 0.0f, -1.0f}, 0.0f, kInf},
      {{-0.0f, 1e-40f, 3.4e38f}, {0.25f, -0.5f, 0.125f}, 0.001f, 17.0f},
      {{nan, kInf, -kInf}, {1.0f, 2.0f, 3.0f}, 5.0f, 1.0f},  // invalid, but stored as is
  };
}

std::vector<HitRecord> sample_hits() {
  return {{2.5f, 7u, 0.25f, 0.5f}, {kInf, kMissPrimitive, 0.0f, 0.0f}, {1e-30f, 0x01020304u, 1.0f, -0.0f}};
}

void expect_same_bits(const RayRecord& a, const RayRecord& b) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(bits(a.origin[k]), bits(b.origin[k]));
    EXPECT_EQ(bits(a.dir[k]), bits(b.dir[k]));
  }
  EXPECT_EQ(bits(a.tmin), bits(b.tmin));
  EXPECT_EQ(bits(a.tmax), bits(b.tmax));
}

TEST(TraceRayFile, RoundTripKeepsEveryBit) {
  TempDir dir;
  const auto rays = sample_rays();
  write_ray_file(dir / "rays.bin", rays);
  const auto back = read_ray_file(dir / "rays.bin");
  ASSERT_EQ(back.size(), rays.size());
  for (size_t i = 0; i < rays.size(); ++i) expect_same_bits(rays[i], back[i]);
}

TEST(TraceRayFile, OnDiskLayoutIsTheDocumentedLittleEndianOne) {
  TempDir dir;
  const auto rays = sample_rays();
  write_ray_file(dir / "rays.bin", rays);
  const auto b = read_bytes(dir / "rays.bin");
  ASSERT_EQ(b.size(), 16u + 32u * rays.size());
  EXPECT_EQ(std::string(b.begin(), b.begin() + 8), "STRAYS01");
  EXPECT_EQ(le32(b, 8), 3u);
  EXPECT_EQ(le32(b, 12), 0u);
  for (size_t i = 0; i < rays.size(); ++i) {
    const size_t r = 16 + 32 * i;
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(le32(b, r + 4 * k), bits(rays[i].origin[k]));
      EXPECT_EQ(le32(b, r + 12 + 4 * k), bits(rays[i].dir[k]));
    }
    EXPECT_EQ(le32(b, r + 24), bits(rays[i].tmin));
    EXPECT_EQ(le32(b, r + 28), bits(rays[i].tmax));
  }
  EXPECT_EQ(b[16], 0x00);  // 1.0f = 0x3f800000, least significant byte first
  EXPECT_EQ(b[19], 0x3f);
}

TEST(TraceRayFile, EmptyBatchIsJustTheHeader) {
  TempDir dir;
  write_ray_file(dir / "rays.bin", {});
  EXPECT_EQ(read_bytes(dir / "rays.bin").size(), 16u);
  EXPECT_TRUE(read_ray_file(dir / "rays.bin").empty());
}

TEST(TraceHitFile, RoundTripKeepsEveryBit) {
  TempDir dir;
  const auto hits = sample_hits();
  write_hit_file(dir / "hits.bin", hits);
  const auto back = read_hit_file(dir / "hits.bin");
  ASSERT_EQ(back.size(), hits.size());
  for (size_t i = 0; i < hits.size(); ++i) {
    EXPECT_EQ(bits(back[i].t), bits(hits[i].t));
    EXPECT_EQ(back[i].primitive, hits[i].primitive);
    EXPECT_EQ(bits(back[i].b1), bits(hits[i].b1));
    EXPECT_EQ(bits(back[i].b2), bits(hits[i].b2));
  }
}

TEST(TraceHitFile, OnDiskLayoutIsTheDocumentedLittleEndianOne) {
  TempDir dir;
  const auto hits = sample_hits();
  write_hit_file(dir / "hits.bin", hits);
  const auto b = read_bytes(dir / "hits.bin");
  ASSERT_EQ(b.size(), 16u + 16u * hits.size());
  EXPECT_EQ(std::string(b.begin(), b.begin() + 8), "STRHITS1");
  EXPECT_EQ(le32(b, 8), 3u);
  EXPECT_EQ(le32(b, 12), 0u);
  for (size_t i = 0; i < hits.size(); ++i) {
    const size_t r = 16 + 16 * i;
    EXPECT_EQ(le32(b, r), bits(hits[i].t));
    EXPECT_EQ(le32(b, r + 4), hits[i].primitive);
    EXPECT_EQ(le32(b, r + 8), bits(hits[i].b1));
    EXPECT_EQ(le32(b, r + 12), bits(hits[i].b2));
  }
  EXPECT_EQ(le32(b, 16 + 16 + 4), 0xFFFFFFFFu);  // the miss
  EXPECT_EQ(le32(b, 16 + 16), 0x7f800000u);      // +inf
  EXPECT_EQ(b[16 + 32 + 4], 0x04);               // 0x01020304, least significant byte first
}

// --- malformed files: each error names the file and says what is wrong ---

TEST(TraceRayFile, MissingFile) {
  TempDir dir;
  const auto file = dir / "nope.bin";
  EXPECT_EQ(error_of([&] { read_ray_file(file); }), file.string() + ": cannot open ray file: no such file");
  EXPECT_EQ(error_of([&] { read_hit_file(file); }), file.string() + ": cannot open hit file: no such file");
}

TEST(TraceRayFile, DirectoryIsNotAFile) {
  TempDir dir;
  EXPECT_EQ(error_of([&] { read_ray_file(dir.path()); }),
            dir.path().string() + ": cannot open ray file: not a regular file");
}

TEST(TraceRayFile, ShorterThanTheHeader) {
  TempDir dir;
  const auto file = dir / "short.bin";
  write_bytes(file, {});
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": not a ray file: 0 bytes, shorter than the 16-byte header");
  write_bytes(file, {'S', 'T', 'R', 'A', 'Y', 'S', '0', '1', 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": not a ray file: 15 bytes, shorter than the 16-byte header");
  EXPECT_EQ(error_of([&] { read_hit_file(file); }),
            file.string() + ": not a hit file: 15 bytes, shorter than the 16-byte header");
}

TEST(TraceRayFile, WrongMagic) {
  TempDir dir;
  const auto file = dir / "magic.bin";
  write_ray_file(file, sample_rays());
  auto b = read_bytes(file);
  b[7] = '2';
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": not a ray file: magic is \"STRAYS02\", expected \"STRAYS01\"");
  b[0] = 0;
  b[1] = 0xff;
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": not a ray file: magic is \"\\x00\\xffRAYS02\", expected \"STRAYS01\"");
}

TEST(TraceRayFile, HitFileGivenAsRayFileAndViceVersa) {
  TempDir dir;
  write_hit_file(dir / "hits.bin", sample_hits());
  write_ray_file(dir / "rays.bin", sample_rays());
  EXPECT_EQ(error_of([&] { read_ray_file(dir / "hits.bin"); }),
            (dir / "hits.bin").string() +
                ": not a ray file: magic is \"STRHITS1\", expected \"STRAYS01\" (this is a hit file)");
  EXPECT_EQ(error_of([&] { read_hit_file(dir / "rays.bin"); }),
            (dir / "rays.bin").string() +
                ": not a hit file: magic is \"STRAYS01\", expected \"STRHITS1\" (this is a ray file)");
}

TEST(TraceRayFile, NonZeroFlags) {
  TempDir dir;
  const auto file = dir / "flags.bin";
  write_ray_file(file, sample_rays());
  auto b = read_bytes(file);
  put_le32(b, 12, 0x80000001u);
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": unsupported flags 0x80000001 in the header (must be 0)");
}

TEST(TraceRayFile, TruncatedFile) {
  TempDir dir;
  const auto file = dir / "rays.bin";
  write_ray_file(file, std::vector<RayRecord>(1000, sample_rays()[0]));
  auto b = read_bytes(file);
  ASSERT_EQ(b.size(), 32016u);
  b.resize(20000);
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": truncated: header says 1000 rays (32016 bytes) but the file has 20000 bytes");
  b.resize(16);  // header only
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": truncated: header says 1000 rays (32016 bytes) but the file has 16 bytes");
}

TEST(TraceRayFile, CountFarBeyondTheFileDoesNotOverflow) {
  TempDir dir;
  const auto file = dir / "rays.bin";
  write_ray_file(file, sample_rays());
  auto b = read_bytes(file);
  put_le32(b, 8, 0xFFFFFFFFu);
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": truncated: header says 4294967295 rays (137438953456 bytes) but the file has 112 bytes");
}

TEST(TraceRayFile, TrailingBytes) {
  TempDir dir;
  const auto file = dir / "rays.bin";
  write_ray_file(file, std::vector<RayRecord>(1000, sample_rays()[0]));
  auto b = read_bytes(file);
  b.resize(b.size() + 4, 0);
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_ray_file(file); }),
            file.string() + ": trailing bytes: header says 1000 rays (32016 bytes) but the file has 32020 bytes");
}

TEST(TraceHitFile, TruncatedAndTrailing) {
  TempDir dir;
  const auto file = dir / "hits.bin";
  write_hit_file(file, sample_hits());
  auto b = read_bytes(file);
  ASSERT_EQ(b.size(), 64u);
  b.pop_back();
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_hit_file(file); }),
            file.string() + ": truncated: header says 3 hits (64 bytes) but the file has 63 bytes");
  b.resize(80, 0);
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_hit_file(file); }),
            file.string() + ": trailing bytes: header says 3 hits (64 bytes) but the file has 80 bytes");
  put_le32(b, 12, 2u);
  write_bytes(file, b);
  EXPECT_EQ(error_of([&] { read_hit_file(file); }),
            file.string() + ": unsupported flags 0x00000002 in the header (must be 0)");
}

TEST(TraceRayFile, UnwritablePathNamesTheFile) {
  TempDir dir;
  const auto file = dir / "no-such-dir" / "rays.bin";
  const std::string msg = error_of([&] { write_ray_file(file, sample_rays()); });
  EXPECT_EQ(msg.rfind(file.string() + ": cannot write ray file", 0), 0u) << msg;
}

// --- which rays are traced ---

TEST(TraceRayValidity, FiniteOriginDirectionAndOrderedInterval) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const RayRecord good{{0, 0, 0}, {0, 0, 1}, 0.0f, kInf};
  EXPECT_TRUE(ray_is_valid(good));
  auto with = [&](auto change) {
    RayRecord r = good;
    change(r);
    return ray_is_valid(r);
  };
  EXPECT_TRUE(with([](RayRecord& r) { r.tmax = 3.0f; }));
  EXPECT_TRUE(with([](RayRecord& r) { r.tmin = r.tmax = 3.0f; }));  // empty interval: a miss
  EXPECT_TRUE(with([](RayRecord& r) { r.tmin = -0.0f; }));
  EXPECT_TRUE(with([](RayRecord& r) { r.dir[2] = 1e-30f; }));  // not normalised: allowed
  EXPECT_FALSE(with([&](RayRecord& r) { r.origin[1] = nan; }));
  EXPECT_FALSE(with([&](RayRecord& r) { r.origin[0] = -kInf; }));
  EXPECT_FALSE(with([&](RayRecord& r) { r.dir[0] = kInf; }));
  EXPECT_FALSE(with([&](RayRecord& r) { r.dir[2] = nan; }));
  EXPECT_FALSE(with([](RayRecord& r) { r.dir[2] = 0.0f; }));
  EXPECT_FALSE(with([](RayRecord& r) { r.tmin = -1e-6f; }));
  EXPECT_FALSE(with([](RayRecord& r) { r.tmin = 2.0f, r.tmax = 1.0f; }));
  EXPECT_FALSE(with([&](RayRecord& r) { r.tmin = kInf; }));
  EXPECT_FALSE(with([&](RayRecord& r) { r.tmin = nan; }));
  EXPECT_FALSE(with([&](RayRecord& r) { r.tmax = nan; }));
}

// --- random rays ---

TEST(TraceGenerate, DeterministicInsideTheBoundsUniformDirections) {
  scenes::Bounds b;
  b.extend({-1.0f, 2.0f, -30.0f});
  b.extend({3.0f, 2.5f, 10.0f});
  const auto rays = generate_random_rays(b, 20000, 42);
  ASSERT_EQ(rays.size(), 20000u);
  double mean[3] = {0, 0, 0};
  for (const RayRecord& r : rays) {
    EXPECT_TRUE(ray_is_valid(r));
    EXPECT_EQ(r.tmin, 0.0f);
    EXPECT_EQ(r.tmax, kInf);
    EXPECT_GE(r.origin[0], -1.0f);
    EXPECT_LE(r.origin[0], 3.0f);
    EXPECT_GE(r.origin[1], 2.0f);
    EXPECT_LE(r.origin[1], 2.5f);
    EXPECT_GE(r.origin[2], -30.0f);
    EXPECT_LE(r.origin[2], 10.0f);
    const double len = std::sqrt(double(r.dir[0]) * r.dir[0] + double(r.dir[1]) * r.dir[1] +
                                 double(r.dir[2]) * r.dir[2]);
    EXPECT_NEAR(len, 1.0, 1e-5);
    for (int k = 0; k < 3; ++k) mean[k] += r.dir[k] / 20000.0;
  }
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(mean[k], 0.0, 0.02) << "axis " << k;

  const auto again = generate_random_rays(b, 100, 42);
  for (size_t i = 0; i < again.size(); ++i) expect_same_bits(again[i], rays[i]);  // prefix
  const auto other = generate_random_rays(b, 100, 43);
  EXPECT_NE(bits(other[0].origin[0]), bits(rays[0].origin[0]));
}

}  // namespace
}  // namespace strata::sim
