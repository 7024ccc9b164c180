#include "world/model.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "world/error.hpp"
#include "world/limits.hpp"
#include "world/text_file.hpp"
#include "world/toml_util.hpp"

namespace npsnet::world {
namespace {

// tinyobjloader reports "... line N ..." in some messages; lift N into our FILE:LINE form.
int line_in(const std::string& msg) {
  static const std::regex re(R"(line\s*[:=]?\s*(\d+))", std::regex::icase);
  std::smatch m;
  return std::regex_search(msg, m, re) ? std::stoi(m[1]) : 0;
}

// Newell's normal: equals the plane of the first three vertices for a planar polygon, and stays
// defined when those three happen to be collinear.
Vec3f newell_normal(const Model& m, const Face& f) {
  Vec3f n(0, 0, 0);
  for (uint32_t k = 0; k < f.count; ++k) {
    const Vec3f& a = m.vertices[m.face_vertices[f.first + k]];
    const Vec3f& b = m.vertices[m.face_vertices[f.first + (k + 1) % f.count]];
    n.x() += (a.y() - b.y()) * (a.z() + b.z());
    n.y() += (a.z() - b.z()) * (a.x() + b.x());
    n.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  const float len = n.norm();
  return len > 0 ? Vec3f(n / len) : Vec3f(0, 0, 0);  // zero: degenerate face (zero area)
}

// tinyobjloader reads `v nan 1 0` or `v abc 1 0` without complaint (abc as 0): every vertex
// line is checked here first, with its line number: 3 to 6 numbers (x y z [w] or x y z r g b),
// each finite and the coordinates within kMaxSizeM.
void check_vertex_lines(std::string_view text, const std::string& fname) {
  std::istringstream in{std::string(text)};
  std::string line;
  std::vector<Problem> problems;
  for (int ln = 1; std::getline(in, line); ++ln) {
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
    std::istringstream ss(line.substr(2));
    std::vector<std::string> tok;
    for (std::string t; ss >> t;) tok.push_back(t);
    if (tok.size() < 3 || tok.size() > 6) {
      problems.push_back({fname, ln, "v", "a vertex needs x y z (got " + std::to_string(tok.size()) + " values)"});
      continue;
    }
    for (size_t i = 0; i < tok.size(); ++i) {
      char* end = nullptr;
      const double v = std::strtod(tok[i].c_str(), &end);
      if (end == tok[i].c_str() || *end != '\0' || !std::isfinite(v)) {
        problems.push_back({fname, ln, "v", "'" + tok[i] + "' is not a finite number"});
        break;
      }
      if (i < 3 && std::abs(v) > kMaxSizeM) {
        problems.push_back({fname, ln, "v", "coordinate " + range_message(-kMaxSizeM, kMaxSizeM, "m", v)});
        break;
      }
    }
  }
  if (!problems.empty()) throw InputError(std::move(problems));
}

}  // namespace

Model load_obj(const std::filesystem::path& file) {
  const std::string fname = file.string();
  if (!file_exists(file)) throw InputError(fname, 0, "model", "file not found");
  return load_obj_text(read_text_file(file, "model"), file);
}

Model load_obj_text(std::string_view text, const std::filesystem::path& file) {
  const std::string fname = file.string();
  check_vertex_lines(text, fname);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> mats;
  std::string warn, err;
  std::string mtl_dir = file.parent_path().string();
  if (!mtl_dir.empty()) mtl_dir += '/';
  tinyobj::MaterialFileReader mtl_reader(mtl_dir);
  std::istringstream in{std::string(text)};
  // Haines' test works on the polygon as modelled: no triangulation.
  if (!tinyobj::LoadObj(&attrib, &shapes, &mats, &warn, &err, &in, &mtl_reader, /*triangulate=*/false,
                        /*default_vcols_fallback=*/true)) {
    throw InputError(fname, line_in(err), "model", err.empty() ? "cannot parse OBJ" : err);
  }
  Model m;
  m.file = fname;
  const size_t nv = attrib.vertices.size() / 3;
  if (nv == 0) throw InputError(fname, 0, "model", "no vertices");
  m.vertices.reserve(nv);
  for (size_t i = 0; i < nv; ++i) {
    Vec3f v(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    if (!v.allFinite()) throw InputError(fname, 0, "model", "vertex " + std::to_string(i + 1) + " is not finite");
    m.vertices.push_back(v);
  }
  for (const auto& shape : shapes) {
    size_t at = 0;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const unsigned n = shape.mesh.num_face_vertices[f];
      Face face;
      face.first = static_cast<uint32_t>(m.face_vertices.size());
      face.count = n;
      for (unsigned k = 0; k < n; ++k) {
        const int vi = shape.mesh.indices[at + k].vertex_index;
        if (vi < 0 || static_cast<size_t>(vi) >= nv)
          throw InputError(fname, 0, "model", "face " + std::to_string(f + 1) + " of '" + shape.name + "' uses a missing vertex");
        m.face_vertices.push_back(static_cast<uint32_t>(vi));
      }
      at += n;
      const int mid = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      if (mid >= 0 && static_cast<size_t>(mid) < mats.size())
        face.color = Vec3f(mats[mid].diffuse[0], mats[mid].diffuse[1], mats[mid].diffuse[2]);
      if (n < 3) continue;  // points and lines are not surfaces
      face.normal = newell_normal(m, face);
      m.faces.push_back(face);
    }
  }
  if (m.faces.empty()) throw InputError(fname, 0, "model", "no faces with 3 or more vertices");
  m.bbox_min = m.bbox_max = m.vertices.front();
  for (const auto& v : m.vertices) {
    m.bbox_min = m.bbox_min.cwiseMin(v);
    m.bbox_max = m.bbox_max.cwiseMax(v);
  }
  m.centre = 0.5f * (m.bbox_min + m.bbox_max);
  for (const auto& v : m.vertices) m.true_radius = std::max(m.true_radius, (v - m.centre).norm());
  return m;
}

int ModelLibrary::load(const std::filesystem::path& file) {
  std::error_code ec;  // a name the system cannot resolve: load_obj says "file not found"
  const std::filesystem::path canon = std::filesystem::weakly_canonical(file, ec);
  const std::string key = ec ? file.lexically_normal().string() : canon.string();
  for (size_t i = 0; i < paths_.size(); ++i)
    if (paths_[i] == key) return static_cast<int>(i);
  models_.push_back(load_obj(file));
  paths_.push_back(key);
  return static_cast<int>(models_.size() - 1);
}

}  // namespace npsnet::world
