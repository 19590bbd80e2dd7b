// Reading labelled OBJ: one mesh per named object.
//
// A labelled OBJ names each part of a building with an `o name` statement
// (or `g name` in files that have no `o` at all): what the OBJ writer
// produces and what inference reads. The reader streams the text in large
// blocks, so a file is never held whole in memory, and hands each object
// over as soon as its faces are read: memory grows with the file's
// vertices (a face may use any vertex before it) and whatever the caller
// keeps, and a line longer than kMaxObjLine (binary data, a file without
// line breaks) is an error rather than a string as long as the file.
//
// Read: v (x y z, extra w or colour values ignored), vt (u [v [w]]), vn,
// f with corners v, v/vt, v//vn or v/vt/vn, indices from 1 or negative
// (counting back from the latest element), `\` line continuations.
// Ignored: comments, mtllib, usemtl, s, l, p and the free-form geometry
// statements. Names are kept exactly as written ("window.001" stays).
//
// Up axis (up_axis.hpp): objects come out z-up, the grammar's frame. A file
// declares its own with a comment line `# up y` or `# up z` before its
// first vertex (what the OBJ writer puts at its top); files Vernacular
// wrote before it declared one (a first line "# Written by Vernacular..."
// or "# Vernacular built-in primitive...") are z-up; any other file is
// read with ObjLimits::undeclared_up, y by default, as Blender writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <string>
#include <vector>

#include "forward/mesh.hpp"
#include "io/up_axis.hpp"

namespace vern {

struct ObjObject {
  // As written after `o`/`g` (trimmed); empty for faces that come before
  // any `o`/`g` statement: the caller decides what those are. The label
  // the name carries is graph/label.hpp's to say (read_label).
  std::string name;
  // The line of the `o`/`g` statement, or of the first face of an unnamed
  // object: for messages that point at the object.
  std::uint32_t line = 0;
  // In a file that names parts with `o`: how many `g` statements came
  // before the object's `o`. Exporters that group objects write one `g`
  // per group (a building of a scene: inverse/load/scene_buildings.hpp), so
  // objects of one group share this number. Without `o`, each `g` is a
  // part and its own group.
  std::uint32_t group = 0;
  // Only the vertices, normals and texture coordinates this object's faces
  // use, re-indexed from 0 in order of first use.
  Mesh mesh;
};

// The longest line (or `\`-continued statement) read, in bytes.
inline constexpr std::size_t kMaxObjLine = std::size_t{1} << 20;

// Vertex coordinates beyond this magnitude are refused: a double there no
// longer holds a millimetre, and sums and differences of such coordinates
// (extents, scopes) would overflow to inf.
inline constexpr double kMaxObjCoordinate = 1e12;

struct ObjLimits {
  // Objects with faces beyond which reading stops with a Limit error,
  // before the rest of the file is read (0: no limit)...
  std::size_t max_objects = 0;
  // ...and what that error tells the user to do (the caller's flag).
  std::string too_many_hint;
  // The same for the faces of one object (or group, in a file without `o`).
  std::size_t max_faces = 0;
  std::string too_many_faces_hint;
  // Not a limit, but how every file is read: the up axis of a file that
  // does not declare one (see the top of this file; infer/check --up).
  UpAxis undeclared_up = UpAxis::Y;
};

// The objects of an OBJ text in file order, one per `o` (or `g`) statement
// even when names repeat. Objects without faces are left out.
// Throws vern::Error (Input) naming source_name:line:column for a face index
// that is 0 or out of range, a coordinate that is not a finite number or
// beyond kMaxObjCoordinate, a face with fewer than 3 corners, a name that
// is not UTF-8, or text that is not OBJ (a NUL byte, an unknown statement
// before any OBJ statement, a line longer than kMaxObjLine), a `# up`
// declaration naming another axis than y or z, or coming after a vertex;
// (Limit) past limits.max_objects or limits.max_faces.
std::vector<ObjObject> read_obj(std::istream& in, const std::string& source_name, const ObjLimits& limits = {});

// The same for a file; throws vern::Error (Io) when it is missing, a folder
// or unreadable.
std::vector<ObjObject> read_obj_file(const std::filesystem::path& path, const ObjLimits& limits = {});

// Streaming forms: each object, in the same order, is handed to `each` when
// its last face has been read, in a buffer the next object reuses (copy
// what you keep). An error may come after some objects were handed over.
// read_ahead: a second thread reads and parses the lines ahead (the
// objects and errors are the same; `each` runs on the calling thread).
using ObjObjectSink = std::function<void(const ObjObject&)>;
void read_obj(std::istream& in, const std::string& source_name, const ObjLimits& limits, const ObjObjectSink& each,
              bool read_ahead = false);
void read_obj_file(const std::filesystem::path& path, const ObjLimits& limits, const ObjObjectSink& each,
                   bool read_ahead = false);

}  // namespace vern
