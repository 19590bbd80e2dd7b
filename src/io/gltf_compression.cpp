#include "io/gltf_compression.hpp"

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string_view>

#include "base/error.hpp"
#include "io/gltf_container.hpp"

namespace vern {

namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";
constexpr const char* kDraco = "KHR_draco_mesh_compression";
constexpr const char* kHint = "export the file again, or without compression";

[[noreturn]] void refuse(const std::string& source, const std::string& problem) {
  fail(ErrorKind::Input, source, {}, problem, kHint);
}

bool is_fallback(const nlohmann::ordered_json& buffer) {
  if (!buffer.is_object() || buffer.contains("uri")) return false;
  const auto ext = buffer.find("extensions");
  if (ext == buffer.end() || !ext->is_object()) return false;
  const auto meshopt = ext->find(kMeshopt);
  if (meshopt == ext->end() || !meshopt->is_object()) return false;
  const auto fallback = meshopt->find("fallback");
  return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

// A member of an extension object as a whole number in [0, max], or
// nothing when absent; anything else is refused.
std::optional<std::uint64_t> whole(const tinygltf::Value& object, const char* key, const std::string& where,
                                   const std::string& source, std::uint64_t max = std::uint64_t{1} << 52) {
  if (!object.Has(key)) return std::nullopt;
  const tinygltf::Value& v = object.Get(key);
  const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
  if (!(d >= 0) || d != std::floor(d) || d > static_cast<double>(max)) {
    refuse(source, where + "'s " + key + " is not a whole number from 0 to " + std::to_string(max));
  }
  return static_cast<std::uint64_t>(d);
}

std::uint64_t required(const tinygltf::Value& object, const char* key, const std::string& where,
                       const std::string& source, std::uint64_t max = std::uint64_t{1} << 52) {
  const auto v = whole(object, key, where, source, max);
  if (!v) refuse(source, where + " has no " + key);
  return *v;
}

std::string text_member(const tinygltf::Value& object, const char* key, const std::string& fallback) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  return v.IsString() ? v.Get<std::string>() : std::string("(not text)");
}

// Decoded data goes into buffers of its own, within the file's budget.
class Output {
 public:
  Output(tinygltf::Model& model, const std::string& source, std::uint64_t max_bytes)
      : model_(model), source_(source), max_bytes_(max_bytes) {}

  // Room for `bytes` more, or a Limit error saying what needed it.
  void reserve(std::uint64_t bytes, const std::string& what) {
    if (bytes > max_bytes_ - used_) {
      fail(ErrorKind::Limit, source_, {},
           what + " decodes to more than the limit of " + std::to_string(max_bytes_ >> 20) +
               " MiB for a file's data",
           "raise the limit with --max-gltf-mib (decoded data counts as the file's)");
    }
    used_ += bytes;
  }

  int add_buffer(std::vector<unsigned char> data) {
    tinygltf::Buffer b;
    b.data = std::move(data);
    model_.buffers.push_back(std::move(b));
    return static_cast<int>(model_.buffers.size() - 1);
  }

  int add_view(int buffer, std::size_t offset, std::size_t length) {
    tinygltf::BufferView v;
    v.buffer = buffer;
    v.byteOffset = offset;
    v.byteLength = length;
    model_.bufferViews.push_back(std::move(v));
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  int add_accessor(int view, int component, int type, std::size_t count) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = component;
    a.type = type;
    a.count = count;
    model_.accessors.push_back(std::move(a));
    return static_cast<int>(model_.accessors.size() - 1);
  }

 private:
  tinygltf::Model& model_;
  const std::string& source_;
  std::uint64_t max_bytes_;
  std::uint64_t used_ = 0;
};

// The bytes [offset, offset + length) of buffer `index`, checked.
std::span<const unsigned char> bytes_of(const tinygltf::Model& model, std::uint64_t index, std::uint64_t offset,
                                        std::uint64_t length, const std::string& where, const std::string& source) {
  if (index >= model.buffers.size()) {
    refuse(source, where + " reads buffer " + std::to_string(index) + ", but the file has " +
                       std::to_string(model.buffers.size()) + " buffers");
  }
  const std::vector<unsigned char>& data = model.buffers[index].data;
  if (offset > data.size() || length > data.size() - offset) {
    refuse(source, where + " reads bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) +
                       " of buffer " + std::to_string(index) + ", which holds " + std::to_string(data.size()));
  }
  return {data.data() + offset, length};
}

void decode_meshopt_view(tinygltf::Model& model, std::size_t index, Output& out, const std::string& source) {
  const std::string where = "buffer view " + std::to_string(index) + " (" + kMeshopt + ")";
  const tinygltf::Value ext = model.bufferViews[index].extensions.at(kMeshopt);
  if (!ext.IsObject()) refuse(source, where + " is not an object");
  const std::uint64_t buffer = required(ext, "buffer", where, source);
  const std::uint64_t offset = whole(ext, "byteOffset", where, source).value_or(0);
  const std::uint64_t length = required(ext, "byteLength", where, source);
  const std::uint64_t stride = required(ext, "byteStride", where, source, 256);
  const std::uint64_t count = required(ext, "count", where, source);
  const std::string mode = text_member(ext, "mode", "(none)");
  const std::string filter = text_member(ext, "filter", "NONE");
  const std::span<const unsigned char> packed = bytes_of(model, buffer, offset, length, where, source);

  // meshoptimizer asserts its preconditions: each is checked first.
  const bool attributes = mode == "ATTRIBUTES";
  if (attributes) {
    if (stride == 0 || stride % 4 != 0) refuse(source, where + " has byteStride " + std::to_string(stride) + " for ATTRIBUTES, not a multiple of 4 up to 256");
  } else if (mode == "TRIANGLES" || mode == "INDICES") {
    if (stride != 2 && stride != 4) refuse(source, where + " has byteStride " + std::to_string(stride) + " for " + mode + ", not 2 or 4");
    if (mode == "TRIANGLES" && count % 3 != 0) refuse(source, where + " holds " + std::to_string(count) + " indices, not whole triangles");
  } else {
    refuse(source, where + " has mode '" + mode + "', not ATTRIBUTES, TRIANGLES or INDICES");
  }
  const bool oct = filter == "OCTAHEDRAL", quat = filter == "QUATERNION", exp = filter == "EXPONENTIAL";
  if (filter != "NONE" && !(attributes && (oct || quat || exp))) {
    refuse(source, where + " has filter '" + filter + "', not NONE" + (attributes ? ", OCTAHEDRAL, QUATERNION or EXPONENTIAL" : " (the only filter of " + mode + ")"));
  }
  if ((oct && stride != 4 && stride != 8) || (quat && stride != 8)) {
    refuse(source, where + " has byteStride " + std::to_string(stride) + " for the filter " + filter);
  }
  if (count > (std::uint64_t{1} << 40) / stride) refuse(source, where + " holds " + std::to_string(count) + " elements");
  const std::uint64_t size = count * stride;
  out.reserve(size, where);

  std::vector<unsigned char> data(size);
  int rc = 0;
  if (attributes)
    rc = meshopt_decodeVertexBuffer(data.data(), count, stride, packed.data(), packed.size());
  else if (mode == "TRIANGLES")
    rc = meshopt_decodeIndexBuffer(data.data(), count, stride, packed.data(), packed.size());
  else
    rc = meshopt_decodeIndexSequence(data.data(), count, stride, packed.data(), packed.size());
  if (rc != 0) refuse(source, where + ": its data does not decode (meshoptimizer says " + std::to_string(rc) + ")");
  if (oct) meshopt_decodeFilterOct(data.data(), count, stride);
  if (quat) meshopt_decodeFilterQuat(data.data(), count, stride);
  if (exp) meshopt_decodeFilterExp(data.data(), count, stride);

  const int decoded = out.add_buffer(std::move(data));
  tinygltf::BufferView& view = model.bufferViews[index];
  view.buffer = decoded;
  view.byteOffset = 0;
  view.byteLength = size;
  if (attributes) view.byteStride = stride;
  view.extensions.erase(kMeshopt);
}

void decode_draco_primitive(tinygltf::Model& model, std::size_t m, std::size_t p, Output& out,
                            const std::string& source) {
  const std::string where = "primitive " + std::to_string(p) + " of mesh " + std::to_string(m) + " (" + kDraco + ")";
  const tinygltf::Value ext = model.meshes[m].primitives[p].extensions.at(kDraco);
  if (!ext.IsObject() || !ext.Has("attributes") || !ext.Get("attributes").IsObject()) {
    refuse(source, where + " has no attributes object");
  }
  const std::uint64_t view_index = required(ext, "bufferView", where, source);
  if (view_index >= model.bufferViews.size()) {
    refuse(source, where + " reads buffer view " + std::to_string(view_index) + ", but the file has " +
                       std::to_string(model.bufferViews.size()));
  }
  const tinygltf::BufferView& view = model.bufferViews[view_index];
  if (view.buffer < 0) refuse(source, where + " reads a buffer view without a buffer");
  const std::span<const unsigned char> packed =
      bytes_of(model, static_cast<std::uint64_t>(view.buffer), view.byteOffset, view.byteLength, where, source);
  const tinygltf::Value& names = ext.Get("attributes");
  if (!names.Has("POSITION")) refuse(source, where + " does not compress POSITION");
  const std::uint64_t position_id = required(names, "POSITION", where + "'s attributes", source, 0xffffffffu);

  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(packed.data()), packed.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) refuse(source, where + ": its data does not decode (Draco says: " + decoded.status().error_msg_string() + ")");
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  const draco::PointAttribute* position = mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(position_id));
  if (!position || position->num_components() != 3) {
    refuse(source, where + ": the Draco data has no position attribute " + std::to_string(position_id) + " of 3 numbers");
  }
  const std::uint64_t points = mesh->num_points(), faces = mesh->num_faces();
  if (faces == 0) refuse(source, where + ": the Draco data holds no triangles");
  out.reserve(12 * points + 12 * faces, where);

  std::vector<unsigned char> data(12 * points + 12 * faces);
  std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -std::numeric_limits<double>::infinity());
  for (draco::PointIndex i(0); i < mesh->num_points(); ++i) {
    float xyz[3] = {0, 0, 0};
    if (!position->ConvertValue<float>(position->mapped_index(i), 3, xyz)) refuse(source, where + ": a position does not decode");
    std::memcpy(data.data() + 12 * i.value(), xyz, 12);
    for (int a = 0; a < 3; ++a) {
      lo[static_cast<std::size_t>(a)] = std::min(lo[static_cast<std::size_t>(a)], static_cast<double>(xyz[a]));
      hi[static_cast<std::size_t>(a)] = std::max(hi[static_cast<std::size_t>(a)], static_cast<double>(xyz[a]));
    }
  }
  unsigned char* indices = data.data() + 12 * points;
  for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh->face(f)[static_cast<std::size_t>(k)].value();
      std::memcpy(indices + 12 * f.value() + 4 * static_cast<std::size_t>(k), &v, 4);
    }
  }
  const int b = out.add_buffer(std::move(data));
  const int positions = out.add_accessor(out.add_view(b, 0, 12 * points), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                         TINYGLTF_TYPE_VEC3, points);
  model.accessors[static_cast<std::size_t>(positions)].minValues = lo;
  model.accessors[static_cast<std::size_t>(positions)].maxValues = hi;
  const int triangle_corners = out.add_accessor(out.add_view(b, 12 * points, 12 * faces),
                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, 3 * faces);

  tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
  if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP) {
    refuse(source, where + " has mode " + std::to_string(primitive.mode) + ": Draco primitives are triangles");
  }
  // The compressed attributes' accessors hold no data of their own; the
  // loader reads positions only, so the others are dropped with them.
  for (const std::string& name : names.Keys()) primitive.attributes.erase(name);
  primitive.attributes["POSITION"] = positions;
  primitive.indices = triangle_corners;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.extensions.erase(kDraco);
}

}  // namespace

std::optional<std::vector<unsigned char>> prepared_for_tinygltf(std::span<const unsigned char> json_bytes,
                                                                const GlbChunks* glb) {
  const std::string_view json(reinterpret_cast<const char*>(json_bytes.data()), json_bytes.size());
  if (json.find("_compression") == std::string_view::npos) return std::nullopt;
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(json, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return std::nullopt;
  bool changed = false;
  if (doc.contains("buffers") && doc["buffers"].is_array()) {
    for (auto& buffer : doc["buffers"]) {
      if (!is_fallback(buffer)) continue;
      buffer["uri"] = "data:application/octet-stream;base64,AA==";
      buffer["byteLength"] = 1;
      changed = true;
    }
  }
  if (doc.contains("meshes") && doc["meshes"].is_array()) {
    for (auto& mesh : doc["meshes"]) {
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (auto& primitive : mesh["primitives"]) {
        if (!primitive.is_object() || !primitive.contains("indices") || !primitive.contains("extensions")) continue;
        const auto& ext = primitive["extensions"];
        if (!ext.is_object() || !ext.contains(kDraco)) continue;
        primitive.erase("indices");
        changed = true;
      }
    }
  }
  if (!changed) return std::nullopt;
  std::string new_json = doc.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  if (!glb) return std::vector<unsigned char>(new_json.begin(), new_json.end());
  // As the writer lays a GLB out (gltf_container.hpp); the BIN chunk is
  // 4-byte aligned already (glb_chunks checked it).
  const std::string head = glb_header(new_json.size(), glb->bin.size());
  const std::string between = glb_between(new_json.size(), glb->bin.size());
  std::vector<unsigned char> out;
  out.reserve(head.size() + new_json.size() + between.size() + glb->bin.size());
  out.insert(out.end(), head.begin(), head.end());
  out.insert(out.end(), new_json.begin(), new_json.end());
  out.insert(out.end(), between.begin(), between.end());
  out.insert(out.end(), glb->bin.begin(), glb->bin.end());
  return out;
}

void decode_compression(tinygltf::Model& model, const std::string& source, std::uint64_t max_bytes) {
  Output out(model, source, max_bytes);
  std::vector<bool> fallback(model.buffers.size(), false);
  for (std::size_t b = 0; b < model.buffers.size(); ++b) {
    const auto ext = model.buffers[b].extensions.find(kMeshopt);
    if (ext == model.buffers[b].extensions.end() || !ext->second.IsObject() || !ext->second.Has("fallback")) continue;
    const tinygltf::Value& f = ext->second.Get("fallback");
    fallback[b] = f.IsBool() && f.Get<bool>();
  }
  const std::size_t views = model.bufferViews.size();
  for (std::size_t v = 0; v < views; ++v) {
    if (model.bufferViews[v].extensions.count(kMeshopt) != 0) decode_meshopt_view(model, v, out, source);
    const int b = model.bufferViews[v].buffer;
    if (b >= 0 && static_cast<std::size_t>(b) < fallback.size() && fallback[static_cast<std::size_t>(b)]) {
      refuse(source, "buffer view " + std::to_string(v) + " reads buffer " + std::to_string(b) +
                         ", a fallback of " + kMeshopt + " that holds no data, and is not compressed itself");
    }
  }
  for (std::size_t m = 0; m < model.meshes.size(); ++m)
    for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p)
      if (model.meshes[m].primitives[p].extensions.count(kDraco) != 0) decode_draco_primitive(model, m, p, out, source);
}

}  // namespace vern
