#include "scenes/scene_image.h"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <utility>

#include "scenes/content_hash.h"

namespace strata::scenes {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

uint64_t align_up(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }

void copy3(float dst[3], const glm::vec3& v) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
}

// Where every build-tree node and leaf ends up in the image.
struct Placement {
  std::vector<uint32_t> node_index;  // build node -> image node index (inner nodes only)
  std::vector<uint32_t> leaf_ref;    // build node -> child reference (leaves only)
  std::vector<TreeletRecord> treelets;
  uint32_t node_treelets = 0;
  uint64_t triangle_bytes = 0;
};

Placement place(const BinaryBvh& bvh, const TreeletPartition& parts, uint32_t treelet_bytes) {
  const uint32_t per_treelet = treelet_bytes / uint32_t(sizeof(BvhNode));
  Placement p;
  p.node_index.assign(bvh.nodes.size(), BinaryBvh::kNone);
  p.leaf_ref.assign(bvh.nodes.size(), make_leaf_ref(0, 0));
  for (size_t t = 0; t < parts.treelets.size(); ++t) {
    const auto& members = parts.treelets[t];
    for (size_t j = 0; j < members.size(); ++j)
      p.node_index[members[j]] = uint32_t(t * per_treelet + j);
    p.treelets.push_back({kNodeTreelet, uint32_t(members.size() * sizeof(BvhNode)),
                          uint32_t(t * per_treelet), uint32_t(members.size())});
  }
  p.node_treelets = uint32_t(parts.treelets.size());

  // Triangle treelets follow node-treelet order, so the leaves one node treelet reaches sit
  // in as few triangle treelets as possible. A leaf never straddles two triangle treelets.
  uint64_t tri_treelet = 0, used = 0;
  uint32_t in_treelet = 0;
  auto close_treelet = [&] {
    p.treelets.push_back({kTriangleTreelet, uint32_t(used), uint32_t(tri_treelet * treelet_bytes),
                          in_treelet});
    ++tri_treelet;
    used = 0;
    in_treelet = 0;
  };
  for (const auto& members : parts.treelets) {
    for (uint32_t b : members) {
      for (uint32_t c : {bvh.nodes[b].left, bvh.nodes[b].right}) {
        const BinaryBvh::Node& leaf = bvh.nodes[c];
        if (!leaf.is_leaf()) continue;
        const uint64_t bytes = uint64_t(leaf.count) * sizeof(TriangleRecord);
        if (used + bytes > treelet_bytes) close_treelet();
        const uint64_t offset = tri_treelet * treelet_bytes + used;
        if (offset / kLeafOffsetUnit > kLeafOffsetMask)
          throw SceneError("scene image: triangle section exceeds the 2 GiB a leaf reference can address");
        p.leaf_ref[c] = make_leaf_ref(uint32_t(offset), leaf.count);
        used += bytes;
        in_treelet += leaf.count;
      }
    }
  }
  if (in_treelet > 0) close_treelet();
  p.triangle_bytes = tri_treelet * treelet_bytes;
  return p;
}

// A scene whose BVH is a single leaf still needs one inner node for the layout.
BinaryBvh wrap_leaf_root(BinaryBvh bvh) {
  if (!bvh.nodes[0].is_leaf()) return bvh;
  BinaryBvh::Node leaf = bvh.nodes[0];
  BinaryBvh::Node root;
  root.bounds = leaf.bounds;
  root.left = 1;
  root.right = 2;
  leaf.parent = 0;
  leaf.depth = 1;
  BinaryBvh::Node empty;
  empty.parent = 0;
  empty.depth = 1;
  empty.first = leaf.first;
  empty.count = 0;
  bvh.nodes = {root, leaf, empty};
  return bvh;
}

void write_child(BvhNode* node, int side, const BinaryBvh::Node& child, uint32_t ref) {
  if (child.is_leaf() && child.count == 0) {
    for (int a = 0; a < 3; ++a) {
      node->child_box[side][a] = FLT_MAX;
      node->child_box[side][3 + a] = -FLT_MAX;
    }
  } else {
    copy3(node->child_box[side], child.bounds.min);
    copy3(node->child_box[side] + 3, child.bounds.max);
  }
  node->child[side] = ref;
}

void fill_header(SceneImageHeader* h, const Scene& scene, const Bounds& bounds) {
  copy3(h->bounds_min, bounds.min);
  copy3(h->bounds_max, bounds.max);
  copy3(h->camera_eye, scene.camera.eye);
  copy3(h->camera_target, scene.camera.target);
  copy3(h->camera_up, scene.camera.up);
  h->camera_vfov_degrees = scene.camera.vfov_degrees;
  copy3(h->light_position, scene.light.position);
  copy3(h->light_intensity, scene.light.intensity);
  copy3(h->background, scene.background);
}

[[noreturn]] void invalid(const std::string& source, const std::string& what) {
  throw SceneError(source + ": invalid scene image: " + what);
}

uint64_t checksum_of(const uint8_t* bytes, uint64_t size) {
  constexpr size_t field = offsetof(SceneImageHeader, payload_checksum);
  const uint8_t zeros[sizeof(uint64_t)] = {};
  ContentHash h;
  h.add_bytes(bytes, field);
  h.add_bytes(zeros, sizeof zeros);
  h.add_bytes(bytes + field + sizeof zeros, size - field - sizeof zeros);
  return h.value();
}

bool finite3(const float v[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// The header's values that the firmware and the renderer trust, each in its range: a
// checksum proves the file is as written, not that a writer wrote sense.
void check_header_values(const SceneImageHeader& h, const std::string& source) {
  if (h.bvh_depth > kMaxBvhDepth)
    invalid(source, "bvh_depth " + std::to_string(h.bvh_depth) + " exceeds " + std::to_string(kMaxBvhDepth));
  if (h.max_leaf_triangles == 0 || h.max_leaf_triangles > kMaxLeafTriangles)
    invalid(source, "max_leaf_triangles " + std::to_string(h.max_leaf_triangles) + " outside 1.." +
                        std::to_string(kMaxLeafTriangles));
  if (h.triangle_count == 0 || uint64_t(h.triangle_count) * sizeof(TriangleRecord) > h.triangle_bytes)
    invalid(source, "triangle_count " + std::to_string(h.triangle_count) + " does not fit the triangle section (" +
                        std::to_string(h.triangle_bytes) + " bytes)");
  if (h.node_count == 0 || h.node_count > h.node_slots)
    invalid(source, "node_count " + std::to_string(h.node_count) + " outside 1..node_slots (" +
                        std::to_string(h.node_slots) + ")");
  if (h.material_count == 0) invalid(source, "no materials");
  for (const auto& [v, name] : {std::pair{h.bounds_min, "bounds_min"}, {h.bounds_max, "bounds_max"},
                                {h.camera_eye, "camera_eye"}, {h.camera_target, "camera_target"},
                                {h.camera_up, "camera_up"}, {h.light_position, "light_position"},
                                {h.light_intensity, "light_intensity"}, {h.background, "background"}})
    if (!finite3(v)) invalid(source, std::string(name) + " is not finite");
  for (int i = 0; i < 3; ++i) {
    if (h.bounds_min[i] > h.bounds_max[i]) invalid(source, "bounds_min exceeds bounds_max");
    if (h.light_intensity[i] < 0.0f) invalid(source, "light_intensity is negative");
    if (h.background[i] < 0.0f) invalid(source, "background is negative");
  }
  if (!(h.camera_vfov_degrees > 0.0f && h.camera_vfov_degrees < 180.0f))
    invalid(source, "camera_vfov_degrees outside (0, 180)");
  if (h.camera_eye[0] == h.camera_target[0] && h.camera_eye[1] == h.camera_target[1] &&
      h.camera_eye[2] == h.camera_target[2])
    invalid(source, "camera eye and target coincide");
}


}  // namespace

void check_image_params(const SceneImageParams& params) {
  const uint32_t t = params.treelet_bytes;
  if (t < 1024 || (t & (t - 1)) != 0)
    throw SceneError("treelet_bytes: must be a power of two of at least 1024, got " + std::to_string(t));
  if (uint64_t(params.bvh.max_leaf_triangles) * sizeof(TriangleRecord) > t)
    throw SceneError("treelet_bytes: too small to hold one leaf of max_leaf_triangles");
}

uint64_t scene_content_key(const Scene& scene, const SceneImageParams& params) {
  ContentHash h;
  h.add(kSceneImageVersion);
  h.add(uint64_t(scene.triangles.size()));
  for (const Triangle& t : scene.triangles) {
    h.add(t.v0);
    h.add(t.v1);
    h.add(t.v2);
    h.add(t.material);
  }
  h.add(uint64_t(scene.materials.size()));
  for (const Material& m : scene.materials) h.add(m.albedo);
  h.add(scene.camera);
  h.add(scene.light);
  h.add(scene.background);
  h.add(params.bvh);
  h.add(params.treelet_bytes);
  h.add(params.treelet_policy);
  return h.value();
}

SceneImage build_scene_image(const Scene& scene, const SceneImageParams& params,
                             SceneBuildReport* report) {
  check_image_params(params);
  if (scene.triangles.empty()) throw SceneError(scene.name + ": scene has no triangles");
  if (scene.triangles.size() > 0xFFFFFFFEu) throw SceneError(scene.name + ": too many triangles");
  SceneBuildReport local;
  SceneBuildReport& rep = report ? *report : local;

  auto t0 = Clock::now();
  BinaryBvh bvh = wrap_leaf_root(build_bvh(scene.triangles, params.bvh));
  rep.bvh_seconds = seconds_since(t0);

  t0 = Clock::now();
  const uint32_t per_treelet = params.treelet_bytes / uint32_t(sizeof(BvhNode));
  const TreeletPartition parts = partition_treelets(bvh, per_treelet, params.treelet_policy);
  rep.treelet_seconds = seconds_since(t0);

  t0 = Clock::now();
  const Placement p = place(bvh, parts, params.treelet_bytes);
  const uint64_t T = params.treelet_bytes;
  const uint64_t material_offset = sizeof(SceneImageHeader);
  const uint64_t table_offset = material_offset + scene.materials.size() * sizeof(MaterialRecord);
  const uint64_t treelet_offset = align_up(table_offset + p.treelets.size() * sizeof(TreeletRecord), T);
  const uint64_t node_bytes = uint64_t(p.node_treelets) * T;
  const uint64_t triangle_offset = treelet_offset + node_bytes;
  const uint64_t image_bytes = triangle_offset + p.triangle_bytes;
  if (image_bytes > 0xFFFFFFFFull)
    throw SceneError(scene.name + ": scene image of " + std::to_string(image_bytes) +
                     " bytes exceeds the 4 GiB a 32-bit thread processor can address");

  std::vector<uint64_t> words(image_bytes / 8, 0);
  uint8_t* bytes = reinterpret_cast<uint8_t*>(words.data());
  auto* h = reinterpret_cast<SceneImageHeader*>(bytes);
  h->magic = kSceneImageMagic;
  h->version = kSceneImageVersion;
  h->header_bytes = sizeof(SceneImageHeader);
  h->treelet_bytes = params.treelet_bytes;
  h->image_bytes = image_bytes;
  h->content_key = scene_content_key(scene, params);
  h->material_offset = uint32_t(material_offset);
  h->material_count = uint32_t(scene.materials.size());
  h->treelet_table_offset = uint32_t(table_offset);
  h->treelet_count = uint32_t(p.treelets.size());
  h->node_treelet_count = p.node_treelets;
  h->treelet_offset = uint32_t(treelet_offset);
  h->node_offset = uint32_t(treelet_offset);
  h->node_slots = uint32_t(node_bytes / sizeof(BvhNode));
  h->triangle_offset = uint32_t(triangle_offset);
  h->triangle_bytes = uint32_t(p.triangle_bytes);
  h->triangle_count = uint32_t(scene.triangles.size());
  h->root_node = p.node_index[0];
  h->bvh_depth = bvh.max_depth();
  h->max_leaf_triangles = params.bvh.max_leaf_triangles;
  fill_header(h, scene, bvh.nodes[0].bounds);

  auto* materials = reinterpret_cast<MaterialRecord*>(bytes + material_offset);
  for (size_t i = 0; i < scene.materials.size(); ++i) copy3(materials[i].albedo, scene.materials[i].albedo);
  std::memcpy(bytes + table_offset, p.treelets.data(), p.treelets.size() * sizeof(TreeletRecord));

  uint32_t node_count = 0;
  for (size_t b = 0; b < bvh.nodes.size(); ++b) {
    const BinaryBvh::Node& bn = bvh.nodes[b];
    if (bn.is_leaf()) {
      for (uint32_t i = 0; i < bn.count; ++i) {
        const uint32_t prim = bvh.primitives[bn.first + i];
        const Triangle& tri = scene.triangles[prim];
        auto* rec = reinterpret_cast<TriangleRecord*>(
            bytes + triangle_offset + leaf_byte_offset(p.leaf_ref[b]) + i * sizeof(TriangleRecord));
        copy3(rec->v0, tri.v0);
        copy3(rec->v1, tri.v1);
        copy3(rec->v2, tri.v2);
        rec->primitive = prim;
        rec->material = tri.material;
      }
      continue;
    }
    ++node_count;
    const uint32_t index = p.node_index[b];
    auto* node = reinterpret_cast<BvhNode*>(bytes + treelet_offset + uint64_t(index) * sizeof(BvhNode));
    const BinaryBvh::Node& l = bvh.nodes[bn.left];
    const BinaryBvh::Node& r = bvh.nodes[bn.right];
    write_child(node, 0, l, l.is_leaf() ? p.leaf_ref[bn.left] : p.node_index[bn.left]);
    write_child(node, 1, r, r.is_leaf() ? p.leaf_ref[bn.right] : p.node_index[bn.right]);
    node->parent = bn.parent == BinaryBvh::kNone ? kNoParent : p.node_index[bn.parent];
    node->treelet = index / per_treelet;
  }
  h->node_count = node_count;
  h->payload_checksum = scene_image_checksum(bytes, image_bytes);
  rep.layout_seconds = seconds_since(t0);
  return SceneImage(std::move(words), scene.name);
}

SceneImage::SceneImage(std::vector<uint64_t> words, const std::string& source)
    : words_(std::move(words)) {
  const uint64_t have = uint64_t(words_.size()) * 8;
  if (have < sizeof(SceneImageHeader)) invalid(source, "truncated (no complete header)");
  const SceneImageHeader& h = header();
  if (h.magic != kSceneImageMagic) invalid(source, "not a scene image (bad magic)");
  if (h.version != kSceneImageVersion)
    invalid(source, "version " + std::to_string(h.version) + ", expected " + std::to_string(kSceneImageVersion));
  if (h.header_bytes != sizeof(SceneImageHeader)) invalid(source, "bad header size");
  if (h.image_bytes != have)
    invalid(source, "size mismatch: header says " + std::to_string(h.image_bytes) + " bytes, have " + std::to_string(have));
  const uint64_t T = h.treelet_bytes;
  if (T < 1024 || (T & (T - 1)) != 0) invalid(source, "bad treelet size");
  const uint64_t table_end = uint64_t(h.treelet_table_offset) + uint64_t(h.treelet_count) * sizeof(TreeletRecord);
  if (uint64_t(h.material_offset) + uint64_t(h.material_count) * sizeof(MaterialRecord) > have ||
      table_end > h.treelet_offset || h.treelet_offset % T != 0 || h.node_offset != h.treelet_offset ||
      uint64_t(h.node_slots) * sizeof(BvhNode) != uint64_t(h.node_treelet_count) * T ||
      uint64_t(h.triangle_offset) != uint64_t(h.node_offset) + uint64_t(h.node_treelet_count) * T ||
      uint64_t(h.triangle_offset) + h.triangle_bytes != have || h.triangle_bytes % T != 0 ||
      h.treelet_count != h.node_treelet_count + h.triangle_bytes / T)
    invalid(source, "inconsistent section layout");
  if (scene_image_checksum(bytes(), have) != h.payload_checksum) invalid(source, "checksum mismatch (corrupt)");
  check_header_values(h, source);
  // Structural checks, so that even a well-checksummed but wrong image cannot send a
  // traversal out of bounds.
  if (h.root_node >= h.node_slots) invalid(source, "root node out of range");
  for (uint32_t i = 0; i < h.node_slots; ++i) {
    const BvhNode& n = node(i);
    if (n.child[0] == 0 && n.child[1] == 0) continue;  // padding slot
    for (uint32_t ref : n.child) {
      if (child_is_leaf(ref)) {
        if (uint64_t(leaf_byte_offset(ref)) + leaf_count(ref) * sizeof(TriangleRecord) > h.triangle_bytes)
          invalid(source, "leaf of node " + std::to_string(i) + " points outside the triangles");
      } else if (ref >= h.node_slots || node(ref).parent != i) {
        invalid(source, "child of node " + std::to_string(i) + " is out of range or has a wrong parent");
      }
    }
  }
}

uint64_t scene_image_checksum(const uint8_t* bytes, uint64_t size) {
  if (size < sizeof(SceneImageHeader)) throw SceneError("scene_image_checksum: shorter than a header");
  return checksum_of(bytes, size);
}

}  // namespace strata::scenes
