// OBJ loader tests. Fixtures are written into a fresh temporary directory per test.
#include "scenes/load_obj.h"
#include "scenes/scene_spec.h"
#include "scenes/validate.h"
#include "loader_fixtures.h"

#include <sys/stat.h>

#include <algorithm>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>


namespace strata::scenes {
namespace {

using fixtures::sorted_coords;
using fixtures::TempDir;
using fixtures::write_text;
namespace fs = std::filesystem;
using fixtures::any_warning_contains;
using fixtures::contains;
using fixtures::expect_scene_error;

float area(const Triangle& t) { return 0.5f * glm::length(glm::cross(t.v1 - t.v0, t.v2 - t.v0)); }

const char* kQuad =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

TEST(LoaderObj, QuadIsTriangulatedIntoTwoTriangles) {
  TempDir dir;
  const auto file = write_text(dir / "quad.obj", std::string(kQuad) + "f 1 2 3 4\n");
  Scene s;
  load_obj(s, file);
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_FLOAT_EQ(area(s.triangles[0]), 0.5f);
  EXPECT_FLOAT_EQ(area(s.triangles[1]), 0.5f);
  // Together the two triangles use all four corners, each triangle three distinct ones.
  const Bounds b = s.bounds();
  EXPECT_EQ(b.min, glm::vec3(0, 0, 0));
  EXPECT_EQ(b.max, glm::vec3(1, 1, 0));
  EXPECT_EQ(s.dropped_degenerate, 0u);
  EXPECT_TRUE(s.warnings.empty());
  // No mtllib and no usemtl: one grey default material.
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].albedo, glm::vec3(0.8f));
  EXPECT_EQ(s.triangles[0].material, 0u);
}

TEST(LoaderObj, PentagonAndTriangleGiveFourTriangles) {
  TempDir dir;
  const auto file = write_text(dir / "poly.obj",
                               "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\n"
                               "f 1 2 3 4 5\n"
                               "f -5 -4 -3\n");  // relative indices: vertices 1 2 3
  Scene s;
  load_obj(s, file);
  ASSERT_EQ(s.triangles.size(), 4u);
  float total = 0;
  for (size_t i = 0; i < 3; ++i) total += area(s.triangles[i]);
  EXPECT_FLOAT_EQ(total, 5.0f);  // shoelace area of the pentagon
  EXPECT_EQ(sorted_coords({s.triangles[3]}),
            sorted_coords({Triangle{{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, 0}}));
}

TEST(LoaderObj, MtlDiffuseColourIsAlbedo) {
  TempDir dir;
  write_text(dir / "colors.mtl",
             "newmtl red\nKd 1 0 0\n"
             "newmtl blue\nKd 0.1 0.2 0.7\n");
  const auto file = write_text(dir / "colored.obj", std::string("mtllib colors.mtl\n") + kQuad +
                                                        "f 1 2 3\n"  // before any usemtl
                                                        "usemtl blue\nf 1 3 4\n"
                                                        "usemtl red\nf 1 2 4\n");
  Scene s;
  load_obj(s, file);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  ASSERT_EQ(s.triangles.size(), 3u);
  auto mat = [&](size_t i) { return s.materials.at(s.triangles[i].material); };
  EXPECT_EQ(mat(0).name, "default");
  EXPECT_EQ(mat(0).albedo, glm::vec3(0.8f));
  EXPECT_EQ(mat(1).name, "blue");
  EXPECT_EQ(mat(1).albedo, glm::vec3(0.1f, 0.2f, 0.7f));
  EXPECT_EQ(mat(2).name, "red");
  EXPECT_EQ(mat(2).albedo, glm::vec3(1, 0, 0));
  EXPECT_EQ(s.triangles[1].v2, glm::vec3(0, 1, 0));
}

TEST(LoaderObj, SecondFileAppendsWithShiftedMaterialIndices) {
  TempDir dir;
  write_text(dir / "c.mtl", "newmtl green\nKd 0 1 0\n");
  const auto file =
      write_text(dir / "g.obj", std::string("mtllib c.mtl\n") + kQuad + "usemtl green\nf 1 2 3\n");
  Scene s;
  load_obj(s, file);
  load_obj(s, file);
  ASSERT_EQ(s.triangles.size(), 2u);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.triangles[0].material, 0u);
  EXPECT_EQ(s.triangles[1].material, 1u);
  EXPECT_EQ(s.materials[1].albedo, glm::vec3(0, 1, 0));
}

TEST(LoaderObj, MissingMtlWarnsAndUsesDefaultMaterial) {
  TempDir dir;
  const auto file = write_text(dir / "nomtl.obj", std::string("mtllib missing.mtl\n") + kQuad +
                                                      "usemtl stone\nf 1 2 3\nf 1 3 4\n");
  Scene s;
  load_obj(s, file);
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_TRUE(any_warning_contains(s, "missing.mtl"));
  EXPECT_TRUE(any_warning_contains(s, "stone"));
  for (const std::string& w : s.warnings) EXPECT_TRUE(contains(w, "nomtl.obj"));
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].albedo, glm::vec3(0.8f));
  EXPECT_EQ(s.triangles[1].material, 0u);
}

TEST(LoaderObj, TruncatedFileReferencingMissingVertexThrows) {
  TempDir dir;
  // The vertex list was cut after three vertices; the second face needs vertex 4.
  const auto file = write_text(dir / "cut.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 1 3 4\n");
  Scene s;
  expect_scene_error([&] { load_obj(s, file); }, {"cut.obj"});
  EXPECT_TRUE(s.triangles.empty()) << "a failed load must not leave partial geometry";
  EXPECT_TRUE(s.materials.empty());
}

TEST(LoaderObj, TruncatedQuadReferencingMissingVertexThrows) {
  TempDir dir;
  // tinyobjloader silently skips such a quad; we must not.
  const auto file = write_text(dir / "cutquad.obj", std::string(kQuad) + "f 1 2 3 9\n");
  Scene s;
  expect_scene_error([&] { load_obj(s, file); }, {"cutquad.obj"});
}

TEST(LoaderObj, RelativeIndexBeforeFirstVertexThrows) {
  TempDir dir;
  const auto file = write_text(dir / "rel.obj", std::string(kQuad) + "f -1 -2 -7\n");
  Scene s;
  expect_scene_error([&] { load_obj(s, file); }, {"rel.obj", "vertex"});
}

TEST(LoaderObj, FaceWithTwoVerticesWarnsAndKeepsTheRest) {
  TempDir dir;
  const auto file = write_text(dir / "short.obj", std::string(kQuad) + "f 1 2 3\nf 1 2");
  Scene s;
  load_obj(s, file);
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_TRUE(any_warning_contains(s, "Degenerated face")) << ::testing::PrintToString(s.warnings);
  EXPECT_TRUE(any_warning_contains(s, "truncated"));
}

// Whatever byte a file is cut at, loading either fails with SceneError or succeeds with
// a warning about the missing final newline; it never crashes or reads out of bounds.
TEST(LoaderObj, EveryTruncationFailsOrWarns) {
  TempDir dir;
  const std::string text = std::string(kQuad) + "f 1 2 3\nf 1 3 4\nv 2 2 2\nf -1 -2 -3 -4\n";
  for (size_t n = 1; n < text.size(); ++n) {
    Scene s;
    try {
      load_obj(s, write_text(dir / "t.obj", text.substr(0, n)));
      if (text[n - 1] != '\n') {
        EXPECT_TRUE(any_warning_contains(s, "truncated")) << n;
      }
    } catch (const SceneError& e) {
      EXPECT_TRUE(contains(e.what(), "t.obj")) << n;
    }
  }
}

TEST(LoaderObj, ZeroIndexIsAParseError) {
  TempDir dir;
  const auto file = write_text(dir / "zero.obj", std::string(kQuad) + "f 0 1 2\n");
  Scene s;
  expect_scene_error([&] { load_obj(s, file); }, {"zero.obj", "parse error"});
}

// tinyobjloader reads these as zeros; each must be an error that names the file and line.
TEST(LoaderObj, NonFiniteOrMissingCoordinatesAreErrorsNamingTheLine) {
  TempDir dir;
  const struct {
    const char* line;
    const char* why;
  } cases[] = {{"v nan 0 0", "'nan' is not a finite number"},
               {"v 0 inf 0", "'inf' is not a finite number"},
               {"v 0 0 -infinity", "'-infinity' is not a finite number"},
               {"v a b c", "'a' is not a finite number"},
               {"v 1 2", "vertex has 2 coordinates, needs 3"},
               {"v 1e39 0 0", "'1e39' is not a finite number"},
               {"v 1 2 3 0.5 x 0.5", "vertex value 'x'"}};
  for (const auto& c : cases) {
    const auto file = write_text(dir / "bad.obj", std::string(kQuad) + c.line + "\nf 1 2 3\n");
    Scene s;
    expect_scene_error([&] { load_obj(s, file); }, {"bad.obj:5: parse error", c.why});
    EXPECT_TRUE(s.triangles.empty()) << c.line;
  }
}

TEST(LoaderObj, IndicesBeyondTheVerticesAreErrorsNotWrappedOntoRealOnes) {
  TempDir dir;
  // 4294967299 = 2^32 + 3: tinyobjloader's 32-bit parse made it vertex 3.
  for (const char* face : {"f 1 2 4294967299", "f 1 2 99999999999999999999999", "f 1 2 5/1", "f 1 2 x"}) {
    const auto file = write_text(dir / "far.obj", std::string(kQuad) + face + "\n");
    Scene s;
    expect_scene_error([&] { load_obj(s, file); }, {"far.obj:5: parse error", "index"});
  }
}

TEST(LoaderObj, ScientificNotationColoursAndForwardIndicesStillLoad) {
  TempDir dir;
  const auto file = write_text(dir / "ok.obj",
                               "f 1 2 3\n"  // a face before its vertices: legal, if rare
                               "v 0 0 0 1 0 0\nv 1e0 0 0 0 1 0\nv 0 1.0E+0 -0 0 0 1\n");
  Scene s;
  load_obj(s, file);
  EXPECT_EQ(s.triangles.size(), 1u);
}

// A ring-shaped 8-gon (a square with a notch) is concave: a fan would cover its notch.
TEST(LoaderObj, AConcavePolygonIsRefusedAndAConvexOneLoads) {
  TempDir dir;
  const std::string notch =
      "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 3 4 0\nv 3 1 0\nv 1 1 0\nv 1 4 0\nv 0 4 0\nf 1 2 3 4 5 6 7 8\n";
  Scene bad;
  expect_scene_error([&] { load_obj(bad, write_text(dir / "notch.obj", notch)); },
                     {"notch.obj:9: parse error: a concave polygon of 8 vertices"});
  // A convex hexagon, with one collinear corner, in a tilted plane: loads as 4 triangles.
  const std::string hexagon =
      "v 0 0 0\nv 2 0 1\nv 4 0 2\nv 5 2 2.5\nv 4 4 2\nv 0 4 0\nf 1 2 3 4 5 6\n";
  Scene ok;
  load_obj(ok, write_text(dir / "hexagon.obj", hexagon));
  EXPECT_EQ(ok.triangles.size() + ok.dropped_degenerate, 4u);
}

TEST(LoaderObj, OnlyDegenerateTrianglesAreDroppedThenRequireTrianglesFails) {
  TempDir dir;
  const auto file = write_text(dir / "flat.obj",
                               "v 0 0 0\nv 1 0 0\nv 2 0 0\n"
                               "f 1 2 3\n"    // collinear
                               "f 1 1 2\n");  // repeated vertex
  Scene s;
  load_obj(s, file);
  EXPECT_TRUE(s.triangles.empty());
  EXPECT_EQ(s.dropped_degenerate, 2u);
  EXPECT_TRUE(any_warning_contains(s, "flat.obj: dropped 2 zero-area"));
  expect_scene_error([&] { require_triangles(s, file.string()); },
                     {"flat.obj", "scene has no triangles"});
}

TEST(LoaderObj, MissingFileThrows) {
  TempDir dir;
  Scene s;
  expect_scene_error([&] { load_obj(s, dir / "nope.obj"); }, {"nope.obj", "not found"});
}

// Issue 39: a FIFO or a folder given as geometry was reported as "file not found".
TEST(LoaderObj, AFifoOrAFolderIsNotARegularFileRatherThanMissing) {
  TempDir dir;
  ASSERT_EQ(mkfifo((dir / "pipe.obj").c_str(), 0644), 0);
  fs::create_directory(dir / "folder.obj");
  for (const char* name : {"pipe.obj", "folder.obj"}) {
    Scene s;
    expect_scene_error([&] { load_obj(s, dir / name); },
                       {(dir / name).string() + ": not a regular file"});
  }
  // The same through a scene description and a bare spec, and for glTF.
  write_text(dir / "scene.json", R"({"geometry": ["folder.obj"]})");
  expect_scene_error([&] { load_scene((dir / "scene.json").string(), dir.path()); },
                     {(dir / "folder.obj").string() + ": not a regular file"});
  expect_scene_error([&] { load_scene((dir / "pipe.obj").string(), dir.path()); }, {"pipe.obj: not a regular file"});
  ASSERT_EQ(mkfifo((dir / "pipe.gltf").c_str(), 0644), 0);
  expect_scene_error([&] { load_scene((dir / "pipe.gltf").string(), dir.path()); }, {"pipe.gltf: not a regular file"});
}

// Issue 39: finite coordinates of 1e38 made the framing camera infinite, reported as
// "camera_eye is not finite" by the scene image, naming neither the file nor the cause.
TEST(LoaderObj, BoundsTooLargeForTheCameraNameTheFileAndTheBounds) {
  TempDir dir;
  const auto file = write_text(dir / "huge.obj", "v -1e38 0 0\nv 1e38 0 0\nv 0 1e38 0\nf 1 2 3\n");
  expect_scene_error([&] { load_scene(file.string(), dir.path()); },
                     {file.string() + ": scene bounds are too large for the camera", "1e+38"});
  // Large but representable bounds still frame.
  const auto big = write_text(dir / "big.obj", "v -1e15 0 0\nv 1e15 0 0\nv 0 1e15 0\nf 1 2 3\n");
  EXPECT_EQ(load_scene(big.string(), dir.path()).triangles.size(), 1u);
}

// Issue 39: `Kd nan` gave a black material without a word; a non-finite material value is an
// error naming the .mtl, the line, the material and the field, as a NaN vertex is.
TEST(LoaderObj, ANonFiniteMtlValueIsAnErrorNamingFileLineAndField) {
  TempDir dir;
  const struct {
    const char* line;
    const char* why;
  } cases[] = {{"Kd nan 0.5 0.5", "material 'red': Kd value 'nan' is not a finite number"},
               {"Kd 0.5 inf 0.5", "Kd value 'inf'"},
               {"Ks 1e39 0 0", "Ks value '1e39'"},
               {"Ns -nan", "Ns value '-nan'"},
               {"d NaN", "d value 'NaN'"}};
  for (const auto& c : cases) {
    write_text(dir / "m.mtl", std::string("# colours\nnewmtl red\n") + c.line + "\n");
    const auto file = write_text(dir / "m.obj", std::string("mtllib m.mtl\n") + kQuad + "usemtl red\nf 1 2 3\n");
    Scene s;
    expect_scene_error([&] { load_obj(s, file); }, {(dir / "m.mtl").string() + ":3: ", c.why});
    EXPECT_TRUE(s.triangles.empty()) << c.line;
  }
  // Words where numbers may stand (a spectral curve) are left to tinyobjloader as before.
  write_text(dir / "m.mtl", "newmtl red\nKd 1 0 0\nKa spectral red.rfl\n");
  Scene s;
  load_obj(s, write_text(dir / "m.obj", std::string("mtllib m.mtl\n") + kQuad + "usemtl red\nf 1 2 3\n"));
  EXPECT_EQ(s.materials.at(0).albedo, glm::vec3(1, 0, 0));
}

TEST(LoaderObj, Sibenik) {
  const fs::path file = STRATA_SHARED_DIR "/scenes/sibenik/sibenik.obj";
  if (!fs::exists(file)) GTEST_SKIP() << file << " not present";
  Scene s;
  load_obj(s, file);  // its load time is measured by scripts/bench-scenes, never asserted here
  // Every face line of the file is a triangle; zero-area ones are dropped.
  EXPECT_EQ(s.triangles.size() + s.dropped_degenerate, 73564u);
  EXPECT_EQ(s.dropped_degenerate, 8u);  // all exactly collinear, measured
  const Bounds b = s.bounds();
  EXPECT_NEAR(b.min.x, -20.1f, 0.1f);
  EXPECT_NEAR(b.min.y, -15.3f, 0.1f);
  EXPECT_NEAR(b.min.z, -8.5f, 0.1f);
  EXPECT_NEAR(b.max.x, 20.1f, 0.1f);
  EXPECT_NEAR(b.max.y, 15.3f, 0.1f);
  EXPECT_NEAR(b.max.z, 8.5f, 0.1f);
  // Its material library (untitled.mtl, 15 materials) loads: the stone's Kd, not the default grey.
  EXPECT_FALSE(any_warning_contains(s, "untitled.mtl"));
  EXPECT_GE(s.materials.size(), 14u);
  const auto stone = std::find_if(s.materials.begin(), s.materials.end(),
                                  [](const Material& m) { return m.name == "kamen_zid"; });
  ASSERT_NE(stone, s.materials.end());
  EXPECT_NEAR(stone->albedo.x, 0.734118f, 1e-6f);
  EXPECT_NEAR(stone->albedo.z, 0.674118f, 1e-6f);
  // tinyobjloader's note on materials with both d and Tr is noise here: filtered out.
  EXPECT_FALSE(any_warning_contains(s, "Tr"));
  for (const Triangle& t : s.triangles) ASSERT_LT(t.material, s.materials.size());
}

}  // namespace
}  // namespace strata::scenes
