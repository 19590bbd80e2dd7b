#include "forward/obj_writer.hpp"

#include <charconv>
#include <cmath>

#include "forward/palette.hpp"
#include "graph/atomic_file.hpp"
#include "graph/error.hpp"
#include "graph/number_format.hpp"

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

// The mesh each label inserts: the library's, or its box for unknown names.
std::vector<const Mesh*> meshes_by_label(const Scene& scene, const PrimitiveLibrary& library) {
  std::vector<const Mesh*> meshes(scene.labels.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const Mesh* m = library.find(scene.labels[i]);
    meshes[i] = m != nullptr ? m : &library.box();
  }
  return meshes;
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

std::size_t estimated_size(const Scene& scene, const std::vector<const Mesh*>& meshes) {
  std::size_t bytes = 256;
  for (const Variant& v : scene.variants) {
    bytes += v.name.size() + 4;
    for (const Terminal& t : v.terminals) {
      const Mesh& m = *meshes[t.label];
      // about 3 numbers of up to 20 characters per vertex and normal, short uv numbers
      bytes += 60 * (m.positions.size() + m.normals.size()) + 24 * m.uvs.size() + 24 * m.corners.size() +
               4 * m.face_sizes.size() + 2 * scene.labels[t.label].size() + 32;
    }
  }
  return bytes;
}

}  // namespace

std::string obj_text(const Scene& scene, const PrimitiveLibrary& library, const std::string& mtl_file_name,
                     UpAxis up) {
  const MaterialTable materials(scene);  // also checks every terminal's label
  const std::vector<const Mesh*> meshes = meshes_by_label(scene, library);

  std::string out;
  out.reserve(estimated_size(scene, meshes));
  out += "# Written by Vernacular: one object per terminal, named by its label.\n";
  out += "# up ";
  out += up_axis_name(up);
  out += '\n';
  if (!mtl_file_name.empty()) out += "mtllib " + mtl_file_name + "\n";

  std::uint64_t positions = 0, uvs = 0, normals = 0;  // written so far
  for (const Variant& variant : scene.variants) {
    out += "# " + variant.name + "\n";
    for (const Terminal& t : variant.terminals) {
      const Mesh& mesh = *meshes[t.label];
      out += "o ";
      out += scene.labels[t.label];
      out += "\nusemtl ";
      out += materials.materials()[materials.index_of(t)].name;
      out += '\n';
      for (const glm::dvec3& p : mesh.positions) append_vec3(out, "v", from_z_up(t.scope.to_world(p) + variant.offset, up));
      for (const glm::dvec2& uv : mesh.uvs) {
        out += "vt ";
        append_number(out, uv.x);
        out += ' ';
        append_number(out, uv.y);
        out += '\n';
      }
      const NormalMap to_world(t.scope);
      for (const glm::dvec3& n : mesh.normals) append_vec3(out, "vn", from_z_up(to_world(n), up));

      std::size_t corner = 0;
      for (std::uint32_t size : mesh.face_sizes) {
        out += 'f';
        for (std::uint32_t k = 0; k < size; ++k, ++corner) {
          const Mesh::Corner& c = mesh.corners[corner];
          out += ' ';
          append_index(out, positions + c.position + 1);
          if (c.uv != Mesh::kNone || c.normal != Mesh::kNone) {
            out += '/';
            if (c.uv != Mesh::kNone) append_index(out, uvs + c.uv + 1);
            if (c.normal != Mesh::kNone) {
              out += '/';
              append_index(out, normals + c.normal + 1);
            }
          }
        }
        out += '\n';
      }
      positions += mesh.positions.size();
      uvs += mesh.uvs.size();
      normals += mesh.normals.size();
    }
  }
  return out;
}

std::string mtl_text(const Scene& scene) {
  const MaterialTable materials(scene);
  std::string out = "# Written by Vernacular: one material per label or colour.\n";
  for (const Material& m : materials.materials()) {
    out += "\nnewmtl " + m.name + "\n";
    // A matte surface in the material's colour.
    const std::array<double, 3> c = colour_components(m.colour);
    append_vec3(out, "Kd", glm::dvec3(c[0], c[1], c[2]));
    out += "Ka 0 0 0\nKs 0 0 0\nd 1\nillum 1\n";
  }
  return out;
}

std::filesystem::path mtl_path_for(const std::filesystem::path& obj_path) {
  return std::filesystem::path(obj_path).replace_extension(".mtl");
}

void write_obj(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& obj_path,
               OutputFiles& outputs, UpAxis up) {
  const std::filesystem::path mtl_path = mtl_path_for(obj_path);
  if (mtl_path == obj_path) {
    fail(ErrorKind::Usage, obj_path.string(), {}, "the OBJ file would overwrite its own MTL file",
         "give the output an .obj extension");
  }
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
