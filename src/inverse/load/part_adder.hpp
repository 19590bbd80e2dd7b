// Adding a file's labelled parts to an example: each part's box and
// positions, and the whole mesh of the first part of each label; an object
// of loose pieces whose boxes are apart is one part per piece
// (loose_parts.hpp). Shared by the OBJ and glTF loaders.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "base/error.hpp"
#include "forward/mesh.hpp"
#include "inverse/load/loose_parts.hpp"
#include "inverse/load/example.hpp"

namespace vern {

inline std::string too_many_parts_hint(const ExampleLimits& limits) {
  return "raise the limit with --max-parts (now " + std::to_string(limits.max_parts) +
         "), or split the example into smaller buildings";
}

inline std::string too_many_faces_hint(const ExampleLimits& limits) {
  return "raise the limit with --max-faces (now " + std::to_string(limits.max_faces) +
         "), or simplify the part's mesh (a decimate modifier)";
}

// Adds parts to an example: each one's box and positions, and the whole
// mesh of the first part of each label. An object of loose pieces whose
// boxes are apart becomes one part per piece (loose_parts.hpp).
class PartAdder {
 public:
  PartAdder(Example& example, const ExampleLimits& limits) : example_(example), limits_(limits) {}

  // Whether a part labelled `label` would not be the first of its label:
  // its mesh is not kept, only its box and positions.
  bool has_label(const std::string& label) const { return labels_.count(label) != 0; }

  // `label`: the part's (graph/label.hpp); `object`: how messages name the
  // part (its name in the file). `whole`: the mesh is known to be one loose
  // piece (a glTF mesh whole in its own coordinates, LocalMesh), so there
  // are no pieces to look for.
  // `group`: LabelledBox::group.
  void add(const std::string& label, std::uint32_t line, const Mesh& mesh, const std::string& object,
           std::uint32_t group, bool whole = false) {
    const std::vector<Mesh> pieces = whole ? std::vector<Mesh>{} : loose_pieces(mesh);
    if (!pieces.empty() && pieces_apart(pieces, default_tolerance(mesh.min_corner(), mesh.max_corner()))) {
      for (std::size_t k = 0; k < pieces.size(); ++k) {
        add_one(label, line, pieces[k],
                object + " (loose part " + std::to_string(k + 1) + " of " + std::to_string(pieces.size()) + ")")
            .group = group;
      }
    } else {
      LabelledBox& b = add_one(label, line, mesh, object);
      b.loose_pieces = static_cast<std::uint32_t>(std::max<std::size_t>(1, pieces.size()));
      b.group = group;
    }
  }

 private:
  LabelledBox& add_one(const std::string& label, std::uint32_t line, const Mesh& mesh, const std::string& object) {
    if (example_.boxes.size() >= limits_.max_parts) {
      fail(ErrorKind::Limit, example_.source, {line, line != 0 ? 1u : 0u},
           "more than " + std::to_string(limits_.max_parts) + " labelled parts: reading stopped at '" + object + "'",
           too_many_parts_hint(limits_));
    }
    LabelledBox b;
    b.label = label;
    b.min = mesh.min_corner();
    b.max = mesh.max_corner();
    b.object = object;
    b.line = line;
    if (labels_.insert(b.label).second) {
      b.mesh = static_cast<std::uint32_t>(example_.meshes.size());
      example_.meshes.push_back(mesh);
    }
    example_.positions.add(mesh.positions, b.min, b.max);
    example_.boxes.push_back(std::move(b));
    return example_.boxes.back();
  }

  Example& example_;
  const ExampleLimits& limits_;
  std::unordered_set<std::string> labels_;
};

}  // namespace vern
