#include "inverse/load/gltf_example.hpp"


#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <unordered_set>
#include <utility>

#include <glm/gtc/quaternion.hpp>

// tinygltf stays in this file and plain_glb.cpp among the inverse sources.
// As in the glTF writer, the header is included for declarations only:
// Debian's libtinygltf-dev ships the implementation as a library
// (TinyGLTF::TinyGLTF).
#include <tiny_gltf.h>

#include "base/checked_size.hpp"
#include "base/error.hpp"
#include "base/input_file.hpp"
#include "base/number_format.hpp"
#include "base/out_of_memory.hpp"
#include "graph/label.hpp"
#include "inverse/load/part_adder.hpp"
#include "io/glb_chunks.hpp"
#include "io/gltf_compression.hpp"
#include "io/gltf_files.hpp"
#include "io/gltf_rules.hpp"
#include "io/json_cost.hpp"
#include "io/obj_reader.hpp"
#include "io/plain_glb.hpp"

namespace vern {

namespace fs = std::filesystem;

namespace {


// Images play no part in inference: skip decoding them.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// How messages name a glTF part: "node 3 'window.001'", and " instance 2"
// after it for one instance of an instanced node. The text is made only
// for a message: a file holds thousands of parts and rarely an error.
struct PartName {
  int node;
  const std::string& name;  // the node's (may be empty)
  std::optional<std::size_t> instance = {};

  std::string text() const {
    std::string text = "node " + std::to_string(node) + (name.empty() ? "" : " '" + shown_name(name) + "'");
    if (instance) text += " instance " + std::to_string(*instance);
    return text;
  }
};

// One accessor's elements, read as doubles whatever their storage.
// `attribute` names the accessor in messages ("POSITION": "node 3
// 'wall': its POSITION accessor ...").
class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, int index, const std::string& source, const PartName& who,
                 std::string_view attribute, AccessorUse use = AccessorUse::VertexAttribute)
      : source_(source), who_(who), attribute_(attribute) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) broken("refers to a missing accessor");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) broken("uses a sparse accessor, which is not supported");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) {
      broken("has no buffer view");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) broken("has no buffer");
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    component_type_ = a.componentType;
    normalized_ = a.normalized;
    components_ = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (components_ <= 0 || component_size <= 0) broken("has an unknown element type");
    const int stride = a.ByteStride(view);
    if (stride <= 0) broken("has an invalid byte stride");
    stride_ = static_cast<std::size_t>(stride);
    component_size_ = static_cast<std::size_t>(component_size);
    count_ = a.count;
    if (count_ == 0) broken(accessor_problem(model, index, use));
    // Where the last element ends, in the view and in the buffer. Every
    // number here is the file's to choose: near 2^64 they would wrap round
    // into a range that fits, so each step is checked.
    const std::size_t element = component_size_ * static_cast<std::size_t>(components_);
    std::optional<std::size_t> end_in_view = checked_mul(stride_, count_ - 1);
    if (end_in_view) end_in_view = checked_add(*end_in_view, element);
    if (end_in_view) end_in_view = checked_add(*end_in_view, a.byteOffset);
    const std::optional<std::size_t> end_in_buffer =
        end_in_view ? checked_add(*end_in_view, view.byteOffset) : std::nullopt;
    if (!end_in_buffer || *end_in_view > view.byteLength || *end_in_buffer > data.size()) {
      broken("reads past the end of its buffer");
    }
    if (const std::string problem = accessor_problem(model, index, use); !problem.empty()) broken(problem);
    // Neither sum wraps: the start lies below the end.
    data_ = data.data() + view.byteOffset + a.byteOffset;
  }

  std::size_t count() const { return count_; }
  int components() const { return components_; }

  double get(std::size_t element, int component) const {
    const unsigned char* p = data_ + element * stride_ + static_cast<std::size_t>(component) * component_size_;
    switch (component_type_) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: return read<float>(p, 1.0);
      case TINYGLTF_COMPONENT_TYPE_DOUBLE: return read<double>(p, 1.0);
      case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(read<std::int8_t>(p, 127.0), -1.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return read<std::uint8_t>(p, 255.0);
      case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(read<std::int16_t>(p, 32767.0), -1.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return read<std::uint16_t>(p, 65535.0);
      case TINYGLTF_COMPONENT_TYPE_INT: return read<std::int32_t>(p, 2147483647.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return read<std::uint32_t>(p, 4294967295.0);
      default: broken("has an unknown component type");
    }
  }

  // An index: an unsigned integer, never normalised.
  std::uint32_t index(std::size_t element) const {
    const unsigned char* p = data_ + element * stride_;
    switch (component_type_) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return raw<std::uint8_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return raw<std::uint16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return raw<std::uint32_t>(p);
      default: broken("stores indices in a type other than unsigned byte, short or int");
    }
  }

 private:
  template <class T>
  static T raw(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);  // buffers need not be aligned for T
    return v;
  }

  template <class T>
  double read(const unsigned char* p, double scale) const {
    const double v = static_cast<double>(raw<T>(p));
    return normalized_ ? v / scale : v;
  }

  [[noreturn]] void broken(const std::string& problem) const {
    fail(ErrorKind::Input, source_, {}, who_.text() + ": its " + std::string(attribute_) + " accessor " + problem,
         "export the file again, or check it with scripts/validate-gltf");
  }

  const std::string& source_;
  const PartName& who_;
  std::string_view attribute_;
  const unsigned char* data_ = nullptr;
  std::size_t stride_ = 0, component_size_ = 0, count_ = 0;
  int component_type_ = 0, components_ = 0;
  bool normalized_ = false;
};

// translation * rotation * scale, as glTF composes them; the rotation is
// x, y, z, w as glTF stores it.
glm::dmat4 trs_matrix(const glm::dvec3* translation, const glm::dvec4* rotation, const glm::dvec3* scale) {
  glm::dmat4 m(1.0);
  if (translation) m[3] = glm::dvec4(*translation, 1.0);
  if (rotation) {
    const glm::dquat q(rotation->w, rotation->x, rotation->y, rotation->z);
    const glm::dmat3 r = glm::mat3_cast(glm::normalize(q));
    for (int c = 0; c < 3; ++c) m[c] = glm::dvec4(r[c], 0.0);
  }
  if (scale) {
    for (int c = 0; c < 3; ++c) m[c] *= (*scale)[c];
  }
  return m;
}

glm::dmat4 local_matrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    glm::dmat4 m(1.0);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = n.matrix[static_cast<std::size_t>(4 * c + r)];
    return m;
  }
  const auto& t = n.translation;
  const auto& r = n.rotation;
  const auto& s = n.scale;
  const glm::dvec3 translation = t.size() == 3 ? glm::dvec3(t[0], t[1], t[2]) : glm::dvec3(0.0);
  const glm::dvec4 rotation = r.size() == 4 ? glm::dvec4(r[0], r[1], r[2], r[3]) : glm::dvec4(0.0);
  const glm::dvec3 scale = s.size() == 3 ? glm::dvec3(s[0], s[1], s[2]) : glm::dvec3(1.0);
  return trs_matrix(t.size() == 3 ? &translation : nullptr, r.size() == 4 ? &rotation : nullptr,
                    s.size() == 3 ? &scale : nullptr);
}

// EXT_mesh_gpu_instancing (what `generate --instancing` writes): the node's
// mesh is drawn once per instance, each placed by its own translation,
// rotation and scale before the node's own world matrix. Returns each
// instance's matrix, or nothing when the node is not instanced. Each
// instance is a part: more than the limit leaves (after `parts` already
// read) fail before their matrices are made (a small file can hold
// millions, 128 bytes each).
std::optional<std::vector<glm::dmat4>> instance_matrices(const tinygltf::Model& model, const tinygltf::Node& node,
                                                         const std::string& source, const PartName& who,
                                                         const ExampleLimits& limits, std::size_t parts) {
  const auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
  if (ext == node.extensions.end()) return std::nullopt;
  auto broken = [&](const std::string& problem) {
    fail(ErrorKind::Input, source, {}, who.text() + ": its EXT_mesh_gpu_instancing " + problem,
         "export the file again, or check it with scripts/validate-gltf");
  };
  if (!ext->second.IsObject() || !ext->second.Has("attributes") || !ext->second.Get("attributes").IsObject())
    broken("extension has no attributes");
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  struct Attribute {
    const char* name;
    const char* accessor;  // how messages name its accessor
    int components;
    std::optional<AccessorReader> reader;
  };
  Attribute wanted[3] = {{"TRANSLATION", "instance TRANSLATION", 3, {}},
                         {"ROTATION", "instance ROTATION", 4, {}},
                         {"SCALE", "instance SCALE", 3, {}}};
  std::optional<std::size_t> count;
  for (Attribute& a : wanted) {
    if (!attributes.Has(a.name)) continue;
    const tinygltf::Value& index = attributes.Get(a.name);
    if (!index.IsInt()) broken(std::string(a.name) + " is not an accessor index");
    a.reader.emplace(model, index.GetNumberAsInt(), source, who, a.accessor, AccessorUse::Other);
    if (a.reader->components() != a.components)
      broken(std::string(a.name) + " must hold " + std::to_string(a.components) + " numbers per instance");
    if (count && *count != a.reader->count()) broken("attributes hold different numbers of instances");
    count = a.reader->count();
  }
  if (!count) broken("extension names none of TRANSLATION, ROTATION and SCALE");
  if (*count > limits.max_parts - std::min(parts, limits.max_parts)) {
    fail(ErrorKind::Limit, source, {},
         who.text() + " has " + std::to_string(*count) + " instances, more than " + std::to_string(limits.max_parts) +
             " labelled parts" + (parts == 0 ? "" : " with the " + std::to_string(parts) + " before them"),
         too_many_parts_hint(limits));
  }
  std::vector<glm::dmat4> matrices;
  matrices.reserve(*count);
  for (std::size_t i = 0; i < *count; ++i) {
    glm::dvec3 t(0.0), s(1.0);
    glm::dvec4 r(0.0, 0.0, 0.0, 1.0);
    if (wanted[0].reader) t = {wanted[0].reader->get(i, 0), wanted[0].reader->get(i, 1), wanted[0].reader->get(i, 2)};
    if (wanted[1].reader)
      r = {wanted[1].reader->get(i, 0), wanted[1].reader->get(i, 1), wanted[1].reader->get(i, 2),
           wanted[1].reader->get(i, 3)};
    if (wanted[2].reader) s = {wanted[2].reader->get(i, 0), wanted[2].reader->get(i, 1), wanted[2].reader->get(i, 2)};
    matrices.push_back(trs_matrix(&t, &r, &s));
  }
  return matrices;
}

// OBJ refuses such numbers where it reads them (obj_reader.hpp); so does glTF.
[[noreturn]] void not_finite(const std::string& source, const PartName& who, const char* attribute, std::size_t i) {
  fail(ErrorKind::Input, source, {},
       who.text() + ": its " + attribute + " accessor holds a value that is not a finite number (element " +
           std::to_string(i) + ")",
       "export the file again, or check it with scripts/validate-gltf");
}

// The triangles a primitive of n indices makes (points and lines: none).
std::size_t triangle_count(int mode, std::size_t n) {
  if (mode == TINYGLTF_MODE_TRIANGLES) return n / 3;
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) return n > 2 ? n - 2 : 0;
  return 0;
}

// Calls f(a, b, c) for each triangle of a primitive's indices, in order.
template <class F>
void for_each_triangle(int mode, const std::vector<std::uint32_t>& indices, F f) {
  const std::size_t n = indices.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (std::size_t i = 0; i + 2 < n; i += 3) f(indices[i], indices[i + 1], indices[i + 2]);
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < n; ++i) {
      if (i % 2 == 0) f(indices[i], indices[i + 1], indices[i + 2]);
      else f(indices[i + 1], indices[i], indices[i + 2]);
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (std::size_t i = 1; i + 1 < n; ++i) f(indices[0], indices[i], indices[i + 1]);
  }
}

// A glTF mesh is read from its accessors once, in its own coordinates, and
// placed for each part that uses it: a city's thousands of nodes share one
// box. One primitive as read:
struct LocalPrimitive {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;     // one per position, or none
  std::vector<glm::dvec2> uvs;         // one per position (v up, as in Mesh), or none
  std::vector<std::uint32_t> indices;  // into positions
  int mode = TINYGLTF_MODE_TRIANGLES;
};

struct LocalMesh {
  std::vector<LocalPrimitive> primitives;  // those with positions
  // One loose piece (loose_parts.hpp) in its own coordinates. Positions
  // equal there stay equal wherever a part is placed (the same arithmetic
  // on the same numbers), so every part made of it is one piece too.
  // Decided for the meshes MeshReader keeps.
  bool whole = false;
};

// A part's world matrix, and what follows from it for normals and faces.
struct Placement {
  explicit Placement(const glm::dmat4& matrix)
      : world(matrix),
        normal_matrix(glm::transpose(glm::inverse(glm::dmat3(matrix)))),
        mirrored(glm::determinant(glm::dmat3(matrix)) < 0.0) {}

  glm::dmat4 world;
  glm::dmat3 normal_matrix;
  bool mirrored;  // faces are turned back to keep them facing outwards
};

// A primitive's positions as its accessor holds them.
void read_positions(const tinygltf::Model& model, int accessor, const std::string& source, const PartName& who,
                    LocalPrimitive& out) {
  const AccessorReader positions(model, accessor, source, who, "POSITION");
  if (positions.components() != 3) {
    fail(ErrorKind::Input, source, {}, who.text() + ": POSITION must hold 3 numbers per vertex",
         "export the file again, or check it with scripts/validate-gltf");
  }
  out.positions.reserve(positions.count());
  for (std::size_t i = 0; i < positions.count(); ++i)
    out.positions.emplace_back(positions.get(i, 0), positions.get(i, 1), positions.get(i, 2));
}

// The rest of a primitive whose positions are read (and whose accessors
// primitive_problem found sound: one NORMAL and TEXCOORD_0 per position):
// normals, texture coordinates and indices.
void read_surface(const tinygltf::Model& model, const tinygltf::Primitive& p, const std::string& source,
                  const PartName& who, LocalPrimitive& out) {
  const std::size_t count = out.positions.size();
  if (const auto nrm = p.attributes.find("NORMAL"); nrm != p.attributes.end()) {
    const AccessorReader normals(model, nrm->second, source, who, "NORMAL");
    out.normals.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      const glm::dvec3 stored(normals.get(i, 0), normals.get(i, 1), normals.get(i, 2));
      if (!std::isfinite(stored.x) || !std::isfinite(stored.y) || !std::isfinite(stored.z))
        not_finite(source, who, "NORMAL", i);
      out.normals.push_back(stored);
    }
  }
  if (const auto tex = p.attributes.find("TEXCOORD_0"); tex != p.attributes.end()) {
    const AccessorReader uvs(model, tex->second, source, who, "TEXCOORD_0");
    out.uvs.reserve(count);
    // glTF's v points down, OBJ's (and Mesh's) up.
    for (std::size_t i = 0; i < count; ++i) {
      const glm::dvec2 uv(uvs.get(i, 0), 1.0 - uvs.get(i, 1));
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) not_finite(source, who, "TEXCOORD_0", i);
      out.uvs.push_back(uv);
    }
  }
  out.mode = p.mode;
  if (p.indices < 0) {
    out.indices.resize(count);
    std::iota(out.indices.begin(), out.indices.end(), 0u);
    return;
  }
  const AccessorReader reader(model, p.indices, source, who, "index", AccessorUse::Indices);
  const int component_type = model.accessors[static_cast<std::size_t>(p.indices)].componentType;
  out.indices.reserve(reader.count());
  for (std::size_t i = 0; i < reader.count(); ++i) {
    const std::uint32_t index = reader.index(i);
    if (index >= count) {
      fail(ErrorKind::Input, source, {},
           who.text() + ": index " + std::to_string(index) + " is past the " + std::to_string(count) + " vertices",
           "export the file again, or check it with scripts/validate-gltf");
    }
    if (is_restart_index(component_type, index)) {
      fail(ErrorKind::Input, source, {},
           who.text() + ": index " + std::to_string(i) + " is " + std::to_string(index) +
               ", the largest of its type, which glTF keeps for restarting strips",
           "export the file again, or check it with scripts/validate-gltf");
    }
    out.indices.push_back(index);
  }
}

// Places a primitive's positions in world space; fails for one that lands
// beyond 1e12 (`i`, in the message, counts within the primitive).
void place_positions(const LocalPrimitive& p, const glm::dmat4& world, const std::string& source, const PartName& who,
                     Mesh& out) {
  for (std::size_t i = 0; i < p.positions.size(); ++i) {
    const glm::dvec3 w = glm::dvec3(world * glm::dvec4(p.positions[i], 1.0));
    // As in OBJ (obj_reader.hpp): such coordinates would make extents inf.
    for (int k = 0; k < 3; ++k) {
      if (!(std::abs(w[k]) <= kMaxObjCoordinate)) {
        fail(ErrorKind::Input, source, {},
             who.text() + ": vertex " + std::to_string(i) + " lies at (" + format_number(w.x) + ", " +
                 format_number(w.y) + ", " + format_number(w.z) +
                 ") after the node transforms: not finite, or beyond 1e12",
             "check the node's matrix, scale and translation and its parents', or export the file again");
      }
    }
    out.positions.push_back(w);
  }
}

// Adds a placed primitive's normals, texture coordinates and triangles
// (its positions start at `base`); more than limits.max_faces faces fail
// before they are made.
void place_surface(const LocalPrimitive& p, const Placement& placement, std::uint32_t base, const std::string& source,
                   const PartName& who, const ExampleLimits& limits, Mesh& out) {
  std::uint32_t normal_base = Mesh::kNone;
  if (!p.normals.empty()) {
    normal_base = static_cast<std::uint32_t>(out.normals.size());
    for (const glm::dvec3& stored : p.normals) {
      const glm::dvec3 n = placement.normal_matrix * stored;
      const double len = glm::length(n);
      out.normals.push_back(len > 0.0 ? n / len : n);
    }
    // A node scaled flat (a panel made from a cube) has no normal
    // matrix: its normals are dropped, not made up.
    const bool usable = std::all_of(out.normals.begin() + normal_base, out.normals.end(), [](const glm::dvec3& n) {
      return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
    });
    if (!usable) {
      out.normals.resize(normal_base);
      normal_base = Mesh::kNone;
    }
  }
  std::uint32_t uv_base = Mesh::kNone;
  if (!p.uvs.empty()) {
    uv_base = static_cast<std::uint32_t>(out.uvs.size());
    out.uvs.insert(out.uvs.end(), p.uvs.begin(), p.uvs.end());
  }

  if (out.face_sizes.size() + triangle_count(p.mode, p.indices.size()) > limits.max_faces) {
    fail(ErrorKind::Limit, source, {}, who.text() + " has more than " + std::to_string(limits.max_faces) + " faces",
         too_many_faces_hint(limits));
  }
  auto corner = [&](std::uint32_t i) {
    Mesh::Corner c;
    c.position = base + i;
    if (normal_base != Mesh::kNone) c.normal = normal_base + i;
    if (uv_base != Mesh::kNone) c.uv = uv_base + i;
    return c;
  };
  for_each_triangle(p.mode, p.indices, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (placement.mirrored) std::swap(b, c);
    out.corners.insert(out.corners.end(), {corner(a), corner(b), corner(c)});
    out.face_sizes.push_back(3);
  });
  // Points and lines have no faces; their vertices still count for the box.
}

// The mesh in its own coordinates, positions and faces only: enough for
// loose_pieces to tell whether it is whole.
Mesh local_shape(const LocalMesh& local) {
  Mesh shape;
  for (const LocalPrimitive& p : local.primitives) {
    const auto base = static_cast<std::uint32_t>(shape.positions.size());
    shape.positions.insert(shape.positions.end(), p.positions.begin(), p.positions.end());
    for_each_triangle(p.mode, p.indices, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      shape.corners.insert(shape.corners.end(),
                           {Mesh::Corner{base + a}, Mesh::Corner{base + b}, Mesh::Corner{base + c}});
      shape.face_sizes.push_back(3);
    });
  }
  return shape;
}

// Vertices and faces placed so far in an example, held to
// ExampleLimits::max_total_faces before they are placed. A mesh counts
// once for each part that places it: a small file whose thousand nodes
// share a mesh of a million triangles stops at the limit, not after a
// billion triangles.
class PlacedTotals {
 public:
  // The counts are each bounded by a buffer's size: the sums do not wrap.
  void add(std::size_t vertices, std::size_t faces, const std::string& source, const PartName& who,
           const ExampleLimits& limits) {
    vertices_ += vertices;
    faces_ += faces;
    const bool too_many_faces = faces_ > limits.max_total_faces;
    if (!too_many_faces && vertices_ <= limits.max_total_faces) return;
    fail(ErrorKind::Limit, source, {},
         "the parts up to " + who.text() + " hold more than " + std::to_string(limits.max_total_faces) +
             (too_many_faces ? " faces" : " vertices") + " in all (a mesh counts once for each node that places it)",
         "raise the limit with --max-total-faces (now " + std::to_string(limits.max_total_faces) +
             (too_many_faces ? "" : "; it bounds vertices too") + "), or give the example fewer or simpler parts");
  }

 private:
  std::size_t vertices_ = 0, faces_ = 0;
};

// Reads a glTF mesh (`mesh`, an index the file has) for the first part
// that uses it, placing each primitive for that part as soon as it is
// read, so that the part's errors come in the order they always did (a
// vertex placed beyond 1e12 before a broken NORMAL accessor of its
// primitive). Any error in what is read stops reading at this first part:
// later ones only place the mesh. Whether it is whole is left to MeshReader.
LocalMesh read_mesh(const tinygltf::Model& model, int mesh, const Placement& placement, const std::string& source,
                    const PartName& who, const ExampleLimits& limits, PlacedTotals& totals, Mesh& out) {
  LocalMesh local;
  const tinygltf::Mesh& gmesh = model.meshes[static_cast<std::size_t>(mesh)];
  for (std::size_t k = 0; k < gmesh.primitives.size(); ++k) {
    const tinygltf::Primitive& p = gmesh.primitives[k];
    const auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) continue;  // nothing to place
    auto check = [&](const std::string& problem) {
      if (problem.empty()) return;
      fail(ErrorKind::Input, source, {},
           who.text() + ": mesh " + std::to_string(mesh) + " primitive " + std::to_string(k) + " " + problem,
           "export the file again, or check it with scripts/validate-gltf");
    };
    check(primitive_problem(model, p));
    // Counted once read: the reading checks the counts against the buffers.
    LocalPrimitive& primitive = local.primitives.emplace_back();
    read_positions(model, pos->second, source, who, primitive);
    totals.add(primitive.positions.size(), 0, source, who, limits);
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    place_positions(primitive, placement.world, source, who, out);
    read_surface(model, p, source, who, primitive);
    check(index_count_problem(p.mode, primitive.indices.size()));
    totals.add(0, triangle_count(primitive.mode, primitive.indices.size()), source, who, limits);
    place_surface(primitive, placement, base, source, who, limits, out);
  }
  return local;
}

// Places a mesh read for an earlier part, transformed to world space: its
// positions, and unless `surface` is false its normals, texture
// coordinates and faces.
void place_mesh(const LocalMesh& local, const Placement& placement, const std::string& source, const PartName& who,
                const ExampleLimits& limits, bool surface, PlacedTotals& totals, Mesh& out) {
  std::size_t positions = 0, normals = 0, uvs = 0, triangles = 0;
  for (const LocalPrimitive& p : local.primitives) {
    positions += p.positions.size();
    normals += p.normals.size();
    uvs += p.uvs.size();
    triangles += triangle_count(p.mode, p.indices.size());
  }
  totals.add(positions, triangles, source, who, limits);
  out.positions.reserve(positions);
  if (surface) {
    out.normals.reserve(normals);
    out.uvs.reserve(uvs);
    out.corners.reserve(3 * triangles);
    out.face_sizes.reserve(triangles);
  }
  for (const LocalPrimitive& p : local.primitives) {
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    place_positions(p, placement.world, source, who, out);
    if (surface) place_surface(p, placement, base, source, who, limits, out);
  }
}

// The meshes of a glTF file, each read by the first part that uses it.
// One that several parts use is kept (LocalMesh) and only placed for the
// others; one used once is not kept, as a scanned statue's copy would
// double the memory reading it takes.
// The name a node had before three.js renamed it, or null. three.js's
// loader makes every name unique ("rect", "rect_1") and drops the
// characters its animation paths reserve ("window.001" becomes
// "window001", "a b" "a_b"), but keeps the name it read as userData.name,
// which its exporter writes as extras.name: the part's name, copy number
// and all.
const std::string* three_js_kept_name(const tinygltf::Node& node) {
  if (!node.extras.IsObject() || !node.extras.Has("name")) return nullptr;
  const tinygltf::Value& name = node.extras.Get("name");
  return name.IsString() ? &name.Get<std::string>() : nullptr;
}

class MeshReader {
 public:
  MeshReader(const tinygltf::Model& model, const std::string& source, const ExampleLimits& limits)
      : model_(model), source_(source), limits_(limits), uses_(model.meshes.size(), 0), kept_(model.meshes.size()) {
    for (const tinygltf::Node& n : model.nodes) {
      if (n.mesh < 0 || static_cast<std::size_t>(n.mesh) >= uses_.size()) continue;
      // An instanced node is a part per instance.
      uses_[static_cast<std::size_t>(n.mesh)] += n.extensions.count("EXT_mesh_gpu_instancing") != 0 ? 2 : 1;
    }
  }

  // Makes a part's mesh (`mesh`: an index the file has) in world space.
  // Returns whether the part is known to be one loose piece. `surface`:
  // whether the part needs its faces (it is the first of its label);
  // a part known whole that does not is only its positions, which are all
  // a part that is not its label's mesh keeps.
  bool place(int mesh, const Placement& placement, const PartName& who, bool surface, Mesh& out) {
    const auto m = static_cast<std::size_t>(mesh);
    std::optional<LocalMesh>& kept = kept_[m];
    if (kept) {
      place_mesh(*kept, placement, source_, who, limits_, surface || !kept->whole, totals_, out);
      return kept->whole;
    }
    LocalMesh read = read_mesh(model_, mesh, placement, source_, who, limits_, totals_, out);
    if (uses_[m] < 2) return false;  // loose pieces are looked for as in any part
    read.whole = loose_pieces(local_shape(read)).empty();
    kept = std::move(read);
    return kept->whole;
  }

 private:
  const tinygltf::Model& model_;
  const std::string& source_;
  const ExampleLimits& limits_;
  // 2 or more: more than one part may use the mesh (an instanced node,
  // or nodes the scene does not reach, count too: keeping is harmless).
  std::vector<std::size_t> uses_;
  std::vector<std::optional<LocalMesh>> kept_;
  PlacedTotals totals_;
};

// tinygltf's file system: every file it opens is one GltfFiles allows.
bool gltf_file_exists(const std::string& path, void* files) { return static_cast<GltfFiles*>(files)->may_read(path); }
std::string gltf_path_as_is(const std::string& path, void*) { return path; }
bool gltf_read_file(std::vector<unsigned char>* out, std::string*, const std::string& path, void* files) {
  return static_cast<GltfFiles*>(files)->read(path, *out);
}
bool gltf_write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

// tinygltf's reading of a glTF or GLB file (bytes: the file), or its error
// said as the file's.
tinygltf::Model load_with_tinygltf(const fs::path& path, bool binary, const ExampleLimits& limits,
                                   const std::vector<unsigned char>& bytes, const std::string& source) {
  GltfFiles files(path, limits.gltf);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  loader.SetFsCallbacks({gltf_file_exists, gltf_path_as_is, gltf_read_file, gltf_write_nothing, &files});
  tinygltf::Model model;
  std::string err, warn;
  // tinygltf takes the length as an unsigned int: the cap keeps it below 4 GiB.
  const auto length = static_cast<unsigned int>(bytes.size());
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), length, files.folder())
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()), length,
                                             files.folder());
  } catch (const std::logic_error& e) {
    // tinygltf indexes some vectors with at(): a buffer of byteLength 0
    // in a GLB throws out_of_range. The file is what is wrong.
    err = std::string("tinygltf could not read it (") + e.what() + ")";
  }
  if (!ok) {
    // A file the glTF names that was refused is the reason, said our way.
    if (const auto& refused = files.refusal()) fail(refused->kind, source, {}, refused->message, refused->hint);
    // tinygltf would say how long the file is, which may not be the
    // user's to know (a file allowed outside the folder): said without.
    if (err.find("File size mismatch") != std::string::npos) {
      fail(ErrorKind::Input, source, {},
           "the buffer file '" + files.last_read() + "' does not hold the byteLength its buffer declares",
           "export the glTF and its .bin file again, together");
    }
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    fail(ErrorKind::Input, source, {}, std::string("is not a valid ") + (binary ? "GLB" : "glTF") + " file: " + err,
         "export the file again, or check it with scripts/validate-gltf");
  }
  return model;
}

// JSON nested deeper than this is refused: tinygltf reads extras and
// extensions recursively. glTF's own objects nest 8 deep at most.
constexpr std::size_t kMaxJsonDepth = 64;

// Refuses a glTF's JSON text whose reading would take more memory than the
// file limit (json_cost.hpp), or that nests deeper than kMaxJsonDepth.
void check_json_cost(std::string_view text, bool binary, const std::string& source, const GltfFileRules& rules) {
  const JsonCost cost = json_cost(text, kMaxJsonDepth);
  if (cost.too_deep_at != JsonCost::npos) {
    const SourceLoc at = text_location(text, cost.too_deep_at);
    fail(ErrorKind::Input, source, binary ? SourceLoc{} : at,
         std::string("its JSON") + (binary ? " (line " + std::to_string(at.line) + ")" : "") +
             " nests arrays and objects more than " + std::to_string(kMaxJsonDepth) + " deep",
         "glTF's own objects nest 8 deep: flatten the extras, or export the file again");
  }
  if (cost.bytes > rules.max_bytes) {
    fail(ErrorKind::Limit, source, {},
         "its JSON holds " + std::to_string(cost.values) + " values, which take up to " +
             std::to_string((cost.bytes >> 20) + 1) + " MiB of memory once read: more than the limit of " +
             mebibytes(rules.max_bytes),
         "glTF JSON takes up to a few hundred bytes per value once read: raise the limit with --max-gltf-mib (now " +
             std::to_string(rules.max_bytes >> 20) + "), or keep the geometry in binary buffers");
  }
}

}  // namespace

Example load_gltf_example(const fs::path& path, bool binary, const ExampleLimits& limits) {
  Example ex;
  ex.source = path.string();
  PartAdder adder(ex, limits);
  std::vector<unsigned char> bytes;
  if (const auto refused = read_regular_file(path, limits.gltf.max_bytes, bytes)) {
    fail(refused->kind, ex.source, {}, refused->problem,
         refused->kind == ErrorKind::Limit ? gltf_size_hint(limits.gltf) : "check the path and the file's permissions");
  }
  // The container and the JSON are checked before any reader sees them.
  std::span<const unsigned char> json = bytes;
  GlbChunks chunks;
  if (binary) {
    chunks = glb_chunks(bytes);
    if (!chunks.problem.empty()) {
      fail(ErrorKind::Input, ex.source, {}, "is not a valid GLB file: " + chunks.problem,
           "export the file again, or check it with scripts/validate-gltf");
    }
    json = chunks.json;
  }
  check_json_cost({reinterpret_cast<const char*>(json.data()), json.size()}, binary, ex.source, limits.gltf);
  // Compressed files hold what tinygltf refuses (gltf_compression.hpp).
  if (auto prepared = prepared_for_tinygltf(json, binary ? &chunks : nullptr)) bytes = std::move(*prepared);
  // The common GLB is read without tinygltf's JSON document; every other
  // file, and every error, is tinygltf's (plain_glb.hpp).
  std::optional<tinygltf::Model> plain = binary ? read_plain_glb(bytes) : std::nullopt;
  tinygltf::Model model = plain ? std::move(*plain) : load_with_tinygltf(path, binary, limits, bytes, ex.source);
  plain.reset();
  bytes = {};
  // The file's own rules first: decoded data lives in buffers of our own.
  check_gltf_file_rules(model, ex.source);
  decode_compression(model, ex.source, limits.gltf.max_bytes);

  // The default scene's roots (check_gltf_file_rules found it); without
  // scenes, every node no other node lists as a child.
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    roots = model.scenes[static_cast<std::size_t>(model.defaultScene >= 0 ? model.defaultScene : 0)].nodes;
  } else {
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const tinygltf::Node& n : model.nodes)
      for (int c : n.children)
        if (c >= 0 && static_cast<std::size_t>(c) < is_child.size()) is_child[static_cast<std::size_t>(c)] = true;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
  }

  // Depth first, children in order: parts come out in the file's node order.
  // Each node is visited once, so a malformed file with cycles still ends.
  std::vector<bool> visited(model.nodes.size(), false);
  MeshReader meshes(model, ex.source, limits);
  // three.js's exporter makes each node name unique with a copy number of
  // its own ("rect_1"), as Blender does with ".001".
  const bool made_by_three_js = model.asset.generator.rfind("THREE.GLTFExporter", 0) == 0;
  // Each part's group (LabelledBox::group): the top-level node it lies
  // under (generate writes a node per building; Blender, one per object
  // that has no parent).
  constexpr std::uint32_t kNotTop = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> group_of(model.nodes.size(), kNotTop);
  for (std::size_t k = 0; k < roots.size(); ++k)
    if (roots[k] >= 0 && static_cast<std::size_t>(roots[k]) < model.nodes.size())
      group_of[static_cast<std::size_t>(roots[k])] = static_cast<std::uint32_t>(k);
  struct Pending {
    int index;
    glm::dmat4 parent;
    std::uint32_t group;
  };
  std::vector<Pending> stack;
  // glTF is y-up: the roots are turned z-up, exactly (a permutation with
  // one sign), so a file `generate` wrote gives back its grammar's numbers.
  glm::dmat4 z_up(1.0);
  for (int c = 0; c < 3; ++c) z_up[c] = glm::dvec4(y_up_to_z_up(glm::dvec3(glm::dmat3(1.0)[c])), 0.0);
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, z_up, 0});
  while (!stack.empty()) {
    const auto [index, parent, above] = stack.back();
    stack.pop_back();
    if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size()) continue;
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
    const PartName who{index, node.name};
    // glTF nodes form trees: a node reached twice is a cycle or a node with
    // two parents, and its part would be counted twice.
    if (visited[static_cast<std::size_t>(index)]) {
      fail(ErrorKind::Input, ex.source, {},
           who.text() + " is reached twice from the scene: it is its own ancestor or the child of two nodes",
           "glTF nodes must form trees; export the file again");
    }
    visited[static_cast<std::size_t>(index)] = true;
    const glm::dmat4 world = parent * local_matrix(node);
    // A top-level node starts its group; any other node is in its parent's.
    const std::uint32_t top = group_of[static_cast<std::size_t>(index)];
    const std::uint32_t group = top != kNotTop ? top : above;
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, world, group});
    if (node.mesh < 0) continue;  // else one the file has (check_gltf_file_rules)
    if (node.name.empty()) {
      fail(ErrorKind::Input, ex.source, {},
           who.text() + " has a mesh but no name: inference cannot tell which primitive it is",
           "name each part's node after its primitive (e.g. `window.001`)");
    }
    // An instanced node is one part per instance. Its name is the mesh's,
    // "label" or "label colour_xxxxxx" (gltf_writer.hpp): the label is the
    // first word (written with its spaces as %20).
    const auto instances = instance_matrices(model, node, ex.source, who, limits, ex.boxes.size());
    const std::size_t parts = instances ? instances->size() : 1;
    const std::string* kept = made_by_three_js ? three_js_kept_name(node) : nullptr;
    const std::string& full = kept ? *kept : node.name;
    std::string_view name = instances ? std::string_view(full).substr(0, full.find(' ')) : std::string_view(full);
    if (made_by_three_js && !kept) name = without_three_js_copy_number(name);
    const std::string label = read_label(name, NameOf::Part, ex.source, {}, "the name of node " + std::to_string(index));
    for (std::size_t i = 0; i < parts; ++i) {
      const PartName part{index, node.name, instances ? std::optional<std::size_t>(i) : std::nullopt};
      if (ex.boxes.size() >= limits.max_parts) {
        fail(ErrorKind::Limit, ex.source, {},
             "more than " + std::to_string(limits.max_parts) + " labelled parts: reading stopped at " + part.text(),
             too_many_parts_hint(limits));
      }
      const Placement placement(instances ? world * (*instances)[i] : world);
      Mesh mesh;
      // Each primitive placed draws a triangle or more (primitive_problem).
      const bool whole = meshes.place(node.mesh, placement, part, !adder.has_label(label), mesh);
      if (mesh.positions.empty()) {
        fail(ErrorKind::Input, ex.source, {}, part.text() + " has a mesh without vertex positions",
             "export the file again with geometry for every named part");
      }
      const std::string object = shown_name(node.name) + (instances ? " (instance " + std::to_string(i) + ")" : "");
      adder.add(label, 0, mesh, object, group, whole);
    }
  }
  if (ex.boxes.empty()) {
    fail(ErrorKind::Input, ex.source, {}, "has no labelled objects; each part must be a named glTF node with a mesh",
         "give each part its own node named after its primitive (e.g. `window.001`)");
  }
  return ex;
}

}  // namespace vern
