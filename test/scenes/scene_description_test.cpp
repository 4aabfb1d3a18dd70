// Scene description (JSON) tests: defaults, every field, and the error messages.
#include "scenes/scene_description.h"
#include "loader_fixtures.h"

#include <gtest/gtest.h>

namespace strata::scenes {
namespace {

namespace fs = std::filesystem;
using fixtures::contains;
using fixtures::expect_scene_error;
using fixtures::GltfBuilder;
using fixtures::TempDir;
using fixtures::write_text;

const char* kTriObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST(SceneDescription, OnlyGeometryGivesSceneHDefaults) {
  TempDir dir;
  write_text(dir / "tri.obj", kTriObj);
  const fs::path json = write_text(dir / "scene.json", R"({"geometry": ["tri.obj"]})");
  const Scene s = load_scene_description(json);
  EXPECT_EQ(s.name, json.string());
  ASSERT_EQ(s.triangles.size(), 1u);
  const Camera cam;
  EXPECT_EQ(s.camera.eye, cam.eye);
  EXPECT_EQ(s.camera.target, cam.target);
  EXPECT_EQ(s.camera.up, cam.up);
  EXPECT_EQ(s.camera.vfov_degrees, cam.vfov_degrees);
  const PointLight light;
  EXPECT_EQ(s.light.position, light.position);
  EXPECT_EQ(s.light.intensity, light.intensity);
  EXPECT_EQ(s.background, glm::vec3(0.0f));
}

TEST(SceneDescription, AllFieldsAndSeveralGeometryFiles) {
  TempDir dir;
  fs::create_directories(dir / "meshes");
  write_text(dir / "meshes" / "tri.obj", kTriObj);
  GltfBuilder g;
  const std::vector<glm::vec3> tri = {{0, 0, 5}, {1, 0, 5}, {0, 1, 5}};
  g.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", g.add_positions(tri)}}}}}}}};
  g.doc["nodes"] = nlohmann::json::array({{{"mesh", 0}}});
  const fs::path gltf = write_text(dir / "other.GLTF", g.gltf());  // extension case ignored
  const fs::path json = write_text(dir / "scene.json", R"({
    "geometry": ["meshes/tri.obj", ")" + gltf.string() + R"("],
    "camera": {"eye": [1, 2, 3], "target": [0, 0.5, 0], "up": [0, 0, 1], "vfov_degrees": 60},
    "light": {"position": [4, 5, 6], "intensity": 150},
    "background": [0.1, 0.2, 0.3]
  })");
  const Scene s = load_scene_description(json);
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.triangles[1].v0, glm::vec3(0, 0, 5));
  EXPECT_EQ(s.camera.eye, glm::vec3(1, 2, 3));
  EXPECT_EQ(s.camera.target, glm::vec3(0, 0.5f, 0));
  EXPECT_EQ(s.camera.up, glm::vec3(0, 0, 1));
  EXPECT_EQ(s.camera.vfov_degrees, 60.0f);
  EXPECT_EQ(s.light.position, glm::vec3(4, 5, 6));
  EXPECT_EQ(s.light.intensity, glm::vec3(150.0f));
  EXPECT_EQ(s.background, glm::vec3(0.1f, 0.2f, 0.3f));
}

TEST(SceneDescription, IntensityAsRgbArray) {
  TempDir dir;
  write_text(dir / "tri.obj", kTriObj);
  const Scene s = load_scene_description(write_text(
      dir / "scene.json", R"({"geometry": ["tri.obj"], "light": {"intensity": [1, 2, 3]}})"));
  EXPECT_EQ(s.light.intensity, glm::vec3(1, 2, 3));
}

TEST(SceneDescription, UnknownKeysAreErrors) {
  TempDir dir;
  write_text(dir / "tri.obj", kTriObj);
  expect_scene_error(
      [&] {
        load_scene_description(
            write_text(dir / "scene.json", R"({"geometry": ["tri.obj"], "lights": {}})"));
      },
      {"scene.json: lights: unknown key"});
  expect_scene_error(
      [&] {
        load_scene_description(
            write_text(dir / "scene.json", R"({"geometry": ["tri.obj"], "camera": {"fov": 40}})"));
      },
      {"scene.json: camera.fov: unknown key"});
}

TEST(SceneDescription, WrongTypesAndValuesNameTheField) {
  TempDir dir;
  write_text(dir / "tri.obj", kTriObj);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("camera": {"eye": [1, 2]})", "scene.json: camera.eye: expected an array of 3 numbers"},
      {R"("camera": {"eye": "here"})", "scene.json: camera.eye: expected an array of 3 numbers"},
      {R"("camera": {"target": [0, 0, "x"]})", "camera.target: expected an array of 3 numbers"},
      {R"("camera": {"up": [0, 1e300, 0]})", "camera.up: expected a finite number"},
      {R"("camera": {"vfov_degrees": 180})", "camera.vfov_degrees: expected a number in (0, 180)"},
      {R"("camera": {"vfov_degrees": 0})", "camera.vfov_degrees"},
      {R"("camera": {"vfov_degrees": "45"})", "camera.vfov_degrees: expected a number"},
      {R"("camera": {"eye": [1, 1, 1], "target": [1, 1, 1]})", "camera: eye and target coincide"},
      {R"("camera": {"eye": [0, 5, 0]})", "camera.up: zero or parallel"},
      {R"("camera": [1, 2, 3])", "scene.json: camera: expected an object"},
      {R"("light": {"intensity": -1})", "light.intensity: expected values >= 0"},
      {R"("light": {"intensity": "bright"})", "light.intensity: expected a number or an array"},
      {R"("light": {"position": [1, 2, 3, 4]})", "light.position: expected an array of 3"},
      {R"("background": 0.5)", "background: expected an array of 3 numbers"},
  };
  for (const auto& [field, message] : cases) {
    SCOPED_TRACE(field);
    const fs::path json =
        write_text(dir / "scene.json", R"({"geometry": ["tri.obj"], )" + field + "}");
    expect_scene_error([&] { load_scene_description(json); }, {message});
  }
}

TEST(SceneDescription, BadGeometryListsAreErrors) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({})", "scene.json: geometry: missing"},
      {R"({"geometry": "tri.obj"})", "scene.json: geometry: expected a non-empty array"},
      {R"({"geometry": []})", "scene.json: geometry: expected a non-empty array"},
      {R"({"geometry": [3]})", "scene.json: geometry[0]: expected a string"},
      {R"([1, 2])", "scene.json: top level: expected an object"},
  };
  for (const auto& [text, message] : cases) {
    SCOPED_TRACE(text);
    const fs::path json = write_text(dir / "scene.json", text);
    expect_scene_error([&] { load_scene_description(json); }, {message});
  }
}

TEST(SceneDescription, FileErrors) {
  TempDir dir;
  expect_scene_error([&] { load_scene_description(dir / "absent.json"); },
                     {"absent.json", "not found"});
  expect_scene_error(
      [&] { load_scene_description(write_text(dir / "broken.json", R"({"geometry": [)")); },
      {"broken.json: not valid JSON at line 1, column 15"});
  expect_scene_error(
      [&] {
        load_scene_description(write_text(dir / "ply.json", R"({"geometry": ["mesh.ply"]})"));
      },
      {"mesh.ply", "unsupported geometry extension '.ply'"});
  expect_scene_error(
      [&] {
        load_scene_description(write_text(dir / "gone.json", R"({"geometry": ["gone.obj"]})"));
      },
      {"gone.obj", "not found"});
}

// Issue 39: as for a chip config, a repeated key (the last silently won) and nesting without
// limit are refused, naming the file.
TEST(SceneDescription, ADuplicateKeyOrDeepNestingIsRefusedNamingTheFile) {
  TempDir dir;
  const fs::path dup = write_text(
      dir / "dup.json", R"({"geometry": ["a.obj"], "camera": {"eye": [0, 0, 5], "eye": [0, 0, 9]}})");
  expect_scene_error([&] { load_scene_description(dup); }, {dup.string() + ": duplicate key 'camera.eye'"});
  const fs::path deep = write_text(dir / "deep.json", "{\"geometry\": " + std::string(100000, '[') +
                                                           std::string(100000, ']') + "}");
  expect_scene_error([&] { load_scene_description(deep); }, {deep.string() + ": nested deeper than 64 levels"});
}

TEST(SceneDescription, OnlyDegenerateGeometryMeansNoTriangles) {
  TempDir dir;
  write_text(dir / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  expect_scene_error(
      [&] {
        load_scene_description(write_text(dir / "flat.json", R"({"geometry": ["flat.obj"]})"));
      },
      {"flat.json: scene has no triangles"});
}

TEST(SceneDescription, SibenikJsonLoads) {
  if (!fs::exists(STRATA_SHARED_DIR "/scenes/sibenik/sibenik.obj")) {
    GTEST_SKIP() << "Sibenik not present in " STRATA_SHARED_DIR;
  }
  const Scene s = load_scene_description(STRATA_SOURCE_DIR "/scenes/data/sibenik.json");
  EXPECT_EQ(s.triangles.size() + s.dropped_degenerate, 73564u);
  EXPECT_EQ(s.camera.eye, glm::vec3(-10, -12, 0));
  EXPECT_EQ(s.camera.target, glm::vec3(0, -11.5f, 0));
  EXPECT_EQ(s.light.position, glm::vec3(0, -2, 0));
  EXPECT_EQ(s.background, glm::vec3(0.0f));
  // The camera and the light are inside the cathedral.
  const Bounds b = s.bounds();
  for (const glm::vec3& p : {s.camera.eye, s.light.position}) {
    EXPECT_TRUE(p.x > b.min.x && p.y > b.min.y && p.z > b.min.z);
    EXPECT_TRUE(p.x < b.max.x && p.y < b.max.y && p.z < b.max.z);
  }
}

}  // namespace
}  // namespace strata::scenes
