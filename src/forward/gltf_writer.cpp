#include "forward/gltf_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <span>
#include <unordered_map>

#include <glm/gtc/quaternion.hpp>

#include "forward/gltf_container.hpp"
#include "forward/json_text.hpp"
#include "forward/palette.hpp"
#include "forward/up_axis.hpp"
#include "graph/atomic_file.hpp"
#include "graph/error.hpp"

// The document is written by hand (json_text.hpp) rather than through
// tinygltf's model: for a thousand city blocks (two million nodes) the model
// and its JSON serialisation took 25 s of a 28 s run. tinygltf still reads
// files back (gltf_summary.cpp, example loading), so what we write is
// checked by an independent parser in the tests, and by the Khronos
// validator in CTest.

namespace vern {

namespace {

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963, kNoTarget = 0;

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

// The one binary buffer, its views and the accessors that read them.
class BinaryBuffer {
 public:
  struct Accessor {
    int view = -1;
    std::size_t offset = 0;  // bytes into the view
    int component = kFloat;
    const char* type = "SCALAR";
    std::size_t count = 0;
    std::vector<double> min, max;  // written when not empty
  };

  // Appends the values as a new view, aligned to 4 bytes as accessors of
  // 4-byte components need; returns the view's index.
  template <class T>
  int add_view(std::span<const T> values, int target) {
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, '\0');
    const std::size_t at = bytes_.size();
    bytes_.resize(at + values.size_bytes());
    if (!values.empty()) std::memcpy(bytes_.data() + at, values.data(), values.size_bytes());  // little-endian hosts
    views_.push_back({at, values.size_bytes(), target});
    return static_cast<int>(views_.size() - 1);
  }

  // A new view of `bytes` bytes to be filled through data(view) (aligned
  // to 4): large arrays are written in place, not built and copied.
  int reserve_view(std::size_t bytes, int target) {
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, '\0');
    const std::size_t at = bytes_.size();
    bytes_.resize(at + bytes);
    views_.push_back({at, bytes, target});
    return static_cast<int>(views_.size() - 1);
  }
  float* floats(int view) { return reinterpret_cast<float*>(bytes_.data() + views_[static_cast<std::size_t>(view)].offset); }

  int add_accessor(Accessor a) {
    accessors_.push_back(std::move(a));
    return static_cast<int>(accessors_.size() - 1);
  }

  // A view holding exactly these values and one accessor over all of them.
  template <class T>
  int add(std::span<const T> values, int component, const char* type, std::size_t count, int target) {
    return add_accessor({add_view(values, target), 0, component, type, count, {}, {}});
  }

  Accessor& accessor(int i) { return accessors_[static_cast<std::size_t>(i)]; }

  // Pads the buffer to 4 bytes (the GLB chunk and data URI both want it).
  const std::string& finish() {
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, '\0');
    return bytes_;
  }

  // "accessors", "bufferViews" and "buffers"; the buffer carries uri when
  // given (the .gltf text form), else it is the GLB's BIN chunk.
  void write(JsonText& json, const std::string* uri) const {
    if (!accessors_.empty()) {
      json.key("accessors").open_array();
      for (const Accessor& a : accessors_) {
        json.open_object().field("bufferView", a.view);
        if (a.offset != 0) json.field("byteOffset", a.offset);
        json.field("componentType", a.component).field("count", a.count).field("type", a.type);
        if (!a.min.empty()) json.key("min").numbers(a.min).key("max").numbers(a.max);
        json.close_object();
      }
      json.close_array();
    }
    if (!views_.empty()) {
      json.key("bufferViews").open_array();
      for (const View& v : views_) {
        json.open_object().field("buffer", 0).field("byteOffset", v.offset).field("byteLength", v.length);
        if (v.target != kNoTarget) json.field("target", v.target);
        json.close_object();
      }
      json.close_array();
    }
    if (!bytes_.empty()) {  // a buffer must not be empty
      json.key("buffers").open_array().open_object().field("byteLength", bytes_.size());
      if (uri != nullptr) json.field("uri", *uri);
      json.close_object().close_array();
    }
  }

 private:
  struct View {
    std::size_t offset = 0, length = 0;
    int target = kNoTarget;
  };
  std::string bytes_;
  std::vector<View> views_;
  std::vector<Accessor> accessors_;
};

// The accessors of one primitive's triangles, shared by its meshes.
struct Geometry {
  int position = -1, normal = -1, uv = -1, indices = -1;
};

Geometry add_geometry(const Mesh& mesh, BinaryBuffer& buffer) {
  const Triangles t = triangulate(mesh);
  const std::size_t vertices = t.positions.size() / 3;
  Geometry g;
  g.position = buffer.add(std::span(t.positions), kFloat, "VEC3", vertices, kArrayBuffer);
  // The spec requires POSITION bounds; they must be those of the floats stored.
  std::vector<double> lo(3, 0.0), hi(3, 0.0);
  for (std::size_t v = 0; v < vertices; ++v) {
    for (std::size_t i = 0; i < 3; ++i) {
      const double x = t.positions[3 * v + i];
      lo[i] = v == 0 ? x : std::min(lo[i], x);
      hi[i] = v == 0 ? x : std::max(hi[i], x);
    }
  }
  buffer.accessor(g.position).min = lo;
  buffer.accessor(g.position).max = hi;
  g.normal = buffer.add(std::span(t.normals), kFloat, "VEC3", vertices, kArrayBuffer);
  if (t.has_uvs) g.uv = buffer.add(std::span(t.uvs), kFloat, "VEC2", vertices, kArrayBuffer);
  if (vertices <= 0xffff) {
    const std::vector<std::uint16_t> small(t.indices.begin(), t.indices.end());
    g.indices = buffer.add(std::span(small), kUnsignedShort, "SCALAR", small.size(), kElementArrayBuffer);
  } else {
    g.indices = buffer.add(std::span(t.indices), kUnsignedInt, "SCALAR", t.indices.size(), kElementArrayBuffer);
  }
  return g;
}

// A scope's sizes as glTF may store them. glTF requires transforms to
// decompose into translation, rotation and scale, which a zero scale (a
// comp() face: a window on a zero-depth scope) does not, and viewers would
// divide by it to transform normals. So a size that is 0, or vanishing next
// to the scope's largest, becomes a millionth of that largest size:
// invisible, and the flattened mesh still faces the right way.
glm::dvec3 drawable_size(const Scope& s) {
  const double largest = std::max({std::abs(s.size.x), std::abs(s.size.y), std::abs(s.size.z)});
  const double thinnest = largest > 0.0 ? largest * 1e-6 : 1e-6;
  glm::dvec3 size = s.size;
  for (int c = 0; c < 3; ++c) {
    if (std::abs(size[c]) < thinnest) size[c] = thinnest;
  }
  return size;
}

// The matrix mapping the unit box onto a scope, column-major.
std::array<double, 16> scope_matrix(const Scope& s) {
  const glm::dvec3 size = drawable_size(s);
  std::array<double, 16> m{};
  for (int c = 0; c < 3; ++c) {
    const glm::dvec3 axis = s.frame[c] * size[c];
    for (int r = 0; r < 3; ++r) m[static_cast<std::size_t>(4 * c + r)] = axis[r];
  }
  for (int r = 0; r < 3; ++r) m[static_cast<std::size_t>(12 + r)] = s.origin[r];
  m[15] = 1.0;
  return m;
}

// A variant's root: its offset, and the quarter turn from the grammar's
// z-up frame to glTF's y-up (up_axis.hpp), column-major. Turned here, at
// the root, the parts beneath keep their grammar-frame matrices and
// instances; its entries are 0, 1 and -1, so reading back is exact.
std::array<double, 16> y_up_root_matrix(const glm::dvec3& offset) {
  std::array<double, 16> m{};
  for (int c = 0; c < 4; ++c) {
    const glm::dvec3 column = z_up_to_y_up(c < 3 ? glm::dvec3(glm::dmat3(1.0)[c]) : offset);
    for (int r = 0; r < 3; ++r) m[static_cast<std::size_t>(4 * c + r)] = column[r];
  }
  m[15] = 1.0;
  return m;
}

// One glTF mesh: a primitive's geometry with one material.
struct MeshUse {
  std::string name;
  int geometry = -1;
  std::uint32_t material = 0;
};

// Per variant, in instancing mode: one node per mesh it uses, in order of
// first use, with the accessors of its instances.
struct InstanceGroup {
  int mesh = -1;
  int translation = -1, rotation = -1, scale = -1;
};

class Document {
 public:
  Document(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options)
      : scene_(scene), library_(library), options_(options), materials_(scene) {
    assign_meshes();
    if (options_.instancing) gather_instances();
  }

  // The JSON document after `prefix` bytes of room; the buffer is referred
  // to by uri when given.
  std::string json(const std::string* uri, std::size_t prefix = 0) {
    JsonText json(prefix);
    std::size_t terminals = 0;
    for (const Variant& v : scene_.variants) terminals += v.terminals.size();
    json.reserve(4096 + (options_.instancing ? 200 * groups_.size() : 130 * terminals));
    json.open_object();
    json.key("asset").open_object().field("generator", "Vernacular").field("version", "2.0").close_object();
    if (options_.instancing) {
      for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
        json.key(list).open_array().string("EXT_mesh_gpu_instancing").close_array();
      }
    }
    write_scene_list(json);
    write_meshes(json);
    write_materials(json);
    buffer_.write(json, uri);
    write_nodes(json);  // last: the bulk of the text, written in one pass
    json.close_object();
    return json.take();
  }

  const std::string& binary() { return buffer_.finish(); }

 private:
  // The mesh of each terminal, meshes and geometry in order of first use.
  void assign_meshes() {
    std::vector<const Mesh*> primitive_of_label(scene_.labels.size(), nullptr);
    std::unordered_map<const Mesh*, int> geometry_of;
    std::unordered_map<std::uint64_t, int> mesh_of;  // label << 32 | material
    for (const Variant& variant : scene_.variants) {
      for (const Terminal& t : variant.terminals) {
        const std::uint32_t material = materials_.index_of(t);  // also checks the label
        const std::uint64_t key = std::uint64_t{t.label} << 32 | material;
        auto [it, fresh] = mesh_of.try_emplace(key, static_cast<int>(meshes_.size()));
        if (fresh) {
          const std::string& label = scene_.labels[t.label];
          const Mesh*& primitive = primitive_of_label[t.label];
          if (primitive == nullptr) {
            primitive = library_.find(label);
            if (primitive == nullptr) primitive = &library_.box();
          }
          auto [g, new_geometry] = geometry_of.try_emplace(primitive, static_cast<int>(geometries_.size()));
          if (new_geometry) geometries_.push_back(add_geometry(*primitive, buffer_));
          meshes_.push_back({t.coloured ? label + " " + materials_.materials()[material].name : label, g->second,
                             material});
        }
        mesh_of_terminal_.push_back(it->second);
      }
    }
  }

  // Instancing: each variant's terminals sorted (stably) by mesh in order of
  // first use, their transforms in three views (T, R, S) that every group's
  // accessors slice.
  void gather_instances() {
    const std::size_t total = mesh_of_terminal_.size();
    if (total == 0) {
      groups_per_variant_.assign(scene_.variants.size(), 0);
      return;
    }
    // The transforms go straight into the buffer (about 40 bytes a
    // terminal: a thousand city blocks hold two million).
    const int t = buffer_.reserve_view(total * 12, kNoTarget);
    const int r = buffer_.reserve_view(total * 16, kNoTarget);
    const int s = buffer_.reserve_view(total * 12, kNoTarget);
    float* translations = buffer_.floats(t);
    float* rotations = buffer_.floats(r);
    float* scales = buffer_.floats(s);
    std::size_t written = 0;  // instances so far
    std::vector<int> group_of_mesh(meshes_.size(), -1);
    std::size_t next = 0;  // index into mesh_of_terminal_
    for (const Variant& variant : scene_.variants) {
      const std::size_t first_group = groups_.size();
      std::vector<std::vector<std::uint32_t>> members;
      for (std::size_t i = 0; i < variant.terminals.size(); ++i) {
        const int mesh = mesh_of_terminal_[next + i];
        int& group = group_of_mesh[static_cast<std::size_t>(mesh)];
        if (group < static_cast<int>(first_group)) {
          group = static_cast<int>(groups_.size());
          groups_.push_back({mesh, -1, -1, -1});
          members.emplace_back();
        }
        members[static_cast<std::size_t>(group) - first_group].push_back(static_cast<std::uint32_t>(i));
      }
      for (std::size_t k = 0; k < members.size(); ++k) {
        InstanceGroup& g = groups_[first_group + k];
        const std::size_t count = members[k].size();
        g.translation = buffer_.add_accessor({t, written * 12, kFloat, "VEC3", count, {}, {}});
        g.rotation = buffer_.add_accessor({r, written * 16, kFloat, "VEC4", count, {}, {}});
        g.scale = buffer_.add_accessor({s, written * 12, kFloat, "VEC3", count, {}, {}});
        for (const std::uint32_t i : members[k]) {
          write_instance(variant.terminals[i].scope, translations + 3 * written, rotations + 4 * written,
                         scales + 3 * written);
          ++written;
        }
      }
      groups_per_variant_.push_back(groups_.size() - first_group);
      next += variant.terminals.size();
    }
  }

  // T, R, S of a scope: frame * diag(size) = rotation * diag(scale). A
  // mirrored frame (determinant -1) moves its mirror into the x scale.
  static void write_instance(const Scope& scope, float* translation, float* rotation, float* scale) {
    glm::dmat3 frame = scope.frame;
    glm::dvec3 size = drawable_size(scope);
    if (glm::determinant(frame) < 0.0) {
      frame[0] = -frame[0];
      size.x = -size.x;
    }
    const glm::dquat q = glm::normalize(glm::quat_cast(frame));
    const double xyzw[4] = {q.x, q.y, q.z, q.w};
    for (int i = 0; i < 3; ++i) {
      translation[i] = static_cast<float>(scope.origin[i]);
      scale[i] = static_cast<float>(size[i]);
    }
    for (int i = 0; i < 4; ++i) rotation[i] = static_cast<float>(xyzw[i]);
  }

  void write_scene_list(JsonText& json) const {
    json.field("scene", 0).key("scenes").open_array().open_object();
    if (!scene_.variants.empty()) {  // a scene's node list must not be empty
      json.key("nodes").open_array();
      for (std::size_t v = 0, node = 0; v < scene_.variants.size(); ++v) {
        json.integer(static_cast<std::int64_t>(node));
        node += 1 + children(v);
      }
      json.close_array();
    }
    json.close_object().close_array();
  }

  std::size_t children(std::size_t variant) const {
    return options_.instancing ? groups_per_variant_[variant] : scene_.variants[variant].terminals.size();
  }

  void write_meshes(JsonText& json) const {
    if (meshes_.empty()) return;
    json.key("meshes").open_array();
    for (const MeshUse& m : meshes_) {
      const Geometry& g = geometries_[static_cast<std::size_t>(m.geometry)];
      json.open_object().field("name", m.name).key("primitives").open_array().open_object();
      json.key("attributes").open_object().field("NORMAL", g.normal).field("POSITION", g.position);
      if (g.uv >= 0) json.field("TEXCOORD_0", g.uv);
      json.close_object();
      json.field("indices", g.indices).field("material", static_cast<int>(m.material)).field("mode", 4);
      json.close_object().close_array().close_object();
    }
    json.close_array();
  }

  void write_materials(JsonText& json) const {
    if (materials_.materials().empty()) return;
    json.key("materials").open_array();
    for (const Material& m : materials_.materials()) {
      const std::array<double, 3> c = colour_components(m.colour);
      json.open_object().field("name", m.name).key("pbrMetallicRoughness").open_object();
      json.key("baseColorFactor").numbers(std::array<double, 4>{c[0], c[1], c[2], 1.0});
      // Painted and built surfaces: matte, not metal.
      json.field("metallicFactor", 0.0).field("roughnessFactor", 0.9);
      json.close_object().close_object();
    }
    json.close_array();
  }

  void write_nodes(JsonText& json) const {
    if (scene_.variants.empty()) return;
    json.key("nodes").open_array();
    std::size_t node = 0, terminal = 0, group = 0;
    for (std::size_t v = 0; v < scene_.variants.size(); ++v) {
      const Variant& variant = scene_.variants[v];
      json.open_object().field("name", variant.name);
      json.key("matrix").numbers(y_up_root_matrix(variant.offset));
      const std::size_t n = children(v);
      if (n > 0) {  // a node's children list must not be empty
        json.key("children").open_array();
        for (std::size_t c = 1; c <= n; ++c) json.integer(static_cast<std::int64_t>(node + c));
        json.close_array();
      }
      json.close_object();
      if (options_.instancing) {
        for (std::size_t g = 0; g < n; ++g, ++group) write_instanced_node(json, groups_[group]);
      } else {
        for (const Terminal& t : variant.terminals) {
          json.open_object().field("name", scene_.labels[t.label]).field("mesh", mesh_of_terminal_[terminal++]);
          json.key("matrix").numbers(scope_matrix(t.scope)).close_object();
        }
      }
      node += 1 + n;
    }
    json.close_array();
  }

  void write_instanced_node(JsonText& json, const InstanceGroup& g) const {
    json.open_object().field("name", meshes_[static_cast<std::size_t>(g.mesh)].name).field("mesh", g.mesh);
    json.key("extensions").open_object().key("EXT_mesh_gpu_instancing").open_object();
    json.key("attributes").open_object();
    json.field("ROTATION", g.rotation).field("SCALE", g.scale).field("TRANSLATION", g.translation);
    json.close_object().close_object().close_object().close_object();
  }

  const Scene& scene_;
  const PrimitiveLibrary& library_;
  GltfOptions options_;
  MaterialTable materials_;
  BinaryBuffer buffer_;
  std::vector<Geometry> geometries_;
  std::vector<MeshUse> meshes_;
  std::vector<int> mesh_of_terminal_;  // all variants' terminals in order
  std::vector<InstanceGroup> groups_;  // instancing: all variants' groups in order
  std::vector<std::size_t> groups_per_variant_;
};

}  // namespace

std::string glb_bytes(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options) {
  Document document(scene, library, options);
  const std::string& bin = document.binary();  // padded to 4 bytes
  std::string file = glb_head(document.json(nullptr, kGlbJsonOffset), bin);
  file.append(bin);
  return file;
}

std::string gltf_text(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options) {
  Document document(scene, library, options);
  const std::string uri = "data:application/octet-stream;base64," + base64(document.binary());
  std::string text = document.json(&uri);
  text += '\n';
  return text;
}

void write_gltf(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& path,
                GltfOptions options) {
  OutputFiles outputs;
  write_gltf(scene, library, path, options, outputs);
  outputs.commit();
}

void write_gltf(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& path,
                GltfOptions options, OutputFiles& outputs) {
  const std::string ext = path.extension().string();
  if (ext == ".glb" || ext == ".GLB") {
    // Head and binary chunk written one after the other: a thousand city
    // blocks' buffer is not copied into one string first.
    Document document(scene, library, options);
    const std::string& bin = document.binary();
    const std::string head = glb_head(document.json(nullptr, kGlbJsonOffset), bin);
    const std::string_view pieces[] = {head, bin};
    outputs.stage(path, pieces);
  } else if (ext == ".gltf" || ext == ".GLTF") {
    outputs.stage(path, gltf_text(scene, library, options));
  } else {
    fail(ErrorKind::Usage, path.string(), {}, "a glTF file ends in .glb (binary) or .gltf (text)",
         "name the output file.glb or file.gltf");
  }
}

}  // namespace vern
