// Reading labelled OBJ: one mesh per named object.
//
// A labelled OBJ names each part of a building with an `o name` statement
// (or `g name` in files that have no `o` at all): what the OBJ writer
// produces and what inference reads. The reader streams the text line by
// line, so a file is never held whole in memory.
//
// Read: v (x y z, extra w or colour values ignored), vt (u [v [w]]), vn,
// f with corners v, v/vt, v//vn or v/vt/vn, indices from 1 or negative
// (counting back from the latest element), `\` line continuations.
// Ignored: comments, mtllib, usemtl, s, l, p and the free-form geometry
// statements. Names are kept exactly as written ("window.001" stays).
#pragma once

#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "forward/mesh.hpp"

namespace vern {

struct ObjObject {
  // As written after `o`/`g` (trimmed); empty for faces that come before
  // any `o`/`g` statement: the caller decides what those are.
  std::string name;
  // The line of the `o`/`g` statement, or of the first face of an unnamed
  // object: for messages that point at the object.
  std::uint32_t line = 0;
  // Only the vertices, normals and texture coordinates this object's faces
  // use, re-indexed from 0 in order of first use.
  Mesh mesh;
};

// The objects of an OBJ text in file order, one per `o` (or `g`) statement
// even when names repeat. Objects without faces are left out.
// Throws vern::Error (Input) naming source_name:line:column for a face index
// that is 0 or out of range, a coordinate that is not a finite number, a
// face with fewer than 3 corners, or text that is not OBJ (a NUL byte, an
// unknown statement before any OBJ statement).
std::vector<ObjObject> read_obj(std::istream& in, const std::string& source_name);

// The same for a file; throws vern::Error (Io) when it is missing, a folder
// or unreadable.
std::vector<ObjObject> read_obj_file(const std::filesystem::path& path);

}  // namespace vern
