#include "forward/primitive_library.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

// OpenMesh stays in this file: it is slow to compile and its types would
// leak into every user of the library.
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "base/error.hpp"
#include "base/folder_confinement.hpp"
#include "base/input_file.hpp"
#include "forward/builtin_primitives.hpp"
#include "graph/label.hpp"
#include "io/obj_reader.hpp"

namespace vern {

namespace {

struct OmTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<OmTraits>;

// Appends b's faces to a, offsetting b's indices.
void append_mesh(Mesh& a, const Mesh& b) {
  const auto positions = static_cast<std::uint32_t>(a.positions.size());
  const auto normals = static_cast<std::uint32_t>(a.normals.size());
  const auto uvs = static_cast<std::uint32_t>(a.uvs.size());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
  a.uvs.insert(a.uvs.end(), b.uvs.begin(), b.uvs.end());
  a.face_sizes.insert(a.face_sizes.end(), b.face_sizes.begin(), b.face_sizes.end());
  for (Mesh::Corner c : b.corners) {
    c.position += positions;
    if (c.normal != Mesh::kNone) c.normal += normals;
    if (c.uv != Mesh::kNone) c.uv += uvs;
    a.corners.push_back(c);
  }
}

// Flat normals of the given faces (by index), computed by OpenMesh. Each
// face gets its own vertices: faces of an arbitrary OBJ need not form a
// manifold, and a lone polygon always does.
std::vector<glm::dvec3> face_normals(const Mesh& mesh, const std::vector<std::uint32_t>& faces,
                                     const std::vector<std::uint32_t>& face_start) {
  OmMesh om;
  std::vector<OmMesh::FaceHandle> handles;
  handles.reserve(faces.size());
  std::vector<OmMesh::VertexHandle> corners;
  for (std::uint32_t f : faces) {
    corners.clear();
    for (std::uint32_t c = 0; c < mesh.face_sizes[f]; ++c) {
      const glm::dvec3& p = mesh.positions[mesh.corners[face_start[f] + c].position];
      corners.push_back(om.add_vertex(OmMesh::Point(p.x, p.y, p.z)));
    }
    handles.push_back(om.add_face(corners));
  }
  std::vector<glm::dvec3> normals;
  normals.reserve(faces.size());
  for (const OmMesh::FaceHandle& fh : handles) {
    glm::dvec3 n(0.0);
    if (fh.is_valid()) {
      const OmMesh::Normal v = om.calc_face_normal(fh);
      n = glm::dvec3(v[0], v[1], v[2]);
    }
    // A face without area has no direction; any unit normal will do.
    const double length = glm::length(n);
    normals.push_back(std::isfinite(length) && length > 0.5 ? n / length : glm::dvec3(0, 0, 1));
  }
  return normals;
}

bool has_obj_extension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".obj";
}

Mesh merged(const std::vector<ObjObject>& objects) {
  Mesh mesh;
  for (const ObjObject& o : objects) append_mesh(mesh, o.mesh);
  return mesh;
}

}  // namespace

Mesh normalised_primitive(Mesh mesh) {
  // Fit the bounds onto the unit box. (p - lo) / (hi - lo) is exactly 1 at
  // p == hi, so the box is filled exactly, not to within rounding.
  const glm::dvec3 lo = mesh.min_corner();
  const glm::dvec3 extent = mesh.max_corner() - lo;
  for (glm::dvec3& p : mesh.positions) {
    for (glm::length_t i = 0; i < 3; ++i) p[i] = extent[i] > 0.0 ? (p[i] - lo[i]) / extent[i] : 0.0;
  }

  // Normals follow the inverse transpose of that scaling (a flat axis is
  // left as it is: the mesh's faces all face along it anyway). Normals that
  // end up unusable are recomputed below.
  const glm::dvec3 normal_scale(extent.x > 0 ? extent.x : 1.0, extent.y > 0 ? extent.y : 1.0,
                                extent.z > 0 ? extent.z : 1.0);
  std::vector<bool> usable(mesh.normals.size(), true);
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    const glm::dvec3 n = mesh.normals[i] * normal_scale;
    const double length = glm::length(n);
    if (std::isfinite(length) && length > 0.0) {
      mesh.normals[i] = n / length;
    } else {
      usable[i] = false;
    }
  }

  // Faces with a corner lacking a usable normal get a flat one.
  std::vector<std::uint32_t> face_start(mesh.face_sizes.size());
  std::vector<std::uint32_t> needy;
  std::uint32_t start = 0;
  for (std::uint32_t f = 0; f < mesh.face_sizes.size(); ++f) {
    face_start[f] = start;
    for (std::uint32_t c = start; c < start + mesh.face_sizes[f]; ++c) {
      const std::uint32_t n = mesh.corners[c].normal;
      if (n == Mesh::kNone || !usable[n]) {
        needy.push_back(f);
        break;
      }
    }
    start += mesh.face_sizes[f];
  }
  if (!needy.empty()) {
    const std::vector<glm::dvec3> flat = face_normals(mesh, needy, face_start);
    for (std::size_t k = 0; k < needy.size(); ++k) {
      const std::uint32_t f = needy[k];
      const auto index = static_cast<std::uint32_t>(mesh.normals.size());
      mesh.normals.push_back(flat[k]);
      for (std::uint32_t c = face_start[f]; c < face_start[f] + mesh.face_sizes[f]; ++c) {
        const std::uint32_t n = mesh.corners[c].normal;
        if (n == Mesh::kNone || !usable[n]) mesh.corners[c].normal = index;
      }
    }
  }
  return mesh;
}

PrimitiveLibrary PrimitiveLibrary::builtin() {
  static const PrimitiveLibrary parsed = [] {
    PrimitiveLibrary lib;
    for (const EmbeddedPrimitive& source : builtin_primitive_sources()) {
      if (source.name.empty()) continue;
      std::istringstream in{std::string(source.obj_text)};
      const std::string name(source.name);
      try {
        lib.add(name, merged(read_obj(in, "built-in primitive " + name)));
      } catch (const Error& e) {
        throw Error(ErrorKind::Internal, std::string(e.what()) + "\n  (a broken file in data/primitives/)");
      }
    }
    return lib;
  }();
  return parsed;
}

void PrimitiveLibrary::load(const std::filesystem::path& path, const std::optional<std::filesystem::path>& within) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    // Missing, or it cannot be told: a link that leads to itself, a folder
    // on the way that cannot be entered.
    fail(ErrorKind::Io, path.string(), {},
         status.type() == fs::file_type::not_found || !ec ? "no such file or folder" : "cannot read: " + ec.message(),
         "give an .obj file or a folder of .obj files, one per primitive");
  }
  if (!fs::is_directory(status)) {
    std::map<std::string, Mesh> by_name;  // merges objects sharing a name
    std::vector<std::string> order;
    for (ObjObject& o : read_obj_file(path)) {
      std::string name;
      if (o.name.empty()) {
        name = path.stem().string();
        require_label(name, path.string(), {o.line, 1}, "the file's name '" + shown_name(name) + "', which names "
                                                            "the faces before its first object,");
      } else {
        name = read_label(o.name, NameOf::Primitive, path.string(), {o.line, 1}, "the object name");
      }
      auto [it, fresh] = by_name.try_emplace(name);
      if (fresh) order.push_back(name);
      append_mesh(it->second, o.mesh);
    }
    if (order.empty()) {
      fail(ErrorKind::Input, path.string(), {}, "the file has no faces, so it defines no primitive",
           "export the primitive meshes with their faces");
    }
    for (const std::string& name : order) add(name, std::move(by_name[name]));
    return;
  }

  const std::vector<fs::path> files = regular_files_in(path, has_obj_extension, "an .obj file");
  if (files.empty()) {
    fail(ErrorKind::Input, path.string(), {}, "the folder holds no .obj files",
         "put one .obj file per primitive in it, named after the primitive");
  }
  for (const fs::path& file : files) {
    // The folder is in bounds; a link in it may still lead out.
    if (within && !leads_into_folder(file, *within)) {
      fail(ErrorKind::Input, file.string(), {}, "is a link that leads outside the folder of the grammar that names it",
           "a grammar's @primitives may name files in its own folder or below it only: copy the file there, or "
           "pass --allow-outside-files if you trust this grammar");
    }
    const std::string name = file.stem().string();
    require_label(name, file.string(), {}, "the file's name '" + shown_name(name) + "'");
    Mesh mesh = merged(read_obj_file(file));
    if (mesh.face_sizes.empty()) {
      fail(ErrorKind::Input, file.string(), {}, "the file has no faces, so it defines no primitive",
           "export the primitive's mesh with its faces");
    }
    add(name, std::move(mesh));
  }
}

void PrimitiveLibrary::add(const std::string& name, Mesh mesh) {
  if (mesh.face_sizes.empty()) {
    fail(ErrorKind::Input, name, {}, "the primitive mesh has no faces", "give the primitive some faces");
  }
  meshes_[name] = std::make_shared<const Mesh>(normalised_primitive(std::move(mesh)));
}

const Mesh* PrimitiveLibrary::find(std::string_view name) const {
  const auto it = meshes_.find(name);
  return it == meshes_.end() ? nullptr : it->second.get();
}

std::vector<std::string> PrimitiveLibrary::names() const {
  std::vector<std::string> out;
  out.reserve(meshes_.size());
  for (const auto& [name, mesh] : meshes_) out.push_back(name);
  return out;  // std::map keeps them sorted
}

const Mesh& PrimitiveLibrary::box() const {
  if (const Mesh* rect = find("rect")) return *rect;
  // A library built empty still inserts something for unknown names.
  static const PrimitiveLibrary fallback = builtin();
  const Mesh* rect = fallback.find("rect");
  if (rect == nullptr) throw Error(ErrorKind::Internal, "error: the built-in primitive 'rect' is missing");
  return *rect;
}

}  // namespace vern
