#include "io/obj_writer.hpp"

#include <charconv>
#include <cmath>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "base/number_format.hpp"
#include "graph/label.hpp"
#include "io/palette.hpp"

namespace vern {

namespace {

void append_index(std::string& out, std::uint64_t i) {
  char buf[24];
  const auto printed = std::to_chars(buf, buf + sizeof buf, i);
  out.append(buf, printed.ptr);
}

void append_vec3(std::string& out, const char* keyword, const glm::dvec3& v) {
  out += keyword;
  for (glm::length_t i = 0; i < 3; ++i) {
    out += ' ';
    append_number(out, v[i]);
  }
  out += '\n';
}

// Maps a unit-box normal into world space for a scope. A scope stretches
// its mesh by size along its frame, so normals follow the inverse transpose
// frame * diag(1/size); scaled by the determinant that is
// frame * diag(sy*sz, sx*sz, sx*sy), which stays defined when a size is 0
// (a flattened mesh faces along its flat axis).
struct NormalMap {
  glm::dmat3 frame;
  glm::dvec3 factor;

  explicit NormalMap(const Scope& s) : frame(s.frame) {
    const glm::dvec3 a = glm::abs(s.size);
    factor = glm::dvec3(a.y * a.z, a.x * a.z, a.x * a.y);
    for (glm::length_t i = 0; i < 3; ++i) {
      if (s.size[i] < 0) factor[i] = -factor[i];
    }
  }

  glm::dvec3 operator()(const glm::dvec3& n) const {
    glm::dvec3 w = frame * (n * factor);
    double length = glm::length(w);
    if (!(length > 0.0)) {  // two or three sizes are 0: no shape left to face anywhere
      w = frame * n;
      length = glm::length(w);
    }
    return length > 0.0 ? w / length : n;
  }
};

std::string mtl_text_of(const std::vector<Material>& materials) {
  std::string out = "# Written by Vernacular: one material per label or colour.\n";
  for (const Material& m : materials) {
    out += "\nnewmtl " + m.name + "\n";
    // A matte surface in the material's colour.
    const std::array<double, 3> c = colour_components(m.colour);
    append_vec3(out, "Kd", glm::dvec3(c[0], c[1], c[2]));
    out += "Ka 0 0 0\nKs 0 0 0\nd 1\nillum 1\n";
  }
  return out;
}

// Text is passed on once this much has gathered.
constexpr std::size_t kPiece = 1 << 20;

}  // namespace

ObjStream::ObjStream(std::vector<std::string> labels, const PrimitiveLibrary& library, const std::string& mtl_file_name,
                     std::function<void(std::string_view)> write, UpAxis up)
    : labels_(std::move(labels)), materials_(labels_.size()), write_(std::move(write)), up_(up) {
  // The mesh each label inserts: the library's, or its box for unknown names.
  meshes_.resize(labels_.size());
  names_.reserve(labels_.size());
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    const Mesh* m = library.find(labels_[i]);
    meshes_[i] = m != nullptr ? m : &library.box();
    names_.push_back(name_in_file(labels_[i]));
  }
  out_ += "# Written by Vernacular: one object per terminal, named by its label.\n";
  out_ += "# up ";
  out_ += up_axis_name(up_);
  out_ += '\n';
  if (!mtl_file_name.empty()) out_ += "mtllib " + mtl_file_name + "\n";
}

void ObjStream::add(const Variant& variant) {
  std::string& out = out_;
  // A group per variant: a file of several buildings reads back as its
  // buildings (inverse/load/scene_buildings.hpp), as its glTF does.
  out += "g " + variant.name + "\n";
  for (const Terminal& t : variant.terminals) {
    const std::uint32_t material = materials_.intern(t, labels_);  // also checks the label
    const Mesh& mesh = *meshes_[t.label];
    out += "o ";
    out += names_[t.label];
    out += "\nusemtl ";
    out += materials_.materials()[material].name;
    out += '\n';
    for (const glm::dvec3& p : mesh.positions) append_vec3(out, "v", from_z_up(t.scope.to_world(p) + variant.offset, up_));
    for (const glm::dvec2& uv : mesh.uvs) {
      out += "vt ";
      append_number(out, uv.x);
      out += ' ';
      append_number(out, uv.y);
      out += '\n';
    }
    const NormalMap to_world(t.scope);
    for (const glm::dvec3& n : mesh.normals) append_vec3(out, "vn", from_z_up(to_world(n), up_));

    std::size_t corner = 0;
    for (std::uint32_t size : mesh.face_sizes) {
      out += 'f';
      for (std::uint32_t k = 0; k < size; ++k, ++corner) {
        const Mesh::Corner& c = mesh.corners[corner];
        out += ' ';
        append_index(out, positions_ + c.position + 1);
        if (c.uv != Mesh::kNone || c.normal != Mesh::kNone) {
          out += '/';
          if (c.uv != Mesh::kNone) append_index(out, uvs_ + c.uv + 1);
          if (c.normal != Mesh::kNone) {
            out += '/';
            append_index(out, normals_ + c.normal + 1);
          }
        }
      }
      out += '\n';
    }
    positions_ += mesh.positions.size();
    uvs_ += mesh.uvs.size();
    normals_ += mesh.normals.size();
    if (out.size() >= kPiece) flush();
  }
}

void ObjStream::flush() {
  if (!out_.empty()) write_(out_);
  out_.clear();
}

std::string ObjStream::mtl_text() const { return mtl_text_of(materials_.materials()); }

std::string obj_text(const Scene& scene, const PrimitiveLibrary& library, const std::string& mtl_file_name,
                     UpAxis up) {
  std::string text;
  ObjStream stream(scene.labels, library, mtl_file_name, [&](std::string_view piece) { text.append(piece); }, up);
  for (const Variant& v : scene.variants) stream.add(v);
  stream.flush();
  return text;
}

std::string mtl_text(const Scene& scene) { return mtl_text_of(MaterialTable(scene).materials()); }

std::filesystem::path mtl_path_for(const std::filesystem::path& obj_path) {
  return std::filesystem::path(obj_path).replace_extension(".mtl");
}

void check_obj_path(const std::filesystem::path& obj_path) {
  if (mtl_path_for(obj_path) == obj_path) {
    fail(ErrorKind::Usage, obj_path.string(), {}, "the OBJ file would overwrite its own MTL file",
         "give the output an .obj extension");
  }
}

void write_obj(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& obj_path,
               OutputFiles& outputs, UpAxis up) {
  check_obj_path(obj_path);
  const std::filesystem::path mtl_path = mtl_path_for(obj_path);
  outputs.stage(mtl_path, mtl_text(scene));
  outputs.stage(obj_path, obj_text(scene, library, mtl_path.filename().string(), up));
}

void write_obj(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& obj_path,
               UpAxis up) {
  OutputFiles outputs;
  write_obj(scene, library, obj_path, outputs, up);
  outputs.commit();
}

}  // namespace vern
