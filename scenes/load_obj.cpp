#include "scenes/load_obj.h"

#include "scenes/obj_line_check.h"
#include "scenes/validate.h"

#include <tiny_obj_loader.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

namespace strata::scenes {

namespace fs = std::filesystem;

namespace {

// Resolves `mtllib` names against the OBJ's directory and remembers the ones that are
// missing, so the warning can name them. (tinyobjloader's own file reader splits its
// search path on ':' and only says "Failed to load material file(s)".)
class MtlReader : public tinyobj::MaterialReader {
 public:
  explicit MtlReader(fs::path dir) : dir_(std::move(dir)) {}

  bool operator()(const std::string& mtl_name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* name_to_id, std::string* warn,
                  std::string* err) override {
    const fs::path path = dir_ / mtl_name;
    std::error_code ec;
    if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {  // a FIFO would block the open
      missing.push_back(path.string() + " (not a regular file)");
      return false;
    }
    std::ifstream in(path);
    if (!in) {
      missing.push_back(path.string());
      return false;
    }
    try {
      check_mtl_lines(in, path.string());
    } catch (const SceneError& e) {  // thrown by load_obj once tinyobjloader has returned
      if (error.empty()) error = e.what();
      return false;
    }
    tinyobj::LoadMtl(name_to_id, materials, &in, warn, err);
    return true;
  }

  std::vector<std::string> missing;
  std::string error;  // the first .mtl refused, if any

 private:
  fs::path dir_;
};

// A file cut off mid-line is the commonest corruption, and tinyobjloader reads a cut
// "v 1.5 2" as z = 0 without complaint; a missing final newline is the cheap tell.
bool ends_without_newline(std::ifstream& in) {
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  bool result = false;
  if (size > 0) {
    in.seekg(-1, std::ios::end);
    result = in.get() != '\n';
  }
  in.clear();
  in.seekg(0, std::ios::beg);
  return result;
}

// Splits tinyobjloader's warning text into lines. Lines that mean the geometry is wrong
// become errors; lines about materials are collected so a missing .mtl gives one warning,
// not one per usemtl; the rest are passed on, each distinct line once with a count.
void surface_warnings(Scene& scene, const std::string& source, const std::string& text) {
  std::vector<std::pair<std::string, int>> lines;
  std::vector<std::string> unknown_materials;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    // tinyobjloader writes "Degenerated face found\n." so strip stray dots and blanks.
    const size_t b = line.find_first_not_of(" .\t\r");
    if (b == std::string::npos) continue;
    line = line.substr(b);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();

    if (line.find("Vertex indices out of bounds") != std::string::npos ||
        line.find("Face with invalid vertex index") != std::string::npos) {
      throw SceneError(source + ": " + line + " (truncated or corrupt file?)");
    }
    if (line.rfind("Failed to load material file", 0) == 0) continue;  // reported by MtlReader
    // A material with both dissolve (d) and transparency (Tr): the renderer uses neither (only
    // Kd), so the note is noise (Sibenik's .mtl repeats it for 13 materials).
    if (line.rfind("Both `d` and `Tr` parameters defined", 0) == 0) continue;
    const std::string prefix = "material [ '";
    if (line.rfind(prefix, 0) == 0) {
      const size_t end = line.find("' ]", prefix.size());
      unknown_materials.push_back(line.substr(prefix.size(), end - prefix.size()));
      continue;
    }
    auto it = std::find_if(lines.begin(), lines.end(),
                           [&line](const auto& l) { return l.first == line; });
    if (it == lines.end()) {
      lines.emplace_back(line, 1);
    } else {
      ++it->second;
    }
  }
  for (const auto& [msg, count] : lines) {
    scene.warnings.push_back(source + ": " + msg +
                             (count > 1 ? " (x" + std::to_string(count) + ")" : ""));
  }
  if (!unknown_materials.empty()) {
    std::string names;
    for (const std::string& n : unknown_materials) names += (names.empty() ? "" : ", ") + n;
    scene.warnings.push_back(source + ": usemtl names not defined by any loaded .mtl, " +
                             "using the default material: " + names);
  }
}

}  // namespace

void load_obj(Scene& scene, const fs::path& file) {
  const std::string source = file.string();
  require_regular_file(file);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(source + ": cannot open file");
  const bool truncated_tail = ends_without_newline(in);
  check_obj_lines(in, source);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> obj_materials;
  std::string warn;
  std::string err;
  MtlReader mtl_reader(file.parent_path());
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &obj_materials, &warn, &err, &in, &mtl_reader,
                                   /*triangulate=*/true,
                                   /*default_vcols_fallback=*/false);
  if (!mtl_reader.error.empty()) throw SceneError(mtl_reader.error);
  if (!ok || !err.empty()) {
    while (!err.empty() && (err.back() == '\n' || err.back() == '.')) err.pop_back();
    throw SceneError(source + ": parse error: " + (err.empty() ? "unknown" : err));
  }
  Scene part;  // see append_validated
  for (const std::string& missing : mtl_reader.missing) {
    part.warnings.push_back(source + ": material library " + missing +
                            " not found; its faces use the default material");
  }
  surface_warnings(part, source, warn);
  if (truncated_tail) {
    part.warnings.push_back(source + ": last line has no newline; the file may be truncated");
  }

  for (const tinyobj::material_t& m : obj_materials) {
    const glm::vec3 kd{m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    // A Lambertian albedo above 1 would create energy; NaN would poison every pixel.
    const glm::vec3 albedo =
        glm::clamp(glm::vec3(std::isnan(kd.x) ? 0.0f : kd.x, std::isnan(kd.y) ? 0.0f : kd.y,
                             std::isnan(kd.z) ? 0.0f : kd.z),
                   0.0f, 1.0f);
    if (albedo != kd) {
      part.warnings.push_back(source + ": material '" + m.name + "': Kd outside [0,1], clamped");
    }
    part.materials.push_back(Material{m.name, albedo});
  }
  // Added only if some face needs it, so a fully textured file gets no stray material.
  int64_t default_material = -1;
  auto material_for = [&](int id) -> uint32_t {
    if (id >= 0 && static_cast<size_t>(id) < obj_materials.size()) {
      return static_cast<uint32_t>(id);  // added first, in order
    }
    if (default_material < 0) {
      default_material = static_cast<int64_t>(part.materials.size());
      part.materials.push_back(Material{"default", {0.8f, 0.8f, 0.8f}});
    }
    return static_cast<uint32_t>(default_material);
  };

  const size_t vertex_count = attrib.vertices.size() / 3;
  auto vertex = [&](const tinyobj::index_t& idx, const std::string& shape) -> glm::vec3 {
    // Negative (relative) indices that reach before the first vertex come back negative.
    if (idx.vertex_index < 0 || static_cast<size_t>(idx.vertex_index) >= vertex_count) {
      throw SceneError(source + ": object '" + shape + "' has a face referencing vertex " +
                       std::to_string(int64_t{idx.vertex_index} + 1) + " but the file has " +
                       std::to_string(vertex_count) + " vertices");
    }
    const float* p = &attrib.vertices[3 * static_cast<size_t>(idx.vertex_index)];
    return {p[0], p[1], p[2]};
  };

  size_t total = 0;
  for (const tinyobj::shape_t& s : shapes) total += s.mesh.material_ids.size();
  part.triangles.reserve(total);

  for (const tinyobj::shape_t& shape : shapes) {
    const tinyobj::mesh_t& mesh = shape.mesh;
    size_t offset = 0;
    for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
      const size_t n = mesh.num_face_vertices[f];
      if (offset + n > mesh.indices.size()) {
        throw SceneError(source + ": internal parser inconsistency in object '" + shape.name + "'");
      }
      const uint32_t material =
          material_for(f < mesh.material_ids.size() ? mesh.material_ids[f] : -1);
      // triangulate=true gives n == 3; a fan keeps us correct should that ever change.
      for (size_t k = 1; k + 1 < n; ++k) {
        part.triangles.push_back(Triangle{
            vertex(mesh.indices[offset], shape.name), vertex(mesh.indices[offset + k], shape.name),
            vertex(mesh.indices[offset + k + 1], shape.name), material});
      }
      offset += n;
    }
  }

  append_validated(scene, std::move(part), source);
}

}  // namespace strata::scenes
