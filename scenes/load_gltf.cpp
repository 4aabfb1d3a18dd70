#include "scenes/load_gltf.h"

#include "scenes/gltf_preflight.h"

#include "scenes/validate.h"

#include <tiny_gltf.h>

#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <optional>
#include <sstream>
#include <utility>

namespace strata::scenes {

namespace fs = std::filesystem;

namespace {

// Geometry is all we need; decoding textures would only cost time and add failure modes.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

// A bounds-checked window onto an accessor's elements.
struct AccessorView {
  const unsigned char* data = nullptr;
  size_t stride = 0;
  size_t count = 0;
  int component_type = 0;
};

// One triangle of a mesh in the mesh's own coordinates, before any node transform.
struct LocalTriangle {
  glm::vec3 v0, v1, v2;
  uint32_t material;
};

size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
    default: return 0;
  }
}

size_t component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

class GltfReader {
 public:
  // `scene` must start empty: glTF material i becomes scene material i.
  GltfReader(Scene& scene, const tinygltf::Model& model, std::string source)
      : scene_(scene),
        model_(model),
        source_(std::move(source)),
        mesh_cache_(model.meshes.size()) {}

  void run() {
    // Compressed or quantized geometry would surface later as a confusing accessor error.
    for (const std::string& ext : model_.extensionsRequired) {
      if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" ||
          ext == "KHR_mesh_quantization") {
        fail("requires unsupported extension " + ext);
      }
      warn("requires extension " + ext + ", which is ignored");
    }
    for (const tinygltf::Material& m : model_.materials) {
      const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
      glm::vec3 albedo{1.0f, 1.0f, 1.0f};  // glTF's default baseColorFactor
      if (f.size() >= 3) {
        albedo =
            glm::vec3(static_cast<float>(f[0]), static_cast<float>(f[1]), static_cast<float>(f[2]));
      }
      scene_.materials.push_back(Material{m.name, albedo});
    }
    visited_.assign(model_.nodes.size(), false);
    for (int root : root_nodes()) visit(root);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw SceneError(source_ + ": " + what); }
  void warn(const std::string& what) { scene_.warnings.push_back(source_ + ": " + what); }

  std::vector<int> root_nodes() const {
    if (!model_.scenes.empty()) {
      const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (static_cast<size_t>(s) >= model_.scenes.size()) {
        fail("default scene " + std::to_string(s) + " does not exist");
      }
      return model_.scenes[static_cast<size_t>(s)].nodes;
    }
    // No scenes: the spec leaves this to the application; render every root node.
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (const tinygltf::Node& n : model_.nodes) {
      for (int c : n.children) {
        if (c >= 0 && static_cast<size_t>(c) < is_child.size()) {
          is_child[static_cast<size_t>(c)] = true;
        }
      }
    }
    std::vector<int> roots;
    for (size_t i = 0; i < is_child.size(); ++i) {
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
  }

  glm::dmat4 local_transform(const tinygltf::Node& node, size_t index) const {
    const std::string where = "node " + std::to_string(index) + ": ";
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) fail(where + "matrix must have 16 numbers");
      return glm::make_mat4(node.matrix.data());  // both glTF and glm are column-major
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty()) {
      if (node.translation.size() != 3) fail(where + "translation must have 3 numbers");
      t = glm::translate(glm::dmat4(1.0), glm::make_vec3(node.translation.data()));
    }
    if (!node.rotation.empty()) {
      if (node.rotation.size() != 4) fail(where + "rotation must have 4 numbers");
      // glTF stores [x, y, z, w]; set members by name so glm's constructor order
      // (w first) cannot be confused.
      glm::dquat q;
      q.x = node.rotation[0];
      q.y = node.rotation[1];
      q.z = node.rotation[2];
      q.w = node.rotation[3];
      r = glm::mat4_cast(q);
    }
    if (!node.scale.empty()) {
      if (node.scale.size() != 3) fail(where + "scale must have 3 numbers");
      s = glm::scale(glm::dmat4(1.0), glm::make_vec3(node.scale.data()));
    }
    return t * r * s;
  }

  // Depth-first with an explicit stack: a deep hierarchy cannot overflow the call stack,
  // and a node reached twice (a cycle, or two parents) is rejected instead of looping.
  void visit(int root) {
    std::vector<std::pair<int, glm::dmat4>> stack{{root, glm::dmat4(1.0)}};
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size()) {
        fail("node " + std::to_string(index) + " does not exist");
      }
      const auto i = static_cast<size_t>(index);
      if (visited_[i]) {
        fail("node " + std::to_string(i) + " is reached twice (cycle or several parents)");
      }
      visited_[i] = true;
      const tinygltf::Node& node = model_.nodes[i];
      const glm::dmat4 world = parent * local_transform(node, i);
      if (node.mesh >= 0) instance(node.mesh, world, i);
      // Reverse so children come out in file order.
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) {
        stack.emplace_back(*c, world);
      }
    }
  }

  void instance(int mesh_index, const glm::dmat4& world, size_t node) {
    if (static_cast<size_t>(mesh_index) >= model_.meshes.size()) {
      fail("node " + std::to_string(node) + ": mesh " + std::to_string(mesh_index) +
           " does not exist");
    }
    auto& cached = mesh_cache_[static_cast<size_t>(mesh_index)];
    if (!cached) cached = mesh_triangles(static_cast<size_t>(mesh_index));
    auto to_world = [&world](const glm::vec3& p) {
      return glm::vec3(world * glm::dvec4(glm::dvec3(p), 1.0));
    };
    for (const LocalTriangle& t : *cached) {
      scene_.triangles.push_back(
          Triangle{to_world(t.v0), to_world(t.v1), to_world(t.v2), t.material});
    }
  }

  // Converted once per mesh, so instancing costs only the transform and each warning
  // appears once however many nodes use the mesh.
  std::vector<LocalTriangle> mesh_triangles(size_t mesh_index) {
    std::vector<LocalTriangle> out;
    const tinygltf::Mesh& mesh = model_.meshes[mesh_index];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = mesh.primitives[p];
      const std::string where =
          "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(p) + ": ";
      const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        warn(where + "mode " + std::to_string(mode) + " is not a triangle mode; skipped");
        continue;
      }
      const auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) {
        warn(where + "no POSITION attribute; skipped");
        continue;
      }
      const std::vector<glm::vec3> positions = read_positions(pos->second, where);
      const std::vector<uint32_t> indices = read_indices(prim, positions.size(), where);
      const uint32_t material = material_index(prim.material, where);
      const size_t n = indices.size();
      auto emit = [&](size_t a, size_t b, size_t c) {
        out.push_back(LocalTriangle{positions[indices[a]], positions[indices[b]],
                                    positions[indices[c]], material});
      };
      if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0) {
          fail(where + std::to_string(n) + " vertices is not a multiple of 3");
        }
        for (size_t i = 0; i + 2 < n; i += 3) emit(i, i + 1, i + 2);
      } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // Odd triangles swap their first two vertices to keep a consistent winding.
        for (size_t i = 0; i + 2 < n; ++i) {
          if (i % 2 == 0) {
            emit(i, i + 1, i + 2);
          } else {
            emit(i + 1, i, i + 2);
          }
        }
      } else {
        for (size_t i = 1; i + 1 < n; ++i) emit(i, i + 1, 0);
      }
    }
    return out;
  }

  uint32_t material_index(int material, const std::string& where) {
    if (material >= 0) {
      if (static_cast<size_t>(material) >= model_.materials.size()) {
        fail(where + "material " + std::to_string(material) + " does not exist");
      }
      return static_cast<uint32_t>(material);  // run() added them first, in order
    }
    if (!default_material_) {
      default_material_ = static_cast<uint32_t>(scene_.materials.size());
      scene_.materials.push_back(Material{"default", {0.8f, 0.8f, 0.8f}});
    }
    return *default_material_;
  }

  AccessorView view(int index, const std::string& where, int type,
                    std::initializer_list<int> component_types) const {
    const std::string at = where + "accessor " + std::to_string(index) + ": ";
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size()) {
      fail(at + "does not exist");
    }
    const tinygltf::Accessor& acc = model_.accessors[static_cast<size_t>(index)];
    if (acc.sparse.isSparse) fail(at + "sparse accessors are not supported");
    if (acc.type != type) fail(at + "unexpected type " + std::to_string(acc.type));
    if (std::find(component_types.begin(), component_types.end(), acc.componentType) ==
        component_types.end()) {
      fail(at + "unexpected componentType " + std::to_string(acc.componentType));
    }
    if (acc.bufferView < 0 || static_cast<size_t>(acc.bufferView) >= model_.bufferViews.size()) {
      fail(at + "bufferView " + std::to_string(acc.bufferView) + " does not exist");
    }
    const tinygltf::BufferView& bv = model_.bufferViews[static_cast<size_t>(acc.bufferView)];
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model_.buffers.size()) {
      fail(at + "buffer " + std::to_string(bv.buffer) + " does not exist");
    }
    const std::vector<unsigned char>& buf = model_.buffers[static_cast<size_t>(bv.buffer)].data;
    const size_t elem = component_size(acc.componentType) * component_count(acc.type);
    const size_t stride = bv.byteStride != 0 ? bv.byteStride : elem;
    if (stride < elem) fail(at + "byteStride smaller than one element");
    // Every comparison is arranged so that no sum can overflow.
    if (bv.byteLength > buf.size() || bv.byteOffset > buf.size() - bv.byteLength) {
      fail(at + "bufferView " + std::to_string(acc.bufferView) + " runs past the end of buffer " +
           std::to_string(bv.buffer) + " (" + std::to_string(buf.size()) + " bytes)");
    }
    if (acc.count > 0) {
      if (acc.byteOffset > bv.byteLength || elem > bv.byteLength - acc.byteOffset ||
          (acc.count - 1) > (bv.byteLength - acc.byteOffset - elem) / stride) {
        fail(at + std::to_string(acc.count) + " elements run past the end of bufferView " +
             std::to_string(acc.bufferView) + " (" + std::to_string(bv.byteLength) + " bytes)");
      }
    }
    return AccessorView{buf.data() + bv.byteOffset + acc.byteOffset, stride, acc.count,
                        acc.componentType};
  }

  std::vector<glm::vec3> read_positions(int accessor, const std::string& where) const {
    const AccessorView v =
        view(accessor, where + "POSITION ", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    std::vector<glm::vec3> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      std::memcpy(&out[i], v.data + i * v.stride, sizeof(glm::vec3));  // may be unaligned
    }
    return out;
  }

  std::vector<uint32_t> read_indices(const tinygltf::Primitive& prim, size_t vertex_count,
                                     const std::string& where) const {
    std::vector<uint32_t> out;
    if (prim.indices < 0) {  // non-indexed: vertices in order
      out.resize(vertex_count);
      for (size_t i = 0; i < vertex_count; ++i) out[i] = static_cast<uint32_t>(i);
      return out;
    }
    const AccessorView v =
        view(prim.indices, where + "indices ", TINYGLTF_TYPE_SCALAR,
             {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
              TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
    out.resize(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      const unsigned char* p = v.data + i * v.stride;
      uint32_t index = 0;
      if (v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        index = *p;
      } else if (v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t s;
        std::memcpy(&s, p, sizeof s);
        index = s;
      } else {
        std::memcpy(&index, p, sizeof index);
      }
      if (index >= vertex_count) {
        fail(where + "index " + std::to_string(index) + " at position " + std::to_string(i) +
             " is out of range (" + std::to_string(vertex_count) + " vertices)");
      }
      out[i] = index;
    }
    return out;
  }

  Scene& scene_;
  const tinygltf::Model& model_;
  std::string source_;
  std::optional<uint32_t> default_material_;
  std::vector<bool> visited_;
  std::vector<std::optional<std::vector<LocalTriangle>>> mesh_cache_;
};

std::string trim(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

}  // namespace

void load_gltf(Scene& scene, const fs::path& file) {
  const std::string source = file.string();
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".gltf" && ext != ".glb") {
    throw SceneError(source + ": unsupported extension '" + ext + "' (expected .gltf or .glb)");
  }
  require_regular_file(file);

  gltf_preflight(file, ext == ".glb");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  tinygltf::Model model;
  std::string err;
  std::string warn;
  const bool ok = ext == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, source)
                                : loader.LoadASCIIFromFile(&model, &err, &warn, source);
  if (!ok || !err.empty()) {
    err = trim(err);
    throw SceneError(source + ": " + (err.empty() ? "tinygltf failed to load the file" : err));
  }
  std::vector<std::string> warnings;
  std::istringstream lines(warn);
  for (std::string line; std::getline(lines, line);) {
    line = trim(line);
    if (!line.empty()) warnings.push_back(source + ": " + line);
  }

  Scene part;  // see append_validated
  part.warnings = std::move(warnings);
  GltfReader(part, model, source).run();
  append_validated(scene, std::move(part), source);
}

}  // namespace strata::scenes
