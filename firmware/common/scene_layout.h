// The scene memory image: the exact bytes the chip model keeps in simulated DRAM and the
// firmware reads. One definition, shared by the host builder (scenes/), the firmware, the
// native twin and the model. Freestanding: <stdint.h> only. Byte layout is documented in
// docs/scene-image.md; static_asserts below pin every size.
#pragma once

#include <stdint.h>

namespace strata {

constexpr uint32_t kSceneImageMagic = 0x53525453u;  // "STRS" little-endian
constexpr uint32_t kSceneImageVersion = 3;  // 3: the checksum covers the header too

// The traversal stack is one 32-bit word with a bit per level, so no leaf may lie deeper
// than 32 edges below the root. The builder guarantees it.
constexpr uint32_t kMaxBvhDepth = 32;
constexpr uint32_t kMaxLeafTriangles = 15;  // fits the 4-bit count of a leaf reference

// A child reference packs either an inner node index or a leaf (triangle range).
//   bit 31 = 0: inner node index (bits 0..30)
//   bit 31 = 1: leaf; bits 27..30 = triangle count (0 = empty child, never hit);
//               bits 0..26 = byte offset of the first triangle from the triangle section,
//               in 16-byte units (triangles are 48 B, so offsets are multiples of 16)
constexpr uint32_t kLeafFlag = 0x80000000u;
constexpr uint32_t kLeafCountShift = 27;
constexpr uint32_t kLeafCountMask = 0xFu;
constexpr uint32_t kLeafOffsetMask = (1u << kLeafCountShift) - 1u;
constexpr uint32_t kLeafOffsetUnit = 16;
constexpr uint32_t kNoParent = 0xFFFFFFFFu;

inline bool child_is_leaf(uint32_t ref) { return (ref & kLeafFlag) != 0; }
inline uint32_t leaf_count(uint32_t ref) { return (ref >> kLeafCountShift) & kLeafCountMask; }
inline uint32_t leaf_byte_offset(uint32_t ref) { return (ref & kLeafOffsetMask) * kLeafOffsetUnit; }
inline uint32_t make_leaf_ref(uint32_t byte_offset, uint32_t count) {
  return kLeafFlag | (count << kLeafCountShift) | (byte_offset / kLeafOffsetUnit);
}

// One inner node is one 64-byte cache line and holds the boxes of BOTH children, so the box
// tests that decide where a ray goes next read only the current node, hence only the
// current treelet. Leaves are not nodes: a leaf is a child reference to a triangle range.
struct BvhNode {
  // [0] left, [1] right: min xyz then max xyz, so one child's box is 6 contiguous floats,
  // the operand of the box pipeline's strata.ldbox. An empty child has min > max.
  float child_box[2][6];
  uint32_t child[2];      // child references (see above)
  uint32_t parent;        // node index of the parent, kNoParent at the root
  uint32_t treelet;       // id of the node treelet holding this node
};
static_assert(sizeof(BvhNode) == 64, "BvhNode must be one 64-byte line");

inline const float* child_min(const BvhNode& n, int side) { return n.child_box[side]; }
inline const float* child_max(const BvhNode& n, int side) { return n.child_box[side] + 3; }

// A triangle as the triangle pipeline consumes it: three vertices, then identification.
struct TriangleRecord {
  float v0[3], v1[3], v2[3];
  uint32_t primitive;  // index of the triangle in the loaded scene (hit reporting)
  uint32_t material;   // index into the material table
  uint32_t pad;
};
static_assert(sizeof(TriangleRecord) == 48, "TriangleRecord must be 48 bytes");

struct MaterialRecord {
  float albedo[3];
  uint32_t pad;
};
static_assert(sizeof(MaterialRecord) == 16, "MaterialRecord must be 16 bytes");

enum TreeletKind : uint32_t { kNodeTreelet = 0, kTriangleTreelet = 1 };

// Treelet i occupies [treelet_offset + i * treelet_bytes, +treelet_bytes) in the image:
// node treelets first, then triangle treelets. So the treelet of any node or triangle
// follows from its address alone: (address - treelet_offset) / treelet_bytes.
struct TreeletRecord {
  uint32_t kind;        // TreeletKind
  uint32_t used_bytes;  // bytes holding nodes or triangles; the rest is zero padding
  uint32_t first;       // first node index, or first triangle's byte offset in the section
  uint32_t count;       // nodes or triangles it holds
};
static_assert(sizeof(TreeletRecord) == 16, "TreeletRecord must be 16 bytes");

struct SceneImageHeader {
  uint32_t magic;
  uint32_t version;
  uint32_t header_bytes;
  uint32_t treelet_bytes;     // treelet size (= L1 size), a power of two
  uint64_t image_bytes;       // whole blob, header included
  uint64_t content_key;       // hash of the build inputs (scene content + parameters)
  // ContentHash (scenes/content_hash.h) of the whole image, header included, with this field
  // read as 0: a changed camera, light or root node is caught like a changed node.
  uint64_t payload_checksum;
  uint32_t material_offset, material_count;
  uint32_t treelet_table_offset, treelet_count;
  uint32_t node_treelet_count;  // treelets [0, node_treelet_count) hold nodes
  uint32_t treelet_offset;      // first treelet (aligned to treelet_bytes)
  uint32_t node_offset, node_slots;  // node section: node_slots 64 B slots incl. padding
  uint32_t triangle_offset, triangle_bytes;  // triangle section (padding included)
  uint32_t triangle_count;    // real triangles in the image
  uint32_t root_node;
  uint32_t node_count;        // real inner nodes
  uint32_t bvh_depth;         // deepest leaf, in edges from the root
  uint32_t max_leaf_triangles;
  float bounds_min[3], bounds_max[3];
  float camera_eye[3], camera_target[3], camera_up[3], camera_vfov_degrees;
  float light_position[3], light_intensity[3];
  float background[3];
  uint32_t reserved[13];
};
static_assert(sizeof(SceneImageHeader) == 256, "SceneImageHeader must be 256 bytes");

}  // namespace strata
