#include "io/gltf_summary.hpp"

#include <cstring>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

// Declarations only: Debian's libtinygltf-dev ships the implementation as a
// shared library (see gltf_writer.cpp's history and CMakeLists.txt).
#include <tiny_gltf.h>

#include "base/error.hpp"

namespace vern {

namespace {

// The floats of one element of an accessor (tightly packed or strided).
template <std::size_t N>
std::array<float, N> element(const tinygltf::Model& model, int accessor_index, std::size_t i) {
  const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(accessor_index));
  const tinygltf::BufferView& v = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const tinygltf::Buffer& b = model.buffers.at(static_cast<std::size_t>(v.buffer));
  const std::size_t stride = v.byteStride != 0 ? v.byteStride : N * sizeof(float);
  const std::size_t at = v.byteOffset + a.byteOffset + i * stride;
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || at + N * sizeof(float) > b.data.size()) {
    fail(ErrorKind::Input, "glTF data", {}, "an instance accessor is not float data inside its buffer",
         "check the file with scripts/validate-gltf");
  }
  std::array<float, N> out{};
  std::memcpy(out.data(), b.data.data() + at, N * sizeof(float));
  return out;
}

std::vector<std::array<double, 16>> instances(const tinygltf::Model& model, const tinygltf::Node& n) {
  const auto ext = n.extensions.find("EXT_mesh_gpu_instancing");
  if (ext == n.extensions.end()) return {};
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  auto index = [&](const char* name) {
    return attributes.Has(name) ? attributes.Get(name).GetNumberAsInt() : -1;
  };
  const int t = index("TRANSLATION"), r = index("ROTATION"), s = index("SCALE");
  const int any = t >= 0 ? t : r >= 0 ? r : s;
  if (any < 0) return {};
  const std::size_t count = model.accessors.at(static_cast<std::size_t>(any)).count;
  std::vector<std::array<double, 16>> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    glm::dvec3 translation(0.0), scale(1.0);
    glm::dquat rotation(1.0, 0.0, 0.0, 0.0);
    if (t >= 0) {
      const auto e = element<3>(model, t, i);
      translation = {e[0], e[1], e[2]};
    }
    if (r >= 0) {
      const auto e = element<4>(model, r, i);  // stored x, y, z, w
      rotation = glm::dquat(e[3], e[0], e[1], e[2]);
    }
    if (s >= 0) {
      const auto e = element<3>(model, s, i);
      scale = {e[0], e[1], e[2]};
    }
    const glm::dmat3 turn = glm::mat3_cast(rotation);
    for (int c = 0; c < 3; ++c) {
      for (int row = 0; row < 3; ++row) out[i][static_cast<std::size_t>(4 * c + row)] = turn[c][row] * scale[c];
      out[i][static_cast<std::size_t>(12 + c)] = translation[c];
    }
    out[i][15] = 1.0;
  }
  return out;
}

}  // namespace

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
  s.extensions_required = model.extensionsRequired;
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
    node.instances = instances(model, n);
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
