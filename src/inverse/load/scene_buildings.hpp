// A file of several buildings read as several examples: a Blender scene of
// houses, a street `generate -n 20 -o street.glb` wrote. Read as one
// example, such a file is a grammar of the whole street, and checked, it
// is "not derivable" by a grammar that derives each of its houses.
//
// How a file is divided (infer and check --buildings):
// - apart (the default): the file's groups (LabelledBox::group: top-level
//   glTF nodes, OBJ `g` groups; a Blender export has one object per group
//   by default) are gathered into pieces that empty space separates along
//   x or y: no part of one piece reaches across a gap, wider than the
//   tolerance, that runs between it and the others. When there are two
//   pieces or more and each stands on the ground (its lowest part as low
//   as the file's lowest), each piece is a building. Parts floating apart
//   (windows annotated on a facade with no wall) are not buildings, and
//   the file stays one example.
// - parts: the same, each part a group of its own (a scene whose houses
//   one node holds).
// - groups: each group is a building, wherever it stands.
// - file: the file is one example.
// Buildings come out in the order of their first part in the file, each
// with its parts in file order, named "FILE (building K of N)".
#pragma once

#include <string>
#include <vector>

#include "inverse/load/example.hpp"

namespace vern {

enum class BuildingsMode { Apart, Parts, Groups, File };

struct SceneBuildings {
  // The file's buildings (one: the file itself), each with its bounds,
  // positions and canonical meshes.
  std::vector<Example> buildings;
  // What the user should know, "" when nothing: that the file was divided
  // and how to undo it, or (apart) that its groups hold together what
  // looks like several buildings standing apart, and how to divide it.
  std::string note;
};

// `file` divided as `mode` says. `tolerance`: the file's
// (example_tolerance); gaps no wider are not gaps.
SceneBuildings scene_buildings(Example file, BuildingsMode mode, double tolerance);

}  // namespace vern
