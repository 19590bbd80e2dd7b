#include "io/plain_glb.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "io/glb_chunks.hpp"
#include "io/gltf_container.hpp"
#include "io/json_cursor.hpp"

namespace vern {

namespace {

using Declined = JsonCursor::Declined;

[[noreturn]] void decline() { throw Declined{}; }

// Keys an object may hold, each once. A key outside the list declines.
class Keys {
 public:
  // Copied: the list a caller writes lives only as long as its statement.
  // The lists are this file's own, the longest of nine keys.
  Keys(std::initializer_list<std::string_view> allowed) : count_(std::min(allowed.size(), kMost)) {
    std::copy(allowed.begin(), allowed.begin() + static_cast<std::ptrdiff_t>(count_), allowed_.begin());
  }

  // The key's place in the list.
  std::size_t of(std::string_view key) {
    for (std::size_t i = 0; i < count_; ++i) {
      if (allowed_[i] != key) continue;
      // nlohmann::json keeps the last of duplicates, tinygltf's other
      // readers may not: a file that has them is not plain.
      if (seen_ & (1u << i)) decline();
      seen_ |= 1u << i;
      return i;
    }
    decline();
  }
  bool seen(std::size_t i) const { return (seen_ >> i) & 1u; }

 private:
  static constexpr std::size_t kMost = 16;
  std::array<std::string_view, kMost> allowed_;
  std::size_t count_;
  std::uint32_t seen_ = 0;
};

// Calls read() for each element of an array.
template <class F>
void each_item(JsonCursor& json, F read) {
  json.open_array();
  while (json.next_item()) read();
}

std::vector<double> numbers(JsonCursor& json) {
  std::vector<double> out;
  each_item(json, [&] { out.push_back(json.number()); });
  return out;
}

std::vector<int> indices(JsonCursor& json) {
  std::vector<int> out;
  each_item(json, [&] { out.push_back(json.index()); });
  return out;
}

class Reader {
 public:
  Reader(std::string_view text, std::span<const unsigned char> bin) : json_(text), bin_(bin) {}

  tinygltf::Model read() {
    model_.defaultScene = -1;
    Keys keys{"asset", "scene", "scenes", "nodes", "meshes", "materials", "accessors", "bufferViews", "buffers"};
    json_.open_object();
    std::string_view key;
    while (json_.next_key(key)) {
      switch (keys.of(key)) {
        case 0: asset(); break;
        case 1: model_.defaultScene = json_.index(); break;
        case 2: each_item(json_, [&] { scene(); }); break;
        case 3: each_item(json_, [&] { node(); }); break;
        case 4: each_item(json_, [&] { mesh(); }); break;
        case 5: each_item(json_, [&] { material(); }); break;
        case 6: each_item(json_, [&] { accessor(); }); break;
        case 7: each_item(json_, [&] { buffer_view(); }); break;
        case 8: each_item(json_, [&] { buffer(); }); break;
      }
    }
    json_.finish();
    // tinygltf refuses a file without asset.version, and one whose
    // primitive names indices it cannot find.
    if (!version_) decline();
    for (const tinygltf::Mesh& m : model_.meshes)
      for (const tinygltf::Primitive& p : m.primitives) {
        if (p.indices < 0) continue;
        if (static_cast<std::size_t>(p.indices) >= model_.accessors.size()) decline();
        const int view = model_.accessors[static_cast<std::size_t>(p.indices)].bufferView;
        if (view < 0 || static_cast<std::size_t>(view) >= model_.bufferViews.size()) decline();
      }
    return std::move(model_);
  }

 private:
  // Reads an object's keys and values; returns which keys it held.
  template <class F>
  Keys object(Keys keys, F read) {
    json_.open_object();
    std::string_view key;
    while (json_.next_key(key)) read(keys.of(key), keys);
    return keys;
  }

  void asset() {
    object({"version", "generator", "copyright", "minVersion"}, [&](std::size_t k, Keys&) {
      const std::string_view text = json_.string();
      if (k == 0) {
        model_.asset.version = text;
        version_ = true;
      } else if (k == 3) {
        model_.asset.minVersion = text;
      }
    });
  }

  void scene() {
    tinygltf::Scene& s = model_.scenes.emplace_back();
    object({"nodes", "name"}, [&](std::size_t k, Keys&) {
      if (k == 0) s.nodes = indices(json_);
      else s.name = json_.string();
    });
  }

  void node() {
    tinygltf::Node& n = model_.nodes.emplace_back();
    object({"name", "mesh", "children", "matrix", "translation", "rotation", "scale"}, [&](std::size_t k, Keys& keys) {
      switch (k) {
        case 0: n.name = json_.string(); break;
        case 1: n.mesh = json_.index(); break;
        case 2: n.children = indices(json_); break;
        case 3: n.matrix = numbers(json_); break;
        case 4: n.translation = numbers(json_); break;
        case 5: n.rotation = numbers(json_); break;
        case 6: n.scale = numbers(json_); break;
      }
      // tinygltf reads T/R/S only without a matrix.
      if (keys.seen(3) && (keys.seen(4) || keys.seen(5) || keys.seen(6))) decline();
    });
  }

  void mesh() {
    tinygltf::Mesh& m = model_.meshes.emplace_back();
    object({"name", "primitives"}, [&](std::size_t k, Keys&) {
      if (k == 0) m.name = json_.string();
      else each_item(json_, [&] { primitive(m.primitives.emplace_back()); });
    });
  }

  void primitive(tinygltf::Primitive& p) {
    p.mode = TINYGLTF_MODE_TRIANGLES;
    const Keys read = object({"attributes", "indices", "material", "mode"}, [&](std::size_t k, Keys&) {
      switch (k) {
        case 0:
          json_.open_object();
          for (std::string_view name; json_.next_key(name);) {
            if (!p.attributes.emplace(std::string(name), json_.index()).second) decline();
          }
          break;
        case 1: p.indices = json_.index(); break;
        case 2: p.material = json_.index(); break;
        case 3: p.mode = json_.index(); break;
      }
    });
    // tinygltf drops a primitive without attributes.
    if (!read.seen(0)) decline();
  }

  // Materials play no part in inference; tinygltf refuses only some
  // factors' lengths, which the plain form fixes.
  void material() {
    object({"name", "pbrMetallicRoughness"}, [&](std::size_t k, Keys&) {
      if (k == 0) {
        json_.string();
        return;
      }
      object({"baseColorFactor", "metallicFactor", "roughnessFactor"}, [&](std::size_t f, Keys&) {
        if (f != 0) json_.number();
        else if (numbers(json_).size() != 4) decline();
      });
    });
  }

  void accessor() {
    tinygltf::Accessor& a = model_.accessors.emplace_back();
    const Keys read = object(
        {"bufferView", "byteOffset", "componentType", "normalized", "count", "type", "min", "max", "name"},
        [&](std::size_t k, Keys&) {
             switch (k) {
               case 0: a.bufferView = json_.index(); break;
               case 1: a.byteOffset = json_.unsigned_integer(); break;
               case 2: a.componentType = json_.index(); break;
               case 3: a.normalized = json_.boolean(); break;
               case 4: a.count = json_.unsigned_integer(); break;
               case 5: a.type = element_type(json_.string()); break;
               case 6: a.minValues = numbers(json_); break;
               case 7: a.maxValues = numbers(json_); break;
               case 8: a.name = json_.string(); break;
             }
           });
    // tinygltf requires these three, and refuses other component types.
    if (!read.seen(2) || !read.seen(4) || !read.seen(5)) decline();
    if (a.componentType < TINYGLTF_COMPONENT_TYPE_BYTE || a.componentType > TINYGLTF_COMPONENT_TYPE_DOUBLE) decline();
  }

  static int element_type(std::string_view name) {
    if (name == "SCALAR") return TINYGLTF_TYPE_SCALAR;
    if (name == "VEC2") return TINYGLTF_TYPE_VEC2;
    if (name == "VEC3") return TINYGLTF_TYPE_VEC3;
    if (name == "VEC4") return TINYGLTF_TYPE_VEC4;
    if (name == "MAT2") return TINYGLTF_TYPE_MAT2;
    if (name == "MAT3") return TINYGLTF_TYPE_MAT3;
    if (name == "MAT4") return TINYGLTF_TYPE_MAT4;
    decline();
  }

  void buffer_view() {
    tinygltf::BufferView& v = model_.bufferViews.emplace_back();
    const Keys read =
        object({"buffer", "byteOffset", "byteLength", "byteStride", "target", "name"}, [&](std::size_t k, Keys&) {
          switch (k) {
            case 0: v.buffer = json_.index(); break;
            case 1: v.byteOffset = json_.unsigned_integer(); break;
            case 2: v.byteLength = json_.unsigned_integer(); break;
            case 3: v.byteStride = json_.unsigned_integer(); break;
            case 4: v.target = json_.index(); break;
            case 5: v.name = json_.string(); break;
          }
        });
    if (!read.seen(0) || !read.seen(2) || v.byteStride > 252 || v.byteStride % 4 != 0) decline();
    if (v.target != TINYGLTF_TARGET_ARRAY_BUFFER && v.target != TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER) v.target = 0;
  }

  // A buffer without a URI is the binary chunk (its first byteLength bytes).
  void buffer() {
    tinygltf::Buffer& b = model_.buffers.emplace_back();
    std::optional<std::uint64_t> length;
    object({"byteLength", "name"}, [&](std::size_t k, Keys&) {
      if (k == 0) length = json_.unsigned_integer();
      else b.name = json_.string();
    });
    // tinygltf throws on a buffer of byteLength 0 in a GLB.
    if (!length || *length == 0 || bin_.empty() || *length > bin_.size()) decline();
    b.data.assign(bin_.begin(), bin_.begin() + static_cast<std::ptrdiff_t>(*length));
  }

  JsonCursor json_;
  std::span<const unsigned char> bin_;
  tinygltf::Model model_;
  bool version_ = false;
};

}  // namespace

std::optional<tinygltf::Model> read_plain_glb(std::span<const unsigned char> bytes) {
  // The container as glb_chunks checks it, and as tinygltf reads it: what
  // follows the JSON chunk is the BIN chunk, of 4 bytes or more.
  const GlbChunks chunks = glb_chunks(bytes);
  if (!chunks.problem.empty()) return std::nullopt;
  if (kGlbJsonOffset + chunks.json.size() != bytes.size() && (!chunks.has_bin || chunks.bin.size() < 4))
    return std::nullopt;
  const std::string_view text(reinterpret_cast<const char*>(chunks.json.data()), chunks.json.size());
  try {
    return Reader(text, chunks.bin).read();
  } catch (const Declined&) {
    return std::nullopt;
  }
}

namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// The first difference in the fields load_gltf_example reads, or "".
std::string read_fields_difference(const tinygltf::Model& a, const tinygltf::Model& b) {
  if (a.asset.version != b.asset.version || a.asset.minVersion != b.asset.minVersion) return "asset version";
  if (a.extensionsUsed != b.extensionsUsed || a.extensionsRequired != b.extensionsRequired) return "extensions";
  if (a.defaultScene != b.defaultScene) return "default scene";
  if (a.scenes.size() != b.scenes.size()) return "scene count";
  for (std::size_t i = 0; i < a.scenes.size(); ++i)
    if (a.scenes[i].nodes != b.scenes[i].nodes) return "scene " + std::to_string(i) + " nodes";
  if (a.nodes.size() != b.nodes.size()) return "node count";
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const tinygltf::Node &x = a.nodes[i], &y = b.nodes[i];
    const std::string node = "node " + std::to_string(i);
    if (x.name != y.name) return node + " name";
    if (x.mesh != y.mesh) return node + " mesh";
    if (x.children != y.children) return node + " children";
    if (!same_bits(x.matrix, y.matrix)) return node + " matrix";
    if (!same_bits(x.translation, y.translation)) return node + " translation";
    if (!same_bits(x.rotation, y.rotation)) return node + " rotation";
    if (!same_bits(x.scale, y.scale)) return node + " scale";
    if (x.extensions.count("EXT_mesh_gpu_instancing") != y.extensions.count("EXT_mesh_gpu_instancing"))
      return node + " instancing";
  }
  if (a.meshes.size() != b.meshes.size()) return "mesh count";
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    const auto &x = a.meshes[i].primitives, &y = b.meshes[i].primitives;
    const std::string mesh = "mesh " + std::to_string(i);
    if (x.size() != y.size()) return mesh + " primitive count";
    for (std::size_t p = 0; p < x.size(); ++p) {
      if (x[p].attributes != y[p].attributes) return mesh + " primitive " + std::to_string(p) + " attributes";
      if (x[p].indices != y[p].indices) return mesh + " primitive " + std::to_string(p) + " indices";
      if (x[p].mode != y[p].mode) return mesh + " primitive " + std::to_string(p) + " mode";
    }
  }
  if (a.accessors.size() != b.accessors.size()) return "accessor count";
  for (std::size_t i = 0; i < a.accessors.size(); ++i) {
    const tinygltf::Accessor &x = a.accessors[i], &y = b.accessors[i];
    if (x.bufferView != y.bufferView || x.byteOffset != y.byteOffset || x.componentType != y.componentType ||
        x.count != y.count || x.type != y.type || x.normalized != y.normalized ||
        x.sparse.isSparse != y.sparse.isSparse)
      return "accessor " + std::to_string(i);
  }
  if (a.bufferViews.size() != b.bufferViews.size()) return "buffer view count";
  for (std::size_t i = 0; i < a.bufferViews.size(); ++i) {
    const tinygltf::BufferView &x = a.bufferViews[i], &y = b.bufferViews[i];
    if (x.buffer != y.buffer || x.byteOffset != y.byteOffset || x.byteLength != y.byteLength ||
        x.byteStride != y.byteStride)
      return "buffer view " + std::to_string(i);
  }
  if (a.buffers.size() != b.buffers.size()) return "buffer count";
  for (std::size_t i = 0; i < a.buffers.size(); ++i)
    if (a.buffers[i].uri != b.buffers[i].uri || a.buffers[i].data != b.buffers[i].data)
      return "buffer " + std::to_string(i) + " data";
  return "";
}

}  // namespace

std::string plain_glb_disagreement(std::span<const unsigned char> bytes) {
  const std::optional<tinygltf::Model> plain = read_plain_glb(bytes);
  if (!plain || bytes.size() > std::numeric_limits<unsigned int>::max()) return "";
  // A plain file names no other file and holds no image: tinygltf's own
  // file and image callbacks are never called.
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  try {
    if (!loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), ""))
      return "read as a plain GLB, but tinygltf refuses it: " + err;
  } catch (const std::logic_error& e) {
    return "read as a plain GLB, but tinygltf throws on it: " + std::string(e.what());
  }
  const std::string difference = read_fields_difference(*plain, model);
  return difference.empty() ? "" : "read as a plain GLB, its " + difference + " differs from tinygltf's";
}

}  // namespace vern
