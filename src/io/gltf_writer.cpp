#include "io/gltf_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <span>
#include <unordered_map>

#include <glm/gtc/quaternion.hpp>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "base/spill_file.hpp"
#include "graph/label.hpp"
#include "io/gltf_container.hpp"
#include "io/json_text.hpp"
#include "io/palette.hpp"
#include "io/up_axis.hpp"

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

  // A view of `bytes` bytes (a multiple of 4) kept elsewhere (a
  // SpillFile), that follow the bytes held here and the views added before
  // it this way: an instanced scene's transforms are not held in memory.
  int add_outside_view(std::size_t bytes, int target) {
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, '\0');
    views_.push_back({bytes_.size() + outside_, bytes, target});
    outside_ += bytes;
    return static_cast<int>(views_.size() - 1);
  }

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

  // Pads the bytes held here to 4 (the GLB chunk and data URI both want
  // it; outside views are multiples of 4) and gives them: the outside
  // views' bytes follow.
  const std::string& finish() {
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, '\0');
    return bytes_;
  }
  std::size_t size() const { return ((bytes_.size() + 3) & ~std::size_t{3}) + outside_; }
  std::size_t held_bytes() const { return bytes_.capacity(); }

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
    if (size() != 0) {  // a buffer must not be empty
      json.key("buffers").open_array().open_object().field("byteLength", size());
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
  std::size_t outside_ = 0;  // bytes of the outside views
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

std::vector<std::string> names_in_file(const std::vector<std::string>& labels, bool one_word) {
  std::vector<std::string> names;
  names.reserve(labels.size());
  for (const std::string& label : labels) names.push_back(name_in_file(label, one_word));
  return names;
}

// One glTF mesh: a primitive's geometry with one material.
struct MeshUse {
  std::string name;
  int geometry = -1;
  std::uint32_t material = 0;
};

// In instancing mode: one node per mesh a variant uses, in order of first
// use, carrying `count` instances from the `first`-th of the scene on.
struct InstanceGroup {
  int mesh = -1;
  std::size_t first = 0, count = 0;
};

// What a variant's nodes need once the accessors are numbered (instancing).
struct VariantHead {
  std::string name;
  glm::dvec3 offset{0.0};
  std::size_t groups = 0;
};

}  // namespace

// Meshes, materials and geometry are numbered in order of first use as
// the variants arrive, exactly as when the whole scene was at hand. Plain
// nodes are written as each variant arrives and wait in a SpillFile;
// instance transforms wait in three (T, R, S), the small per-group records
// in memory, because their accessors are numbered after the geometry's.
struct GltfStream::State {
  State(std::vector<std::string> labels_in, const PrimitiveLibrary& library_in, GltfOptions options_in,
        const std::optional<std::filesystem::path>& folder, const std::string& owner)
      : labels(std::move(labels_in)),
        names(names_in_file(labels, options_in.instancing)),
        library(library_in),
        options(options_in),
        materials(labels.size()),
        primitive_of_label(labels.size(), nullptr),
        nodes_spill(folder, owner),
        translations(folder, owner, kTransformPiece),
        rotations(folder, owner, kTransformPiece),
        scales(folder, owner, kTransformPiece) {
    nodes.open_array();
  }

  static constexpr std::size_t kTransformPiece = 1 << 18;  // three of them

  std::vector<std::string> labels;
  // By label: how a node names it (graph/label.hpp). An instanced node's
  // name is its mesh's, "label colour_ff0000", whose first word is the label.
  std::vector<std::string> names;
  const PrimitiveLibrary& library;
  GltfOptions options;
  MaterialTable materials;
  BinaryBuffer buffer;
  std::vector<Geometry> geometries;
  std::vector<MeshUse> meshes;
  std::vector<const Mesh*> primitive_of_label;
  std::unordered_map<const Mesh*, int> geometry_of;
  std::unordered_map<std::uint64_t, int> mesh_of;  // label << 32 | material
  std::vector<std::size_t> children;               // per variant
  std::size_t next_node = 0;
  JsonText nodes;  // plain: the "nodes" array, drained into nodes_spill
  SpillFile nodes_spill;
  std::vector<InstanceGroup> groups;  // instancing: all variants' groups in order
  std::vector<VariantHead> heads;     // instancing
  std::vector<int> group_of_mesh;     // instancing: within the current variant
  std::size_t instances = 0;
  SpillFile translations, rotations, scales;  // instancing: floats, little-endian hosts

  // The mesh of a terminal: meshes and geometry numbered in order of first use.
  int mesh_for(const Terminal& t) {
    const std::uint32_t material = materials.intern(t, labels);  // also checks the label
    const std::uint64_t key = std::uint64_t{t.label} << 32 | material;
    auto [it, fresh] = mesh_of.try_emplace(key, static_cast<int>(meshes.size()));
    if (fresh) {
      const std::string& name = names[t.label];
      const Mesh*& primitive = primitive_of_label[t.label];
      if (primitive == nullptr) {
        primitive = library.find(labels[t.label]);
        if (primitive == nullptr) primitive = &library.box();
      }
      auto [g, new_geometry] = geometry_of.try_emplace(primitive, static_cast<int>(geometries.size()));
      if (new_geometry) geometries.push_back(add_geometry(*primitive, buffer));
      meshes.push_back({t.coloured ? name + " " + materials.materials()[material].name : name, g->second, material});
    }
    return it->second;
  }

  void add_plain(const Variant& variant) {
    const std::size_t n = variant.terminals.size();
    nodes.open_object().field("name", variant.name);
    nodes.key("matrix").numbers(y_up_root_matrix(variant.offset));
    if (n > 0) {  // a node's children list must not be empty
      nodes.key("children").open_array();
      for (std::size_t c = 1; c <= n; ++c) nodes.integer(static_cast<std::int64_t>(next_node + c));
      nodes.close_array();
    }
    nodes.close_object();
    for (const Terminal& t : variant.terminals) {
      const int mesh = mesh_for(t);
      nodes.open_object().field("name", names[t.label]).field("mesh", mesh);
      nodes.key("matrix").numbers(scope_matrix(t.scope)).close_object();
      if (nodes.text().size() >= kNodesPiece) drain_nodes();
    }
    children.push_back(n);
    next_node += 1 + n;
    drain_nodes();
  }

  // A building of a million terminals is not held as text either.
  static constexpr std::size_t kNodesPiece = 1 << 20;
  void drain_nodes() {
    nodes_spill.append(nodes.text());
    nodes.clear_text();
  }

  // The variant's terminals sorted (stably) by mesh in order of first use.
  void add_instanced(const Variant& variant) {
    const std::size_t first_group = groups.size();
    std::vector<std::vector<std::uint32_t>> members;
    for (std::size_t i = 0; i < variant.terminals.size(); ++i) {
      const auto mesh = static_cast<std::size_t>(mesh_for(variant.terminals[i]));
      if (group_of_mesh.size() <= mesh) group_of_mesh.resize(mesh + 1, -1);
      int& group = group_of_mesh[mesh];
      if (group < static_cast<int>(first_group)) {
        group = static_cast<int>(groups.size());
        groups.push_back({static_cast<int>(mesh), 0, 0});
        members.emplace_back();
      }
      members[static_cast<std::size_t>(group) - first_group].push_back(static_cast<std::uint32_t>(i));
    }
    for (std::size_t k = 0; k < members.size(); ++k) {
      InstanceGroup& g = groups[first_group + k];
      g.first = instances;
      g.count = members[k].size();
      for (const std::uint32_t i : members[k]) {
        float t[3], r[4], s[3];
        write_instance(variant.terminals[i].scope, t, r, s);
        translations.append(std::string_view(reinterpret_cast<const char*>(t), sizeof t));
        rotations.append(std::string_view(reinterpret_cast<const char*>(r), sizeof r));
        scales.append(std::string_view(reinterpret_cast<const char*>(s), sizeof s));
        ++instances;
      }
    }
    const std::size_t n = groups.size() - first_group;
    heads.push_back({variant.name, variant.offset, n});
    children.push_back(n);
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

  // The instances' views (after the geometry's) and their accessors: each
  // group slices the three views.
  std::vector<std::array<int, 3>> number_instances() {
    std::vector<std::array<int, 3>> accessors;
    if (instances == 0) return accessors;
    const int t = buffer.add_outside_view(instances * 12, kNoTarget);
    const int r = buffer.add_outside_view(instances * 16, kNoTarget);
    const int s = buffer.add_outside_view(instances * 12, kNoTarget);
    for (const InstanceGroup& g : groups) {
      accessors.push_back({buffer.add_accessor({t, g.first * 12, kFloat, "VEC3", g.count, {}, {}}),
                           buffer.add_accessor({r, g.first * 16, kFloat, "VEC4", g.count, {}, {}}),
                           buffer.add_accessor({s, g.first * 12, kFloat, "VEC3", g.count, {}, {}})});
    }
    return accessors;
  }

  // The JSON document after `prefix` bytes of room, up to where the plain
  // nodes go (the text then ends in `"nodes":`), or whole when there are
  // none to splice in. The buffer is referred to by uri when given.
  std::string head(const std::string* uri, std::size_t prefix, bool& nodes_follow) {
    const std::vector<std::array<int, 3>> instance_accessors = number_instances();
    JsonText json(prefix);
    json.open_object();
    json.key("asset").open_object().field("generator", "Vernacular").field("version", "2.0").close_object();
    if (options.instancing) {
      for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
        json.key(list).open_array().string("EXT_mesh_gpu_instancing").close_array();
      }
    }
    write_scene_list(json);
    write_meshes(json);
    write_materials(json);
    buffer.write(json, uri);
    nodes_follow = !options.instancing && !children.empty();
    if (nodes_follow) {
      json.key("nodes");
      return json.take();
    }
    if (options.instancing && !children.empty()) write_instanced_nodes(json, instance_accessors);
    json.close_object();
    return json.take();
  }

  void write_scene_list(JsonText& json) const {
    json.field("scene", 0).key("scenes").open_array().open_object();
    if (!children.empty()) {  // a scene's node list must not be empty
      json.key("nodes").open_array();
      for (std::size_t v = 0, node = 0; v < children.size(); ++v) {
        json.integer(static_cast<std::int64_t>(node));
        node += 1 + children[v];
      }
      json.close_array();
    }
    json.close_object().close_array();
  }

  void write_meshes(JsonText& json) const {
    if (meshes.empty()) return;
    json.key("meshes").open_array();
    for (const MeshUse& m : meshes) {
      const Geometry& g = geometries[static_cast<std::size_t>(m.geometry)];
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
    if (materials.materials().empty()) return;
    json.key("materials").open_array();
    for (const Material& m : materials.materials()) {
      const std::array<double, 3> c = colour_components(m.colour);
      json.open_object().field("name", m.name).key("pbrMetallicRoughness").open_object();
      json.key("baseColorFactor").numbers(std::array<double, 4>{c[0], c[1], c[2], 1.0});
      // Painted and built surfaces: matte, not metal.
      json.field("metallicFactor", 0.0).field("roughnessFactor", 0.9);
      json.close_object().close_object();
    }
    json.close_array();
  }

  void write_instanced_nodes(JsonText& json, const std::vector<std::array<int, 3>>& accessors) const {
    json.key("nodes").open_array();
    std::size_t node = 0, group = 0;
    for (const VariantHead& v : heads) {
      json.open_object().field("name", v.name);
      json.key("matrix").numbers(y_up_root_matrix(v.offset));
      if (v.groups > 0) {  // a node's children list must not be empty
        json.key("children").open_array();
        for (std::size_t c = 1; c <= v.groups; ++c) json.integer(static_cast<std::int64_t>(node + c));
        json.close_array();
      }
      json.close_object();
      for (std::size_t k = 0; k < v.groups; ++k, ++group) {
        const InstanceGroup& g = groups[group];
        const std::array<int, 3>& a = accessors[group];
        json.open_object().field("name", meshes[static_cast<std::size_t>(g.mesh)].name).field("mesh", g.mesh);
        json.key("extensions").open_object().key("EXT_mesh_gpu_instancing").open_object();
        json.key("attributes").open_object();
        json.field("ROTATION", a[1]).field("SCALE", a[2]).field("TRANSLATION", a[0]);
        json.close_object().close_object().close_object().close_object();
      }
      node += 1 + v.groups;
    }
    json.close_array();
  }

  // The plain nodes' text after head(): the array, then the document's end.
  void nodes_text(const std::function<void(std::string_view)>& write) {
    nodes.close_array();
    drain_nodes();
    nodes_spill.read(write);
    write("}");
  }

  std::uint64_t nodes_size() const { return nodes_spill.size() + nodes.text().size() + 1 /* ] */ + 1 /* } */; }

  // The binary buffer: geometry, then the instances' transforms.
  void binary(const std::function<void(std::string_view)>& write) {
    write(buffer.finish());
    translations.read(write);
    rotations.read(write);
    scales.read(write);
  }
};

GltfStream::GltfStream(std::vector<std::string> labels, const PrimitiveLibrary& library, GltfOptions options,
                       std::optional<std::filesystem::path> spill_folder, std::string owner)
    : state_(std::make_unique<State>(std::move(labels), library, options, spill_folder, owner)) {}

GltfStream::~GltfStream() = default;
GltfStream::GltfStream(GltfStream&&) noexcept = default;

void GltfStream::add(const Variant& variant) {
  if (state_->options.instancing)
    state_->add_instanced(variant);
  else
    state_->add_plain(variant);
}

std::size_t GltfStream::held_bytes() const {
  const State& s = *state_;
  return s.nodes.capacity() + s.nodes_spill.held_bytes() + s.translations.held_bytes() + s.rotations.held_bytes() +
         s.scales.held_bytes() + s.buffer.held_bytes();
}

void GltfStream::glb(const std::function<void(std::string_view)>& write) {
  State& s = *state_;
  bool nodes_follow = false;
  std::string head = s.head(nullptr, kGlbJsonOffset, nodes_follow);
  const std::uint64_t json = head.size() - kGlbJsonOffset + (nodes_follow ? s.nodes_size() : 0);
  const std::uint64_t bin = s.buffer.size();
  head.replace(0, kGlbJsonOffset, glb_header(json, bin));
  write(head);
  if (nodes_follow) s.nodes_text(write);
  write(glb_between(json, bin));
  if (bin != 0) s.binary(write);
}

void GltfStream::gltf(const std::function<void(std::string_view)>& write) {
  State& s = *state_;
  std::string bytes;
  s.binary([&](std::string_view piece) { bytes.append(piece); });
  const std::string uri = "data:application/octet-stream;base64," + base64(bytes);
  bytes = {};
  bool nodes_follow = false;
  write(s.head(&uri, 0, nodes_follow));
  if (nodes_follow) s.nodes_text(write);
  write("\n");
}

namespace {

GltfStream stream_of(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options,
                     std::optional<std::filesystem::path> folder, const std::string& owner) {
  GltfStream stream(scene.labels, library, options, std::move(folder), owner);
  for (const Variant& v : scene.variants) stream.add(v);
  return stream;
}

}  // namespace

std::string glb_bytes(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options) {
  GltfStream stream = stream_of(scene, library, options, std::nullopt, "glTF output");
  std::string file;
  stream.glb([&](std::string_view piece) { file.append(piece); });
  return file;
}

std::string gltf_text(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options) {
  GltfStream stream = stream_of(scene, library, options, std::nullopt, "glTF output");
  std::string text;
  stream.gltf([&](std::string_view piece) { text.append(piece); });
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
  check_gltf_path(path);
  GltfStream stream = stream_of(scene, library, options, path.parent_path(), path.string());
  write_gltf(stream, path, outputs);
}

void check_gltf_path(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext != ".glb" && ext != ".GLB" && ext != ".gltf" && ext != ".GLTF")
    fail(ErrorKind::Usage, path.string(), {}, "a glTF file ends in .glb (binary) or .gltf (text)",
         "name the output file.glb or file.gltf");
}

void write_gltf(GltfStream& stream, const std::filesystem::path& path, OutputFiles& outputs) {
  check_gltf_path(path);
  const std::string ext = path.extension().string();
  OutputFile file = outputs.open(path);
  const auto write = [&](std::string_view piece) { file.write(piece); };
  if (ext == ".glb" || ext == ".GLB")
    stream.glb(write);
  else
    stream.gltf(write);
  file.close();
}

}  // namespace vern
