// One object made of several loose pieces: what Blender's Array modifier
// or joining objects (Ctrl+J) leaves, e.g. `o window` whose faces are
// three boxes side by side. Inference works on one box per part, so such
// an object is read as its pieces, each a part with the object's label,
// when their boxes are apart (they may touch); pieces whose boxes meet (a
// pane inside its frame) stay one part, and are named in the error should
// that part overlap another (Blender: Mesh > Separate > By Loose Parts).
#pragma once

#include <vector>

#include "forward/mesh.hpp"

namespace vern {

// The mesh's loose pieces: faces joined by a shared vertex, or by vertices
// at the very same position (glTF repeats a corner for each normal), in
// order of their first face, each with only the positions, normals and
// uvs it uses (in the order it first uses them). One piece: {} (the mesh
// is whole). Positions no face uses belong to no piece.
std::vector<Mesh> loose_pieces(const Mesh& mesh);

// Whether the insides of the pieces' boxes are apart, so that each piece
// can be a part of its own. As box splitting sees overlaps: solid boxes
// meet when they share more than a face (by more than `tolerance`), a flat
// box meets a solid one it lies strictly inside, and two flat ones meet
// at the same place.
bool pieces_apart(const std::vector<Mesh>& pieces, double tolerance);

}  // namespace vern
