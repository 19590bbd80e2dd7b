#include "forward/gltf_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <unordered_map>

// tinygltf stays in this file. Debian's libtinygltf-dev ships the
// implementation compiled as a shared library (TinyGLTF::TinyGLTF), so the
// header is included for declarations only: defining TINYGLTF_IMPLEMENTATION
// here would duplicate it, and clash with any other file that reads glTF.
#include <tiny_gltf.h>

#include "forward/palette.hpp"
#include "graph/atomic_file.hpp"
#include "graph/error.hpp"

namespace vern {

namespace {

// A primitive's mesh as glTF wants it: one vertex per distinct
// (position, normal, uv) corner, triangles indexing them.
struct Triangles {
  std::vector<float> positions;  // xyz
  std::vector<float> normals;    // xyz
  std::vector<float> uvs;        // uv, v pointing down (glTF's convention)
  std::vector<std::uint32_t> indices;
  bool has_uvs = false;
};

Triangles triangulate(const Mesh& mesh) {
  Triangles out;
  for (const Mesh::Corner& c : mesh.corners) out.has_uvs = out.has_uvs || c.uv != Mesh::kNone;
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> vertex_of;
  auto vertex = [&](const Mesh::Corner& c) {
    const auto [it, fresh] =
        vertex_of.try_emplace({c.position, c.normal, c.uv}, static_cast<std::uint32_t>(vertex_of.size()));
    if (fresh) {
      const glm::dvec3& p = mesh.positions[c.position];
      // The library gives every corner a normal; the fallback only guards.
      const glm::dvec3 n = c.normal != Mesh::kNone ? mesh.normals[c.normal] : glm::dvec3(0, 0, 1);
      const glm::dvec2 t = c.uv != Mesh::kNone ? mesh.uvs[c.uv] : glm::dvec2(0.0);
      for (glm::length_t i = 0; i < 3; ++i) {
        out.positions.push_back(static_cast<float>(p[i]));
        out.normals.push_back(static_cast<float>(n[i]));
      }
      out.uvs.push_back(static_cast<float>(t.x));
      out.uvs.push_back(static_cast<float>(1.0 - t.y));
    }
    return it->second;
  };
  std::size_t start = 0;
  for (std::uint32_t size : mesh.face_sizes) {
    const std::uint32_t first = vertex(mesh.corners[start]);
    std::uint32_t previous = vertex(mesh.corners[start + 1]);
    for (std::uint32_t k = 2; k < size; ++k) {
      const std::uint32_t current = vertex(mesh.corners[start + k]);
      out.indices.insert(out.indices.end(), {first, previous, current});
      previous = current;
    }
    start += size;
  }
  return out;
}

// Builds the one buffer, one view per accessor.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) {}

  template <class T>
  int add(const std::vector<T>& values, int component, int type, std::size_t count, int target) {
    std::vector<unsigned char>& data = bytes_;
    while (data.size() % 4 != 0) data.push_back(0);  // accessors align to their component size
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    view.target = target;
    const std::size_t at = data.size();
    data.resize(at + view.byteLength);
    std::memcpy(data.data() + at, values.data(), view.byteLength);  // little-endian hosts only, as glTF
    model_.bufferViews.push_back(view);

    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model_.bufferViews.size() - 1);
    accessor.byteOffset = 0;
    accessor.componentType = component;
    accessor.type = type;
    accessor.count = count;
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size() - 1);
  }

  void finish() {
    if (bytes_.empty()) return;  // a buffer must not be empty
    while (bytes_.size() % 4 != 0) bytes_.push_back(0);
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes_);
    model_.buffers.push_back(std::move(buffer));
  }

 private:
  tinygltf::Model& model_;
  std::vector<unsigned char> bytes_;
};

// The accessors of one primitive's triangles, shared by its meshes.
struct Geometry {
  int position = -1, normal = -1, uv = -1, indices = -1;
};

Geometry add_geometry(const Mesh& mesh, BufferBuilder& buffer, tinygltf::Model& model) {
  const Triangles t = triangulate(mesh);
  const std::size_t vertices = t.positions.size() / 3;
  Geometry g;
  g.position = buffer.add(t.positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices,
                          TINYGLTF_TARGET_ARRAY_BUFFER);
  // The spec requires POSITION bounds; they must be those of the floats stored.
  std::vector<double> lo(3, 0.0), hi(3, 0.0);
  for (std::size_t v = 0; v < vertices; ++v) {
    for (std::size_t i = 0; i < 3; ++i) {
      const double x = t.positions[3 * v + i];
      lo[i] = v == 0 ? x : std::min(lo[i], x);
      hi[i] = v == 0 ? x : std::max(hi[i], x);
    }
  }
  model.accessors[static_cast<std::size_t>(g.position)].minValues = lo;
  model.accessors[static_cast<std::size_t>(g.position)].maxValues = hi;
  g.normal = buffer.add(t.normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices,
                        TINYGLTF_TARGET_ARRAY_BUFFER);
  if (t.has_uvs) {
    g.uv = buffer.add(t.uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, vertices,
                      TINYGLTF_TARGET_ARRAY_BUFFER);
  }
  if (vertices <= 0xffff) {
    std::vector<std::uint16_t> small(t.indices.begin(), t.indices.end());
    g.indices = buffer.add(small, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, small.size(),
                           TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  } else {
    g.indices = buffer.add(t.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                           t.indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  }
  return g;
}

// The matrix mapping the unit box onto a scope, column-major. glTF requires
// node matrices to decompose into translation, rotation and scale, which a
// zero scale (a comp() face: a window on a zero-depth scope) does not, and
// viewers would divide by it to transform normals. So a size that is 0, or
// vanishing next to the scope's largest, becomes a millionth of that
// largest size: invisible, and the flattened mesh still faces the right way.
std::vector<double> scope_matrix(const Scope& s) {
  const double largest = std::max({std::abs(s.size.x), std::abs(s.size.y), std::abs(s.size.z)});
  const double thinnest = largest > 0.0 ? largest * 1e-6 : 1e-6;
  std::vector<double> m(16, 0.0);
  for (int c = 0; c < 3; ++c) {
    const double size = std::abs(s.size[c]) < thinnest ? thinnest : s.size[c];
    const glm::dvec3 axis = s.frame[c] * size;
    for (int r = 0; r < 3; ++r) m[static_cast<std::size_t>(4 * c + r)] = axis[r];
  }
  for (int r = 0; r < 3; ++r) m[static_cast<std::size_t>(12 + r)] = s.origin[r];
  m[15] = 1.0;
  return m;
}

tinygltf::Model build_model(const Scene& scene, const PrimitiveLibrary& library) {
  const MaterialTable materials(scene);  // also checks every terminal's label
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Vernacular";

  for (const Material& m : materials.materials()) {
    tinygltf::Material g;
    g.name = m.name;
    const std::array<double, 3> c = colour_components(m.colour);
    g.pbrMetallicRoughness.baseColorFactor = {c[0], c[1], c[2], 1.0};
    g.pbrMetallicRoughness.metallicFactor = 0.0;  // painted and built surfaces: matte, not metal
    g.pbrMetallicRoughness.roughnessFactor = 0.9;
    model.materials.push_back(std::move(g));
  }

  BufferBuilder buffer(model);
  std::vector<const Mesh*> mesh_of_label(scene.labels.size(), nullptr);
  std::unordered_map<const Mesh*, Geometry> geometry;           // per primitive mesh
  std::map<std::pair<LabelId, std::uint32_t>, int> mesh_index;  // per (label, material)

  tinygltf::Scene root_scene;
  for (const Variant& variant : scene.variants) {
    const auto root = static_cast<int>(model.nodes.size());
    root_scene.nodes.push_back(root);
    {
      tinygltf::Node node;
      node.name = variant.name;
      if (variant.offset != glm::dvec3(0.0)) node.translation = {variant.offset.x, variant.offset.y, variant.offset.z};
      model.nodes.push_back(std::move(node));
    }
    for (const Terminal& t : variant.terminals) {
      const std::uint32_t material = materials.index_of(t);
      auto [it, fresh] = mesh_index.try_emplace({t.label, material}, static_cast<int>(model.meshes.size()));
      if (fresh) {
        const std::string& label = scene.labels[t.label];
        const Mesh*& primitive = mesh_of_label[t.label];
        if (primitive == nullptr) {
          primitive = library.find(label);
          if (primitive == nullptr) primitive = &library.box();
        }
        auto [g, new_geometry] = geometry.try_emplace(primitive);
        if (new_geometry) g->second = add_geometry(*primitive, buffer, model);

        tinygltf::Primitive p;
        p.attributes["POSITION"] = g->second.position;
        p.attributes["NORMAL"] = g->second.normal;
        if (g->second.uv >= 0) p.attributes["TEXCOORD_0"] = g->second.uv;
        p.indices = g->second.indices;
        p.material = static_cast<int>(material);
        p.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh mesh;
        mesh.name = t.coloured ? label + " " + materials.materials()[material].name : label;
        mesh.primitives.push_back(std::move(p));
        model.meshes.push_back(std::move(mesh));
      }
      tinygltf::Node node;
      node.name = scene.labels[t.label];
      node.mesh = it->second;
      node.matrix = scope_matrix(t.scope);
      model.nodes[static_cast<std::size_t>(root)].children.push_back(static_cast<int>(model.nodes.size()));
      model.nodes.push_back(std::move(node));
    }
  }
  buffer.finish();
  model.scenes.push_back(std::move(root_scene));
  model.defaultScene = 0;
  return model;
}

std::string serialise(const tinygltf::Model& model, bool binary) {
  tinygltf::TinyGLTF writer;
  std::ostringstream out;
  if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, binary)) {
    throw Error(ErrorKind::Internal, "error: tinygltf could not serialise the scene");
  }
  return std::move(out).str();
}

}  // namespace

std::string glb_bytes(const Scene& scene, const PrimitiveLibrary& library) {
  return serialise(build_model(scene, library), true);
}

std::string gltf_text(const Scene& scene, const PrimitiveLibrary& library) {
  return serialise(build_model(scene, library), false);
}

void write_gltf(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".glb" || ext == ".GLB") {
    write_file_atomically(path, glb_bytes(scene, library));
  } else if (ext == ".gltf" || ext == ".GLTF") {
    write_file_atomically(path, gltf_text(scene, library));
  } else {
    fail(ErrorKind::Usage, path.string(), {}, "a glTF file ends in .glb (binary) or .gltf (text)",
         "name the output file.glb or file.gltf");
  }
}

GltfSummary summarize_gltf(std::string_view bytes) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = bytes.starts_with("glTF");
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned int>(bytes.size()))
             : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()),
                                          "");
  if (!ok) fail(ErrorKind::Input, "glTF data", {}, "not valid glTF: " + err, "check the file with scripts/validate-gltf");

  GltfSummary s;
  s.generator = model.asset.generator;
  if (!model.scenes.empty()) {
    const auto scene = static_cast<std::size_t>(model.defaultScene >= 0 ? model.defaultScene : 0);
    s.roots = model.scenes.at(scene).nodes;
  }
  for (const tinygltf::Node& n : model.nodes) {
    GltfSummary::Node node;
    node.name = n.name;
    node.mesh = n.mesh;
    node.children = n.children;
    for (std::size_t i = 0; i < 16; ++i) node.matrix[i] = n.matrix.size() == 16 ? n.matrix[i] : (i % 5 == 0 ? 1.0 : 0.0);
    for (std::size_t i = 0; i < 3 && n.translation.size() == 3; ++i) node.translation[i] = n.translation[i];
    s.nodes.push_back(std::move(node));
  }
  for (const tinygltf::Mesh& m : model.meshes) {
    GltfSummary::MeshInfo info;
    info.name = m.name;
    if (!m.primitives.empty()) {
      const tinygltf::Primitive& p = m.primitives.front();
      info.material = p.material;
      const auto pos = p.attributes.find("POSITION");
      if (pos != p.attributes.end()) {
        info.position_accessor = pos->second;
        const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(pos->second));
        info.vertices = a.count;
        for (std::size_t i = 0; i < 3 && a.minValues.size() == 3 && a.maxValues.size() == 3; ++i) {
          info.min[i] = a.minValues[i];
          info.max[i] = a.maxValues[i];
        }
      }
      if (p.indices >= 0) info.indices = model.accessors.at(static_cast<std::size_t>(p.indices)).count;
    }
    s.meshes.push_back(std::move(info));
  }
  for (const tinygltf::Material& m : model.materials) {
    GltfSummary::MaterialInfo info;
    info.name = m.name;
    for (std::size_t i = 0; i < 4 && m.pbrMetallicRoughness.baseColorFactor.size() == 4; ++i) {
      info.colour[i] = m.pbrMetallicRoughness.baseColorFactor[i];
    }
    s.materials.push_back(std::move(info));
  }
  return s;
}

}  // namespace vern
