// End to end: runs the built strata-sim binary (STRATA_SIM_EXE) on temp files.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "scenes/scene_spec.h"
#include "sim/ray_file.h"
#include "test/support/test_files.h"

namespace strata::sim {
namespace {

using testing::TempDir;
using testing::read_bytes;
using testing::read_text;
using testing::write_bytes;

constexpr const char* kScene = "cornell:size=0.3";

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// Runs strata-sim with `args`, stdout and stderr into files in `dir`; returns the exit code.
int run_sim(const TempDir& dir, const std::string& args) {
  const std::string cmd = std::string("'") + STRATA_SIM_EXE + "' " + args + " >" +
                          quoted(dir / "stdout.txt") + " 2>" + quoted(dir / "stderr.txt");
  const int status = std::system(cmd.c_str());
  if (status == -1 || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

TEST(TraceCommand, GenerateThenTraceWritesTheLibraryHits) {
  TempDir dir;
  const auto rays_file = dir / "rays.bin";
  const auto hits_file = dir / "hits.bin";
  ASSERT_EQ(run_sim(dir, std::string("trace --scene ") + kScene + " --generate 3000 --seed 5 --out " +
                             quoted(rays_file)),
            0)
      << read_text(dir / "stderr.txt");
  const scenes::Scene scene = scenes::load_scene(kScene, STRATA_SOURCE_DIR);
  const auto rays = read_ray_file(rays_file);
  const auto want_rays = generate_random_rays(scene.bounds(), 3000, 5);
  ASSERT_EQ(rays.size(), 3000u);
  for (size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(bits(rays[i].origin[0]), bits(want_rays[i].origin[0])) << "ray " << i;
    EXPECT_EQ(bits(rays[i].dir[2]), bits(want_rays[i].dir[2])) << "ray " << i;
  }

  ASSERT_EQ(run_sim(dir, std::string("trace --scene ") + kScene + " --rays " + quoted(rays_file) +
                             " --out " + quoted(hits_file) + " --cache-dir " + quoted(dir / "cache")),
            0)
      << read_text(dir / "stderr.txt");
  const auto hits = read_hit_file(hits_file);
  const auto image = scenes::build_scene_image(scene, scenes::SceneImageParams{}, nullptr);
  TraceStats stats;
  const auto want = trace_rays(image, rays, &stats);
  ASSERT_EQ(hits.size(), want.size());
  for (size_t i = 0; i < hits.size(); ++i) {
    EXPECT_EQ(hits[i].primitive, want[i].primitive) << "ray " << i;
    EXPECT_EQ(bits(hits[i].t), bits(want[i].t)) << "ray " << i;
    EXPECT_EQ(bits(hits[i].b1), bits(want[i].b1)) << "ray " << i;
    EXPECT_EQ(bits(hits[i].b2), bits(want[i].b2)) << "ray " << i;
  }
  const std::string out = read_text(dir / "stdout.txt");
  EXPECT_NE(out.find("rays             3000 from"), std::string::npos) << out;
  EXPECT_NE(out.find("hits             " + std::to_string(stats.hits) + " ("), std::string::npos) << out;
  EXPECT_NE(out.find("MRays/s"), std::string::npos) << out;
  EXPECT_NE(out.find("node visits"), std::string::npos) << out;
  EXPECT_TRUE(std::filesystem::exists(dir / "cache")) << "--cache-dir not used";
  EXPECT_EQ(read_text(dir / "stderr.txt"), "");
}

TEST(TraceCommand, TruncatedRayFileFailsNamingTheFile) {
  TempDir dir;
  const auto rays_file = dir / "short-rays.bin";
  write_ray_file(rays_file, generate_random_rays(scenes::Bounds{{0, 0, 0}, {1, 1, 1}}, 10, 1));
  auto b = read_bytes(rays_file);
  b.resize(b.size() - 7);
  write_bytes(rays_file, b);
  const int rc = run_sim(dir, std::string("trace --scene ") + kScene + " --rays " + quoted(rays_file) +
                                  " --out " + quoted(dir / "hits.bin") + " --no-cache");
  EXPECT_NE(rc, 0);
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find(rays_file.string() + ": truncated: header says 10 rays (336 bytes) but the file has 329 bytes"),
            std::string::npos)
      << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "hits.bin"));
}

TEST(TraceCommand, MissingRayFileFailsNamingTheFile) {
  TempDir dir;
  const int rc = run_sim(dir, std::string("trace --scene ") + kScene + " --rays " + quoted(dir / "absent.bin") +
                                  " --out " + quoted(dir / "hits.bin") + " --no-cache");
  EXPECT_NE(rc, 0);
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find((dir / "absent.bin").string() + ": cannot open ray file: no such file"), std::string::npos)
      << err;
}

TEST(TraceCommand, InvalidRaysAreMissesWithAWarning) {
  TempDir dir;
  auto rays = generate_random_rays(scenes::Bounds{{-0.5f, 0.5f, -0.5f}, {0.5f, 1.5f, 0.5f}}, 4, 1);
  rays[1].tmin = -1.0f;
  rays[3].origin[0] = std::numeric_limits<float>::quiet_NaN();
  write_ray_file(dir / "rays.bin", rays);
  ASSERT_EQ(run_sim(dir, std::string("trace --scene ") + kScene + " --rays " + quoted(dir / "rays.bin") +
                             " --out " + quoted(dir / "hits.bin") + " --no-cache"),
            0)
      << read_text(dir / "stderr.txt");
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find("warning: " + (dir / "rays.bin").string() + ": 2 invalid rays (first: ray 1)"),
            std::string::npos)
      << err;
  const auto hits = read_hit_file(dir / "hits.bin");
  ASSERT_EQ(hits.size(), 4u);
  EXPECT_EQ(hits[1].primitive, kMissPrimitive);
  EXPECT_EQ(hits[3].primitive, kMissPrimitive);
  EXPECT_NE(read_text(dir / "stdout.txt").find("(2 invalid rays among them)"), std::string::npos);
}

TEST(TraceCommand, NeedsRaysOrGenerateButNotBoth) {
  TempDir dir;
  EXPECT_NE(run_sim(dir, std::string("trace --scene ") + kScene + " --out " + quoted(dir / "x.bin")), 0);
  EXPECT_NE(read_text(dir / "stderr.txt").find("--rays or --generate"), std::string::npos)
      << read_text(dir / "stderr.txt");
  EXPECT_NE(run_sim(dir, std::string("trace --scene ") + kScene + " --generate 5 --rays " +
                             quoted(dir / "r.bin") + " --out " + quoted(dir / "x.bin")),
            0);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.bin"));
}

}  // namespace
}  // namespace strata::sim
