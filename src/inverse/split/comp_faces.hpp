// A mass model's faces: comp(f) read back from flat parts (issue 23).
//
// The CGA idiom for a house is a mass cut into its faces,
//     house --> comp(f){ front : facade | back : facade | left : I(wall) | top : I(roof) }
// each face a scope of no thickness, facades split on it. Its buildings
// are flat parts round an open box: the walls meet at the corners, so no
// straight cut separates them (the left wall stands in the way of every
// cut through the front along x, and the front in the way of every cut
// along y), and box splitting alone finds a pinwheel. Where every part
// of such a container is flat and lies on one of the container's faces,
// and the parts on each face cover it, the container is comp(f): each
// face's parts, in that face's own frame as derive() gives it
// (forward/scope.hpp face_scope: the front's x along the building's x
// and its y up, the left's x along -y...), are split as any facade is.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "graph/node.hpp"
#include "inverse/load/example.hpp"
#include "inverse/load/orientation.hpp"
#include "inverse/split/box_split.hpp"

namespace vern {

// One face of a container and the parts on it.
struct FaceParts {
  Face face = Face::Front;
  std::vector<std::uint32_t> boxes;  // indices of the parts on it
  std::vector<LabelledBox> local;    // the same parts in the face's frame: x, y across it, z = 0
  glm::dvec3 size{0.0};              // the face's size in its frame (z = 0)
};

// The faces of the container [min, max] that the parts `group` (indices
// into boxes) lie on, front, back, left, right, top, bottom as present,
// or nothing: some part not flat on one of the container's faces (within
// `tolerance`), fewer than two faces, or a face its parts leave partly
// bare (where its split would begin is unknown).
std::optional<std::vector<FaceParts>> comp_faces(const std::vector<LabelledBox>& boxes,
                                                 const std::vector<std::uint32_t>& group, glm::dvec3 min,
                                                 glm::dvec3 max, double tolerance);

// The turns of the parts on comp faces below each example's tree
// (trees[i] split from examples[i]), as each face's frame sees them: a
// wall on the left face is the front's wall unturned in its own frame,
// where the world sees it turned a quarter about z. Replaces those parts'
// turns in oriented.turns; a part whose mesh is no turn of its label's
// there keeps none. A label whose parts all lie on faces, all turned
// alike (a flat wall's mesh, taken from the world where it lies along x
// and z, is turned a quarter about x in every face's frame), has its
// canonical mesh turned so, and its parts none: `I(wall)`, not
// `R(x, pi / 2){ I(wall) }` wherever a wall stands.
void orient_face_parts(const std::vector<SplitTree>& trees, const std::vector<Example>& examples, double tolerance,
                       PartOrientations& oriented);

}  // namespace vern
