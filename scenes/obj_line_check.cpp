#include "scenes/obj_line_check.h"

#include "scenes/scene.h"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace strata::scenes {
namespace {

// Finite as the float32 the scene stores (1e39 is a finite double but an infinite float);
// an underflow to zero or a subnormal is fine.
bool finite_number(const std::string& token) {
  if (token.empty()) return false;
  const char* begin = token.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  return end == begin + token.size() && std::isfinite(v) && std::fabs(v) <= double(FLT_MAX);
}

// The vertex part of a face token ("7", "7/2", "-1//3"): a whole number, kept in 64 bits.
bool vertex_index(const std::string& token, int64_t* index) {
  const std::string v = token.substr(0, token.find('/'));
  if (v.empty()) return false;
  const char* begin = v.c_str();
  char* end = nullptr;
  errno = 0;
  const long long i = std::strtoll(begin, &end, 10);
  if (end != begin + v.size() || errno == ERANGE) return false;
  *index = i;
  return true;
}

struct PendingIndex {
  int64_t index;
  size_t line;
};

struct Vec {
  double x, y, z;
};
Vec sub(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec cross(const Vec& a, const Vec& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// A polygon of more than 3 vertices that tinyobjloader's fan would triangulate wrongly: not
// convex in its own plane (Newell's normal; every corner must turn the same way). Collinear
// corners are allowed; a polygon that is not planar enough to have a normal is left alone.
bool concave(const std::vector<Vec>& p) {
  Vec n{0, 0, 0};
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec& a = p[i];
    const Vec& b = p[(i + 1) % p.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  const double scale = dot(n, n);
  if (!(scale > 0)) return false;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec e0 = sub(p[(i + 1) % p.size()], p[i]);
    const Vec e1 = sub(p[(i + 2) % p.size()], p[(i + 1) % p.size()]);
    // Relative to the polygon's size, so that rounding on a collinear corner is not a reflex one.
    if (dot(cross(e0, e1), n) < -1e-9 * scale) return true;
  }
  return false;
}

}  // namespace

void check_obj_lines(std::istream& in, const std::string& source) {
  auto fail = [&](size_t line, const std::string& why) {
    throw SceneError(source + ":" + std::to_string(line) + ": parse error: " + why);
  };
  std::string text;
  size_t line_no = 0;
  int64_t vertices = 0;
  std::vector<PendingIndex> forward;  // positive indices beyond the vertices seen so far
  std::vector<Vec> positions;
  struct Polygon {
    std::vector<int64_t> index;  // 0-based
    size_t line;
  };
  std::vector<Polygon> polygons;  // faces of more than 3 vertices, checked once all are read
  while (std::getline(in, text)) {
    ++line_no;
    std::istringstream words(text);
    std::string key;
    if (!(words >> key)) continue;
    if (key == "v") {
      std::vector<std::string> values;
      for (std::string w; words >> w;) values.push_back(w);
      if (values.size() < 3) fail(line_no, "vertex has " + std::to_string(values.size()) + " coordinates, needs 3");
      for (size_t i = 0; i < values.size(); ++i)
        if (!finite_number(values[i]))
          fail(line_no, "vertex " + std::string(i < 3 ? "coordinate" : "value") + " '" + values[i] +
                            "' is not a finite number");
      ++vertices;
      positions.push_back({std::strtod(values[0].c_str(), nullptr), std::strtod(values[1].c_str(), nullptr),
                           std::strtod(values[2].c_str(), nullptr)});
    } else if (key == "f" || key == "l" || key == "p") {
      Polygon poly{{}, line_no};
      for (std::string w; words >> w;) {
        int64_t i = 0;
        if (!vertex_index(w, &i)) fail(line_no, "index '" + w + "' is not a whole number");
        if (i == 0) fail(line_no, "index 0: OBJ indices start at 1");
        if (i < 0 && -i > vertices)
          fail(line_no, "relative index " + std::to_string(i) + " reaches before the first vertex (" +
                            std::to_string(vertices) + " defined so far)");
        if (i > vertices) forward.push_back({i, line_no});
        poly.index.push_back(i < 0 ? vertices + i : i - 1);
      }
      if (key == "f" && poly.index.size() > 3) polygons.push_back(std::move(poly));
    }
  }
  for (const PendingIndex& p : forward)
    if (p.index > vertices)
      fail(p.line, "index " + std::to_string(p.index) + " is beyond the file's " + std::to_string(vertices) +
                       " vertices");
  for (const Polygon& poly : polygons) {
    std::vector<Vec> p;
    for (int64_t i : poly.index) p.push_back(positions[static_cast<size_t>(i)]);
    if (concave(p))
      fail(poly.line, "a concave polygon of " + std::to_string(p.size()) +
                          " vertices: it would be triangulated as a fan, wrongly; split it into convex "
                          "polygons or triangles");
  }
  in.clear();
  in.seekg(0, std::ios::beg);
}

void check_mtl_lines(std::istream& in, const std::string& source) {
  // The fields tinyobjloader reads as numbers (colours, exponents, PBR factors).
  static const char* const kNumeric[] = {"Ka", "Kd", "Ks", "Kt", "Ke", "Tf", "Ni", "Ns", "d",     "Tr",
                                         "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "illum"};
  std::string text, material;
  size_t line_no = 0;
  while (std::getline(in, text)) {
    ++line_no;
    std::istringstream words(text);
    std::string key;
    if (!(words >> key)) continue;
    if (key == "newmtl") {
      std::getline(words >> std::ws, material);
      continue;
    }
    bool numeric = false;
    for (const char* k : kNumeric) numeric = numeric || key == k;
    if (!numeric) continue;
    for (std::string w; words >> w;) {
      char* end = nullptr;
      (void)std::strtod(w.c_str(), &end);
      const bool a_number = !w.empty() && end == w.c_str() + w.size();
      if (a_number && !finite_number(w))
        throw SceneError(source + ":" + std::to_string(line_no) + ": material '" + material + "': " + key +
                         " value '" + w + "' is not a finite number");
    }
  }
  in.clear();
  in.seekg(0, std::ios::beg);
}

}  // namespace strata::scenes
