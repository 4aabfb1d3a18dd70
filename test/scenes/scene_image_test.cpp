// Scene image: determinism, file round trips, and the on-disk cache refusing truncated,
// corrupt and stale files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <cstddef>
#include <unistd.h>

#include "scenes/procedural/procedural.h"
#include "scenes/scene_cache.h"
#include "scenes/scene_image.h"

namespace strata::scenes {
namespace {

namespace fs = std::filesystem;

class SceneImageFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("strata-image-test-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::vector<uint64_t> read_words(const fs::path& f) {
  std::ifstream in(f, std::ios::binary | std::ios::ate);
  std::vector<uint64_t> w(size_t(in.tellg()) / 8);
  in.seekg(0);
  in.read(reinterpret_cast<char*>(w.data()), std::streamsize(w.size() * 8));
  return w;
}

void patch_byte(const fs::path& f, uint64_t offset) {
  std::fstream io(f, std::ios::binary | std::ios::in | std::ios::out);
  io.seekg(std::streamoff(offset));
  char c = 0;
  io.read(&c, 1);
  c = char(c ^ 0x5a);
  io.seekp(std::streamoff(offset));
  io.write(&c, 1);
}

TEST(SceneImage, BuildIsDeterministicAndHeaderIsFilled) {
  const Scene s = make_cornell({0.3, 1});
  const SceneImage a = build_scene_image(s, {}, nullptr);
  const SceneImage b = build_scene_image(s, {}, nullptr);
  EXPECT_EQ(a.words(), b.words());
  const SceneImageHeader& h = a.header();
  EXPECT_EQ(h.magic, kSceneImageMagic);
  EXPECT_EQ(h.version, kSceneImageVersion);
  EXPECT_EQ(h.triangle_count, s.triangles.size());
  EXPECT_EQ(h.material_count, s.materials.size());
  EXPECT_EQ(h.camera_eye[0], s.camera.eye.x);
  EXPECT_EQ(h.light_position[1], s.light.position.y);
  EXPECT_EQ(a.material(1).albedo[0], s.materials[1].albedo.x);
}

TEST_F(SceneImageFiles, WriteThenReadGivesTheSameBytes) {
  const SceneImage a = build_scene_image(make_cornell({0.3, 1}), {}, nullptr);
  write_scene_image(a, dir_ / "x.strs");
  const SceneImage b = read_scene_image(dir_ / "x.strs");
  EXPECT_EQ(a.words(), b.words());
}

TEST_F(SceneImageFiles, ReadRejectsTruncatedCorruptAndForeignFiles) {
  const SceneImage a = build_scene_image(make_cornell({0.3, 1}), {}, nullptr);
  const fs::path f = dir_ / "x.strs";
  write_scene_image(a, f);
  fs::resize_file(f, a.size_bytes() - 4096);
  EXPECT_THROW(read_scene_image(f), SceneError);
  write_scene_image(a, f);
  patch_byte(f, a.size_bytes() - 100);
  try {
    read_scene_image(f);
    FAIL() << "corrupt image accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("x.strs"), std::string::npos) << e.what();
  }
  std::ofstream(dir_ / "junk.strs") << "not an image at all, just some text....";
  EXPECT_THROW(read_scene_image(dir_ / "junk.strs"), SceneError);
  EXPECT_THROW(read_scene_image(dir_ / "missing.strs"), SceneError);
}

TEST_F(SceneImageFiles, CacheSkipsTheSecondBuild) {
  const Scene s = make_hairball({0.01, 1});
  SceneBuildReport first, second;
  const SceneImage a = load_or_build_scene_image(s, {}, dir_, &first);
  const SceneImage b = load_or_build_scene_image(s, {}, dir_, &second);
  EXPECT_FALSE(first.from_cache);
  EXPECT_TRUE(second.from_cache) << second.cache_note;
  EXPECT_EQ(a.words(), b.words());
  // Other parameters or other content get another key, hence a build of their own.
  SceneImageParams other;
  other.treelet_bytes = 4096;
  SceneBuildReport third;
  load_or_build_scene_image(s, other, dir_, &third);
  EXPECT_FALSE(third.from_cache);
  SceneBuildReport fourth;
  load_or_build_scene_image(make_hairball({0.01, 2}), {}, dir_, &fourth);
  EXPECT_FALSE(fourth.from_cache);
}

TEST_F(SceneImageFiles, CacheRebuildsTruncatedCorruptAndStaleFiles) {
  const Scene s = make_cornell({0.3, 1});
  const SceneImageParams params;
  const SceneImage good = load_or_build_scene_image(s, params, dir_, nullptr);
  const fs::path f = cache_file_for(dir_, scene_content_key(s, params));
  ASSERT_TRUE(fs::exists(f));

  auto reload = [&](const char* what) {
    SceneBuildReport r;
    const SceneImage img = load_or_build_scene_image(s, params, dir_, &r);
    EXPECT_FALSE(r.from_cache) << what << ": " << r.cache_note;
    EXPECT_EQ(img.words(), good.words()) << what;
    // The rebuilt file replaced the bad one.
    EXPECT_EQ(read_words(f), good.words()) << what;
    return r.cache_note;
  };

  fs::resize_file(f, fs::file_size(f) / 2);
  EXPECT_NE(reload("truncated").find("rejected"), std::string::npos);
  patch_byte(f, good.header().node_offset + 7);
  EXPECT_NE(reload("corrupt").find("checksum"), std::string::npos);
  patch_byte(f, offsetof(SceneImageHeader, version));
  EXPECT_NE(reload("old version").find("version"), std::string::npos);
  // A valid image of other content under this key (e.g. a renamed file) is stale.
  write_scene_image(build_scene_image(make_cornell({0.2, 1}), params, nullptr), f);
  EXPECT_NE(reload("stale").find("stale"), std::string::npos);
}

// The checksum covers the header: a changed camera float (byte 124 was the repro) is caught.
TEST_F(SceneImageFiles, AChangedHeaderFieldFailsTheChecksum) {
  const SceneImage good = build_scene_image(make_cornell({0.3, 1}), {}, nullptr);
  for (const size_t offset : {offsetof(SceneImageHeader, camera_eye) + 4, offsetof(SceneImageHeader, root_node),
                              offsetof(SceneImageHeader, background), offsetof(SceneImageHeader, light_intensity),
                              offsetof(SceneImageHeader, bvh_depth)}) {
    std::vector<uint64_t> words = good.words();
    reinterpret_cast<uint8_t*>(words.data())[offset] ^= 0x40;
    try {
      SceneImage bad(std::move(words), "patched.strs");
      ADD_FAILURE() << "accepted a header changed at byte " << offset;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("patched.strs: invalid scene image: checksum mismatch"), std::string::npos)
          << offset << ": " << e.what();
    }
  }
}

// A writer that wrote nonsense and a right checksum over it: the values are checked too.
TEST_F(SceneImageFiles, HeaderValuesOutOfRangeAreRefusedEvenWithAValidChecksum) {
  const SceneImage good = build_scene_image(make_cornell({0.3, 1}), {}, nullptr);
  const struct {
    void (*patch)(SceneImageHeader&);
    const char* expected;
  } cases[] = {
      {[](SceneImageHeader& h) { h.bvh_depth = 40; }, "bvh_depth 40 exceeds 32"},
      {[](SceneImageHeader& h) { h.triangle_count = h.triangle_bytes; }, "does not fit the triangle section"},
      {[](SceneImageHeader& h) { h.triangle_count = 0; }, "triangle_count 0"},
      {[](SceneImageHeader& h) { h.background[1] = std::nanf(""); }, "background is not finite"},
      {[](SceneImageHeader& h) { h.camera_vfov_degrees = 180.0f; }, "camera_vfov_degrees outside (0, 180)"},
      {[](SceneImageHeader& h) { h.light_intensity[0] = -1.0f; }, "light_intensity is negative"},
      {[](SceneImageHeader& h) { h.node_count = h.node_slots + 1; }, "node_count"},
      {[](SceneImageHeader& h) { h.max_leaf_triangles = 16; }, "max_leaf_triangles 16"},
  };
  for (const auto& c : cases) {
    std::vector<uint64_t> words = good.words();
    auto& h = *reinterpret_cast<SceneImageHeader*>(words.data());
    c.patch(h);
    h.payload_checksum = scene_image_checksum(reinterpret_cast<const uint8_t*>(words.data()), words.size() * 8);
    try {
      SceneImage bad(std::move(words), "written.strs");
      ADD_FAILURE() << "accepted: " << c.expected;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace strata::scenes
