// glTF loader tests. Each test builds its document with GltfBuilder and writes it as
// .gltf (base64 data URI) and/or .glb into a fresh temporary directory.
#include "scenes/load_gltf.h"
#include "scenes/validate.h"
#include "loader_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace strata::scenes {
namespace {

namespace fs = std::filesystem;
using fixtures::any_warning_contains;
using fixtures::contains;
using fixtures::expect_scene_error;
using fixtures::GltfBuilder;
using fixtures::sorted_coords;
using fixtures::TempDir;
using fixtures::write_bytes;
using fixtures::write_text;
using nlohmann::json;

const std::vector<glm::vec3> kTri = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}};

// Adds a mesh with one indexed triangle primitive and returns its index.
int add_mesh(GltfBuilder& g, const std::vector<glm::vec3>& positions,
             const std::vector<uint32_t>& indices, int material = -1) {
  json prim = {{"attributes", {{"POSITION", g.add_positions(positions)}}},
               {"indices", g.add_indices(indices)}};
  if (material >= 0) prim["material"] = material;
  g.doc["meshes"].push_back({{"primitives", {prim}}});
  return static_cast<int>(g.doc["meshes"].size()) - 1;
}

Scene load_gltf_text(const TempDir& dir, const std::string& name, const std::string& text) {
  Scene s;
  load_gltf(s, write_text(dir / name, text));
  return s;
}

// parent: translation (10,20,30) -> child: rotation 180 deg about z, scale (2,3,4), mesh.
// The 180-degree quaternion [0,0,1,0] makes every value exact, and would turn into a
// rotation about y if [x,y,z,w] were read in glm's (w,x,y,z) order.
GltfBuilder hierarchy() {
  GltfBuilder g;
  const int mesh = add_mesh(g, kTri, {0, 1, 2});
  g.doc["nodes"] = json::array({
      {{"translation", {10, 20, 30}}, {"children", {1}}},
      {{"rotation", {0, 0, 1, 0}}, {"scale", {2, 3, 4}}, {"mesh", mesh}},
  });
  g.doc["scenes"] = json::array({{{"nodes", {0}}}});
  g.doc["scene"] = 0;
  return g;
}

TEST(LoaderGltf, NodeHierarchyGivesExactWorldPositions) {
  TempDir dir;
  const Scene s = load_gltf_text(dir, "h.gltf", hierarchy().gltf());
  ASSERT_EQ(s.triangles.size(), 1u);
  // p -> scale -> rotate (x,y -> -x,-y) -> translate
  EXPECT_EQ(s.triangles[0].v0, glm::vec3(8, 20, 30));
  EXPECT_EQ(s.triangles[0].v1, glm::vec3(10, 14, 30));
  EXPECT_EQ(s.triangles[0].v2, glm::vec3(10, 20, 42));
  EXPECT_TRUE(s.warnings.empty());
}

TEST(LoaderGltf, QuarterTurnTrsAndMatrixNodes) {
  TempDir dir;
  GltfBuilder g;
  const int mesh = add_mesh(g, kTri, {0, 1, 2});
  const double h = std::sqrt(0.5);
  g.doc["nodes"] = json::array({
      // T * R * S with R = 90 deg about x, (x,y,z) -> (x,-z,y). The rotation does not
      // commute with the non-uniform scale, so a wrong composition order shows.
      {{"translation", {1, 2, 3}},
       {"rotation", {h, 0, 0, h}},
       {"scale", {2, 3, 4}},
       {"mesh", mesh}},
      // Column-major matrix: scale 2 on x, then translate by (100, 0, -1).
      {{"matrix", {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 100, 0, -1, 1}}, {"mesh", mesh}},
  });
  g.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
  const Scene s = load_gltf_text(dir, "q.gltf", g.gltf());
  ASSERT_EQ(s.triangles.size(), 2u);
  const Triangle& r = s.triangles[0];
  // p -> (2x, 3y, 4z) -> (2x, -4z, 3y) -> + (1, 2, 3)
  const glm::vec3 expect[3] = {{3, 2, 3}, {1, 2, 9}, {1, -10, 3}};
  const glm::vec3 got[3] = {r.v0, r.v1, r.v2};
  for (int i = 0; i < 3; ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[i][c], expect[i][c], 1e-5f) << i << "," << c;
  }
  EXPECT_EQ(s.triangles[1].v0, glm::vec3(102, 0, -1));
  EXPECT_EQ(s.triangles[1].v1, glm::vec3(100, 2, -1));
  EXPECT_EQ(s.triangles[1].v2, glm::vec3(100, 0, 2));
}

TEST(LoaderGltf, MeshUsedByTwoNodesIsInstancedTwice) {
  TempDir dir;
  GltfBuilder g;
  const int mesh = add_mesh(g, kTri, {0, 1, 2});
  g.doc["nodes"] = json::array({{{"translation", {5, 0, 0}}, {"mesh", mesh}},
                                {{"translation", {0, 0, -5}}, {"mesh", mesh}}});
  g.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
  const Scene s = load_gltf_text(dir, "inst.gltf", g.gltf());
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(sorted_coords(s.triangles),
            sorted_coords({Triangle{{6, 0, 0}, {5, 2, 0}, {5, 0, 3}, 0},
                           Triangle{{1, 0, -5}, {0, 2, -5}, {0, 0, -2}, 0}}));
}

TEST(LoaderGltf, SeveralMeshesAndPrimitivesIndexedAndNot) {
  TempDir dir;
  GltfBuilder g;
  const std::vector<glm::vec3> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  json mesh0 = {{"primitives",
                 {{{"attributes", {{"POSITION", g.add_positions(quad)}}},
                   {"indices", g.add_indices({0, 1, 2, 0, 2, 3}, 5121)}},      // u8
                  {{"attributes", {{"POSITION", g.add_positions(kTri)}}}}}}};  // non-indexed
  json mesh1 = {{"primitives",
                 {{{"attributes", {{"POSITION", g.add_positions(quad)}}},
                   {"indices", g.add_indices({3, 2, 1}, 5125)}}}}};  // u32
  g.doc["meshes"] = {mesh0, mesh1};
  g.doc["nodes"] = json::array({{{"mesh", 0}}, {{"mesh", 1}, {"translation", {0, 0, 7}}}});
  g.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
  const Scene s = load_gltf_text(dir, "multi.gltf", g.gltf());
  EXPECT_EQ(sorted_coords(s.triangles),
            sorted_coords({Triangle{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, 0},
                           Triangle{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0},
                           Triangle{kTri[0], kTri[1], kTri[2], 0},
                           Triangle{{0, 1, 7}, {1, 1, 7}, {1, 0, 7}, 0}}));
}

TEST(LoaderGltf, NonTrianglePrimitivesAreSkippedWithAWarning) {
  TempDir dir;
  GltfBuilder g;
  const std::vector<glm::vec3> strip = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const int tri = g.add_positions(kTri);
  const int four = g.add_positions(strip);
  g.doc["meshes"] = {{{"primitives",
                       {{{"attributes", {{"POSITION", four}}}, {"mode", 1}},  // LINES
                        {{"attributes", {{"POSITION", four}}}, {"mode", 0}},  // POINTS
                        {{"attributes", {{"POSITION", tri}}}, {"mode", 4}},
                        {{"attributes", {{"POSITION", four}}}, {"mode", 5}},      // strip: 2
                        {{"attributes", {{"POSITION", four}}}, {"mode", 6}}}}}};  // fan: 2
  g.doc["nodes"] = json::array({{{"mesh", 0}}});
  g.doc["scenes"] = json::array({{{"nodes", {0}}}});
  const Scene s = load_gltf_text(dir, "modes.gltf", g.gltf());
  EXPECT_EQ(s.triangles.size(), 5u);
  EXPECT_EQ(s.warnings.size(), 2u);
  EXPECT_TRUE(any_warning_contains(s, "modes.gltf: mesh 0 primitive 0: mode 1"));
  EXPECT_TRUE(any_warning_contains(s, "modes.gltf: mesh 0 primitive 1: mode 0"));
  // Strip triangles (0,1,2) and (2,1,3) after the winding swap.
  EXPECT_EQ(s.triangles[1].v0, strip[0]);
  EXPECT_EQ(s.triangles[2].v0, strip[2]);
  EXPECT_EQ(s.triangles[2].v1, strip[1]);
  EXPECT_EQ(s.triangles[2].v2, strip[3]);
}

TEST(LoaderGltf, BaseColorFactorIsAlbedo) {
  TempDir dir;
  GltfBuilder g;
  g.doc["materials"] = json::array(
      {{{"name", "paint"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.25, 0.5, 0.75, 1}}}}},
       {{"name", "plain"}}});
  add_mesh(g, kTri, {0, 1, 2}, 0);
  add_mesh(g, kTri, {0, 2, 1}, 1);
  add_mesh(g, kTri, {1, 2, 0});  // no material
  g.doc["nodes"] = json::array({{{"mesh", 0}}, {{"mesh", 1}}, {{"mesh", 2}}});
  g.doc["scenes"] = json::array({{{"nodes", {0, 1, 2}}}});
  Scene s;
  s.materials.push_back(Material{"already-there", {0, 0, 0}});
  load_gltf(s, write_text(dir / "mat.gltf", g.gltf()));
  ASSERT_EQ(s.triangles.size(), 3u);
  auto mat = [&](size_t i) { return s.materials.at(s.triangles[i].material); };
  EXPECT_EQ(mat(0).name, "paint");
  EXPECT_EQ(mat(0).albedo, glm::vec3(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(mat(1).albedo, glm::vec3(1.0f));  // glTF default baseColorFactor
  EXPECT_EQ(mat(2).albedo, glm::vec3(0.8f));  // our default for "no material"
  EXPECT_EQ(s.triangles[0].material, 1u);     // shifted past the existing material
}

TEST(LoaderGltf, GlbGivesTheSameTrianglesAsGltf) {
  TempDir dir;
  GltfBuilder g = hierarchy();
  g.doc["materials"] =
      json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.2, 0.3, 1}}}}}});
  add_mesh(g, {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 1, 2}, 0);
  g.doc["nodes"].push_back({{"mesh", 1}, {"scale", {1, 1, 5}}});
  g.doc["nodes"][0]["children"].push_back(2);
  Scene a, b;
  load_gltf(a, write_text(dir / "same.gltf", g.gltf()));
  load_gltf(b, write_bytes(dir / "same.glb", g.glb()));
  ASSERT_EQ(a.triangles.size(), 2u);
  ASSERT_EQ(b.triangles.size(), a.triangles.size());
  for (size_t i = 0; i < a.triangles.size(); ++i) {
    EXPECT_EQ(a.triangles[i].v0, b.triangles[i].v0);
    EXPECT_EQ(a.triangles[i].v1, b.triangles[i].v1);
    EXPECT_EQ(a.triangles[i].v2, b.triangles[i].v2);
    EXPECT_EQ(a.materials[a.triangles[i].material].albedo,
              b.materials[b.triangles[i].material].albedo);
  }
  EXPECT_EQ(b.triangles[1].v2, glm::vec3(10, 20, 35));
}

TEST(LoaderGltf, InterleavedBufferRespectsByteStrideAndOffset) {
  TempDir dir;
  GltfBuilder g;
  // [position, other vec3] x 3; the second accessor reads the "other" halves.
  const std::vector<glm::vec3> data = {{1, 0, 0}, {7, 7, 7}, {0, 1, 0},
                                       {8, 8, 8}, {0, 0, 1}, {9, 9, 10}};
  const size_t offset = g.append(data.data(), data.size() * sizeof(glm::vec3));
  const int view = g.add_view(offset, data.size() * sizeof(glm::vec3), 34962);
  g.doc["bufferViews"][view]["byteStride"] = 24;
  const int a = g.add_accessor(
      {{"bufferView", view}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  const int b = g.add_accessor({{"bufferView", view},
                                {"byteOffset", 12},
                                {"componentType", 5126},
                                {"count", 3},
                                {"type", "VEC3"}});
  g.doc["meshes"] = {
      {{"primitives", {{{"attributes", {{"POSITION", a}}}}, {{"attributes", {{"POSITION", b}}}}}}}};
  g.doc["nodes"] = json::array({{{"mesh", 0}}});
  g.doc["scenes"] = json::array({{{"nodes", {0}}}});
  const Scene s = load_gltf_text(dir, "stride.gltf", g.gltf());
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.triangles[0].v0, data[0]);
  EXPECT_EQ(s.triangles[0].v1, data[2]);
  EXPECT_EQ(s.triangles[0].v2, data[4]);
  EXPECT_EQ(s.triangles[1].v0, data[1]);
  EXPECT_EQ(s.triangles[1].v2, data[5]);
}

TEST(LoaderGltf, SceneSelection) {
  TempDir dir;
  GltfBuilder g;
  const int mesh = add_mesh(g, kTri, {0, 1, 2});
  g.doc["nodes"] = json::array({{{"mesh", mesh}, {"children", {1}}},
                                {{"mesh", mesh}, {"translation", {0, 0, 1}}},
                                {{"mesh", mesh}, {"translation", {0, 0, 2}}}});
  // No scenes: every root node (0 and 2), with node 1 reached through node 0 only.
  EXPECT_EQ(load_gltf_text(dir, "noscene.gltf", g.gltf()).triangles.size(), 3u);
  // "scene" picks the default scene among several.
  g.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {2}}}});
  g.doc["scene"] = 1;
  const Scene s = load_gltf_text(dir, "default.gltf", g.gltf());
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.triangles[0].v2, glm::vec3(0, 0, 5));
  // Without "scene", scene 0.
  g.doc.erase("scene");
  EXPECT_EQ(load_gltf_text(dir, "first.gltf", g.gltf()).triangles.size(), 2u);
}

TEST(LoaderGltf, NodeCycleThrows) {
  TempDir dir;
  GltfBuilder g = hierarchy();
  g.doc["nodes"][1]["children"] = {0};
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_text(dir / "cycle.gltf", g.gltf())); },
                     {"cycle.gltf", "reached twice"});
}

TEST(LoaderGltf, MalformedAndTruncatedFilesThrow) {
  TempDir dir;
  const std::string text = hierarchy().gltf();
  const std::vector<uint8_t> glb = hierarchy().glb();
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_text(dir / "bad.gltf", "{ this is not json")); },
                     {"bad.gltf"});
  expect_scene_error(
      [&] { load_gltf(s, write_text(dir / "cut.gltf", text.substr(0, text.size() / 2))); },
      {"cut.gltf"});
  expect_scene_error(
      [&] {
        load_gltf(s, write_bytes(dir / "cut.glb", {glb.begin(), glb.begin() + glb.size() / 2}));
      },
      {"cut.glb"});
  expect_scene_error(
      [&] {
        load_gltf(s, write_bytes(dir / "tiny.glb", {'g', 'l', 'T', 'F'}));
      },
      {"tiny.glb"});
  EXPECT_TRUE(s.triangles.empty());
  EXPECT_TRUE(s.materials.empty());
}

// A cut-off download or copy: every proper prefix must fail cleanly, never crash.
TEST(LoaderGltf, EveryTruncationFailsWithSceneError) {
  TempDir dir;
  const std::vector<uint8_t> glb = hierarchy().glb();
  const std::string text = hierarchy().gltf();
  for (size_t n = 0; n < glb.size(); ++n) {
    Scene s;
    EXPECT_THROW(load_gltf(s, write_bytes(dir / "t.glb", {glb.begin(), glb.begin() + n})),
                 SceneError)
        << n;
  }
  for (size_t n = 0; n < text.size(); n += 7) {
    Scene s;
    EXPECT_THROW(load_gltf(s, write_text(dir / "t.gltf", text.substr(0, n))), SceneError) << n;
  }
}

TEST(LoaderGltf, AccessorPastTheEndOfItsBufferThrows) {
  TempDir dir;
  {
    GltfBuilder g = hierarchy();
    g.doc["accessors"][0]["count"] = 4;  // bufferView holds 3 positions
    Scene s;
    expect_scene_error([&] { load_gltf(s, write_text(dir / "count.gltf", g.gltf())); },
                       {"count.gltf", "accessor 0", "past the end"});
  }
  {
    GltfBuilder g = hierarchy();
    g.doc["accessors"][0]["byteOffset"] = 4;
    Scene s;
    expect_scene_error([&] { load_gltf(s, write_bytes(dir / "offset.glb", g.glb())); },
                       {"offset.glb", "past the end"});
  }
  {
    GltfBuilder g = hierarchy();
    g.doc["bufferViews"][0]["byteLength"] = 4096;  // longer than the buffer
    Scene s;
    expect_scene_error([&] { load_gltf(s, write_text(dir / "view.gltf", g.gltf())); },
                       {"view.gltf"});
  }
  {
    GltfBuilder g = hierarchy();
    g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 17;  // no such accessor
    Scene s;
    expect_scene_error([&] { load_gltf(s, write_text(dir / "missing.gltf", g.gltf())); },
                       {"missing.gltf"});
  }
}

TEST(LoaderGltf, IndexOutOfRangeThrows) {
  TempDir dir;
  GltfBuilder g;
  add_mesh(g, kTri, {0, 1, 3});
  g.doc["nodes"] = json::array({{{"mesh", 0}}});
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_text(dir / "index.gltf", g.gltf())); },
                     {"index.gltf", "index 3", "out of range"});
}

TEST(LoaderGltf, NaNCoordinateThrowsNamingTheFile) {
  TempDir dir;
  GltfBuilder g;
  add_mesh(g, {{0, 0, 0}, {std::numeric_limits<float>::quiet_NaN(), 1, 0}, {0, 0, 1}}, {0, 1, 2});
  g.doc["accessors"][0].erase("min");  // nlohmann would write NaN min/max as null
  g.doc["accessors"][0].erase("max");
  g.doc["nodes"] = json::array({{{"mesh", 0}}});
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_bytes(dir / "nan.glb", g.glb())); },
                     {"nan.glb", "non-finite"});
}

TEST(LoaderGltf, RequiredGeometryCompressionExtensionIsAnError) {
  TempDir dir;
  GltfBuilder g = hierarchy();
  g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_text(dir / "draco.gltf", g.gltf())); },
                     {"draco.gltf", "KHR_draco_mesh_compression"});
}

// A real Draco file's accessors have no bufferView: tinygltf used to fail on that first, with
// "accessor[0] invalid bufferView", before our check of the required extensions ran.
TEST(LoaderGltf, DracoFileSaysDracoNotInvalidBufferView) {
  TempDir dir;
  GltfBuilder g = hierarchy();
  g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  for (auto& a : g.doc["accessors"]) a.erase("bufferView");
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_text(dir / "draco.gltf", g.gltf())); },
                     {"draco.gltf: requires unsupported extension KHR_draco_mesh_compression"});
  expect_scene_error([&] { load_gltf(s, write_bytes(dir / "draco.glb", g.glb())); },
                     {"draco.glb: requires unsupported extension KHR_draco_mesh_compression"});
}

TEST(LoaderGltf, GltfOneIsNamedAsSuch) {
  TempDir dir;
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_text(dir / "v1.gltf", R"({"asset": {"version": "1.0"}})")); },
                     {"v1.gltf: glTF 1.0 is not supported"});
  // Many 1.0 exporters wrote no asset at all; 1.0 keeps scenes in an object, not an array.
  expect_scene_error(
      [&] { load_gltf(s, write_text(dir / "old.gltf", R"({"scene": "s", "scenes": {"s": {"nodes": []}}})")); },
      {"old.gltf: a glTF 1.0 file"});
}

TEST(LoaderGltf, ABufferUriThatIsAFolderIsNamed) {
  TempDir dir;
  json doc = json::parse(hierarchy().gltf());
  doc["buffers"][0]["uri"] = ".";
  Scene s;
  expect_scene_error([&] { load_gltf(s, write_text(dir / "dot.gltf", doc.dump())); },
                     {"dot.gltf: buffers[0].uri '.': not a regular file"});
  doc["buffers"][0]["uri"] = "missing.bin";
  expect_scene_error([&] { load_gltf(s, write_text(dir / "gone.gltf", doc.dump())); },
                     {"gone.gltf: buffers[0].uri 'missing.bin': no such file"});
}

TEST(LoaderGltf, NoTrianglesSaysWhy) {
  TempDir dir;
  GltfBuilder g;
  const int pts = g.add_positions(kTri);
  g.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", pts}}}, {"mode", 0}}}}}};
  g.doc["nodes"] = json::array({{{"mesh", 0}}});
  g.doc["scenes"] = json::array({{{"nodes", {0}}}});
  const Scene s = load_gltf_text(dir, "points.gltf", g.gltf());
  expect_scene_error([&] { require_triangles(s, "points.gltf"); },
                     {"points.gltf: scene has no triangles; the loader said:", "mode 0 is not a triangle mode"});
}

TEST(LoaderGltf, MissingFileAndUnsupportedExtensionThrow) {
  TempDir dir;
  Scene s;
  expect_scene_error([&] { load_gltf(s, dir / "absent.gltf"); }, {"absent.gltf", "not found"});
  expect_scene_error([&] { load_gltf(s, write_text(dir / "mesh.fbx", "x")); },
                     {"mesh.fbx", ".fbx"});
}

}  // namespace
}  // namespace strata::scenes
