#include "io/gltf_rules.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "base/number_format.hpp"

namespace vern {

namespace {

const char* const kHint = "export the file again, or check it with scripts/validate-gltf";

[[noreturn]] void broken(const std::string& source, const std::string& problem, const std::string& hint = kHint) {
  fail(ErrorKind::Input, source, {}, problem, hint);
}

std::string count_of(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string node_text(const tinygltf::Model& model, std::size_t i) {
  const std::string& name = model.nodes[i].name;
  return "node " + std::to_string(i) + (name.empty() ? "" : " '" + name + "'");
}

// "2.0" -> {2, 0}; nothing unless it is <major>.<minor>, both digits only.
std::optional<std::pair<unsigned, unsigned>> version_of(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == text.size()) return std::nullopt;
  unsigned major = 0, minor = 0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto m = std::from_chars(begin, begin + dot, major);
  const auto n = std::from_chars(begin + dot + 1, end, minor);
  if (m.ec != std::errc() || m.ptr != begin + dot || n.ec != std::errc() || n.ptr != end) return std::nullopt;
  if (!std::all_of(begin, end, [](char c) { return c == '.' || (c >= '0' && c <= '9'); })) return std::nullopt;
  return std::pair{major, minor};
}

void check_asset(const tinygltf::Model& model, const std::string& source) {
  const auto version = version_of(model.asset.version);
  if (!version) {
    broken(source, "asset.version '" + model.asset.version + "' is not a glTF version (major.minor, e.g. 2.0)");
  }
  if (version->first != 2) {
    broken(source, "asset.version is " + model.asset.version + ": only glTF 2 files are read",
           "export the file as glTF 2.0");
  }
  if (model.asset.minVersion.empty()) return;
  const auto min = version_of(model.asset.minVersion);
  if (!min || *min > *version) {
    broken(source, "asset.minVersion '" + model.asset.minVersion + "' is not a glTF version at most its version " +
                       model.asset.version);
  }
  if (*min > std::pair{2u, 0u}) {
    broken(source, "asset.minVersion is " + model.asset.minVersion + ": the file needs glTF " +
                       model.asset.minVersion + " features, and this reader implements glTF 2.0",
           "export the file as glTF 2.0");
  }
}

// Extensions a file may require: those the loader reads, and those that
// only change how a surface looks, which inference does not read.
bool may_be_required(const std::string& name) {
  if (name == "EXT_mesh_gpu_instancing" || name == "KHR_mesh_quantization") return true;
  if (name == "EXT_meshopt_compression" || name == "KHR_draco_mesh_compression") return true;  // gltf_compression.hpp
  for (const char* look : {"KHR_materials_", "KHR_texture_", "EXT_texture_"})
    if (name.starts_with(look)) return true;
  return name == "KHR_lights_punctual";
}

void check_extensions(const tinygltf::Model& model, const std::string& source) {
  for (const std::string& name : model.extensionsRequired) {
    if (!may_be_required(name)) {
      broken(source,
             "requires the extension " + name +
                 ", which this reader does not implement: read without it, the file's geometry would be wrong",
             "export the file again without " + name + " (compression and the like are export options)");
    }
    if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), name) == model.extensionsUsed.end()) {
      broken(source, "requires the extension " + name + " but does not list it in extensionsUsed");
    }
  }
}

bool finite(const std::vector<double>& numbers) {
  return std::all_of(numbers.begin(), numbers.end(), [](double v) { return std::isfinite(v); });
}

// Whether a column-major 4x4 matrix is T * R * S: last row 0 0 0 1 and
// the first three columns at right angles (no shear), within what float
// rounding in an exporter leaves.
bool is_trs(const std::vector<double>& m) {
  if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0) return false;
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      double dot = 0.0, la = 0.0, lb = 0.0;
      for (int r = 0; r < 3; ++r) {
        const double x = m[static_cast<std::size_t>(4 * a + r)], y = m[static_cast<std::size_t>(4 * b + r)];
        dot += x * y;
        la += x * x;
        lb += y * y;
      }
      if (std::abs(dot) > 1e-4 * std::sqrt(la * lb)) return false;
    }
  }
  return true;
}

void check_transform(const tinygltf::Model& model, std::size_t i, const std::string& source) {
  const tinygltf::Node& n = model.nodes[i];
  auto sized = [&](const std::vector<double>& numbers, const char* what, std::size_t size) {
    if (!numbers.empty() && numbers.size() != size) {
      broken(source, node_text(model, i) + " has a " + what + " of " + count_of(numbers.size(), "number", "numbers") +
                         ", not " + std::to_string(size));
    }
    if (!finite(numbers)) broken(source, node_text(model, i) + "'s " + what + " holds a number that is not finite");
  };
  sized(n.matrix, "matrix", 16);
  sized(n.translation, "translation", 3);
  sized(n.rotation, "rotation", 4);
  sized(n.scale, "scale", 3);
  if (!n.matrix.empty() && !is_trs(n.matrix)) {
    broken(source, node_text(model, i) +
                       "'s matrix is not a translation, rotation and scale: its last row is not 0 0 0 1, or it shears");
  }
  if (!n.rotation.empty()) {
    const double length = std::sqrt(n.rotation[0] * n.rotation[0] + n.rotation[1] * n.rotation[1] +
                                    n.rotation[2] * n.rotation[2] + n.rotation[3] * n.rotation[3]);
    if (std::abs(length - 1.0) > 1e-3) {
      broken(source, node_text(model, i) + "'s rotation is not a unit quaternion (its length is " +
                         format_number(length) + ")");
    }
  }
}

// Children exist; each node has one parent at most and is not its own
// ancestor: nodes form trees.
void check_node_trees(const tinygltf::Model& model, const std::string& source) {
  const std::size_t n = model.nodes.size();
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> parent(n, kNone);
  for (std::size_t i = 0; i < n; ++i) {
    for (const int c : model.nodes[i].children) {
      if (c < 0 || static_cast<std::size_t>(c) >= n) {
        broken(source, node_text(model, i) + " lists child " + std::to_string(c) + ", but the file has " +
                           count_of(n, "node", "nodes"));
      }
      const auto child = static_cast<std::size_t>(c);
      if (parent[child] != kNone) {
        broken(source, node_text(model, child) + " is the child of two nodes, " + node_text(model, parent[child]) +
                           " and " + node_text(model, i) + ": glTF nodes form trees");
      }
      parent[child] = i;
    }
  }
  // Walking up from each node ends at a root unless it meets a cycle;
  // every node is passed on one walk only.
  std::vector<std::size_t> walk(n, kNone);  // the walk that passed the node
  for (std::size_t start = 0; start < n; ++start) {
    for (std::size_t i = start; i != kNone && walk[i] == kNone; i = parent[i]) {
      walk[i] = start;
      if (parent[i] != kNone && walk[parent[i]] == start) {
        broken(source, node_text(model, parent[i]) + " is its own ancestor (a cycle through " + node_text(model, i) +
                           "): glTF nodes form trees");
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const int mesh = model.nodes[i].mesh;
    if (mesh < -1 || (mesh >= 0 && static_cast<std::size_t>(mesh) >= model.meshes.size())) {
      broken(source, node_text(model, i) + " refers to mesh " + std::to_string(mesh) + ", but the file has " +
                         count_of(model.meshes.size(), "mesh", "meshes"));
    }
    check_transform(model, i, source);
  }
  for (std::size_t s = 0; s < model.scenes.size(); ++s) {
    const std::vector<int>& roots = model.scenes[s].nodes;
    for (std::size_t k = 0; k < roots.size(); ++k) {
      const int r = roots[k];
      const std::string scene = "scene " + std::to_string(s);
      if (r < 0 || static_cast<std::size_t>(r) >= n) {
        broken(source, scene + " lists node " + std::to_string(r) + ", but the file has " +
                           count_of(n, "node", "nodes"));
      }
      const auto root = static_cast<std::size_t>(r);
      if (parent[root] != kNone) {
        broken(source, scene + " lists " + node_text(model, root) + ", the child of " +
                           node_text(model, parent[root]) + ": a scene lists root nodes only");
      }
      if (std::find(roots.begin(), roots.begin() + static_cast<std::ptrdiff_t>(k), r) !=
          roots.begin() + static_cast<std::ptrdiff_t>(k)) {
        broken(source, scene + " lists " + node_text(model, root) + " twice");
      }
    }
  }
}

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // INT and DOUBLE are tinygltf's, not glTF's
  }
}

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return " (POINTS)";
    case TINYGLTF_MODE_LINE: return " (LINES)";
    case TINYGLTF_MODE_LINE_LOOP: return " (LINE_LOOP)";
    case TINYGLTF_MODE_LINE_STRIP: return " (LINE_STRIP)";
    default: return ", which is not a glTF primitive mode";
  }
}

}  // namespace

void check_gltf_file_rules(const tinygltf::Model& model, const std::string& source) {
  check_asset(model, source);
  check_extensions(model, source);
  check_node_trees(model, source);
  if (model.defaultScene < -1 ||
      (model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) >= model.scenes.size())) {
    broken(source, "the default scene is scene " + std::to_string(model.defaultScene) + ", but the file has " +
                       count_of(model.scenes.size(), "scene", "scenes"));
  }
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    if (model.meshes[m].primitives.empty()) broken(source, "mesh " + std::to_string(m) + " has no primitives");
  }
  for (std::size_t b = 0; b < model.buffers.size(); ++b) {
    if (b > 0 && model.buffers[b].uri.empty()) {
      broken(source, "buffer " + std::to_string(b) + " has no URI: only a GLB's first buffer may be its BIN chunk");
    }
  }
}

std::string accessor_problem(const tinygltf::Model& model, int index, AccessorUse use) {
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::size_t buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data.size();
  const std::string which = "(accessor " + std::to_string(index) + ") ";
  const int size = component_size(a.componentType);
  if (size == 0) return which + "has componentType " + std::to_string(a.componentType) + ", not one glTF defines";
  if (a.count == 0) return which + "has count 0: an accessor holds at least one element";
  if (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                       a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
    return which + "is normalized, which FLOAT and UNSIGNED_INT components may not be";
  }
  const std::string in_view = "buffer view " + std::to_string(a.bufferView);
  if (view.byteLength == 0 || view.byteOffset > buffer || view.byteLength > buffer - view.byteOffset) {
    return which + "lies in " + in_view + ", which is empty or lies past the end of its buffer";
  }
  const auto align = static_cast<std::size_t>(use == AccessorUse::VertexAttribute ? std::max(size, 4) : size);
  if (a.byteOffset % align != 0 || (view.byteOffset + a.byteOffset) % static_cast<std::size_t>(size) != 0) {
    return which + "starts at byteOffset " + std::to_string(a.byteOffset) + " in " + in_view +
           ", not aligned to its components (" + std::to_string(align) + " bytes)";
  }
  if (view.byteStride != 0) {
    if (use == AccessorUse::Indices) return which + "holds indices in " + in_view + ", which has a byteStride";
    const auto components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const std::size_t element = static_cast<std::size_t>(size) * static_cast<std::size_t>(components);
    if (view.byteStride < element || view.byteStride % static_cast<std::size_t>(size) != 0) {
      return which + "has byteStride " + std::to_string(view.byteStride) + " (" + in_view +
             "), less than its elements' " + std::to_string(element) + " bytes or not a multiple of its components'";
    }
  }
  if (use == AccessorUse::Indices && a.type != TINYGLTF_TYPE_SCALAR) return which + "holds indices that are not SCALAR";
  return "";
}

std::string primitive_problem(const tinygltf::Model& model, const tinygltf::Primitive& p) {
  const int mode = p.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    return "has mode " + std::to_string(mode) + mode_name(mode) +
           ": only triangles (TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN: modes 4, 5, 6) make a part's surface";
  }
  const std::size_t accessors = model.accessors.size();
  auto missing = [&](int index) { return index < 0 || static_cast<std::size_t>(index) >= accessors; };
  if (p.indices < -1 || (p.indices >= 0 && missing(p.indices))) {
    return "names indices accessor " + std::to_string(p.indices) + ", but the file has " +
           count_of(accessors, "accessor", "accessors");
  }
  for (const auto& [name, index] : p.attributes) {
    if (missing(index)) {
      return "names " + name + " accessor " + std::to_string(index) + ", but the file has " +
             count_of(accessors, "accessor", "accessors");
    }
  }
  const std::size_t vertices = model.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))].count;
  for (const auto& [name, index] : p.attributes) {
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.count != vertices) {
      return "has " + std::to_string(vertices) + " POSITION elements but " + std::to_string(a.count) + " " + name +
             " elements: a primitive's attributes hold one element per vertex";
    }
    if ((name == "NORMAL" && a.type != TINYGLTF_TYPE_VEC3) || (name == "TEXCOORD_0" && a.type != TINYGLTF_TYPE_VEC2)) {
      return "has a " + name + " accessor of another type than " + (name == "NORMAL" ? "VEC3" : "VEC2");
    }
  }
  return "";
}

std::string index_count_problem(int mode, std::size_t indices) {
  if (mode == TINYGLTF_MODE_TRIANGLES && (indices == 0 || indices % 3 != 0)) {
    return "draws " + std::to_string(indices) + " vertex indices as TRIANGLES: not a multiple of 3";
  }
  if (mode != TINYGLTF_MODE_TRIANGLES && indices < 3) {
    return "draws " + std::to_string(indices) + " vertex indices as a strip or fan: fewer than 3";
  }
  return "";
}

bool is_restart_index(int component_type, std::uint32_t index) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return index == 0xFFu;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return index == 0xFFFFu;
    default: return index == 0xFFFFFFFFu;
  }
}

}  // namespace vern
