// The rules of glTF 2.0 that tinygltf leaves unchecked, for what the
// example loader reads of a file.
//
// tinygltf reads what the JSON says and leaves the rest to its caller: a
// child or scene node that does not exist, a byteStride shorter than an
// element, an extension the file requires and nothing here implements,
// primitive mode -1, an index count that is not whole triangles. Read as
// they come, each is a file misread in silence, so each is refused (exit 3)
// naming the node, mesh, primitive or accessor, after the specification's
// rules (registry.khronos.org/glTF/specs/2.0, "MUST"):
//
// - the asset's version is 2.x, and its minVersion, if any, at most 2.0;
// - every extension in extensionsRequired is one the loader implements or
//   one that only changes how a surface looks (materials, textures), and
//   is listed in extensionsUsed too;
// - the default scene exists; scenes list existing root nodes, once each;
// - nodes form trees: children exist, no node is its own ancestor or the
//   child of two; a node's mesh exists; its matrix has 16 numbers and is
//   a translation, rotation and scale (last row 0 0 0 1, columns at right
//   angles); translation and scale have 3 numbers, rotation 4 making a unit
//   quaternion; every number is finite;
// - every mesh has primitives; a primitive draws triangles (TRIANGLES,
//   TRIANGLE_STRIP, TRIANGLE_FAN: points and lines make no surface), of
//   whole triangles (a multiple of 3 vertex indices for TRIANGLES, 3 or
//   more for strips and fans); its attributes name existing accessors
//   holding one element per vertex, NORMAL of VEC3 and TEXCOORD_0 of VEC2;
// - an accessor it reads has a glTF component type, at least one element,
//   is not normalized when its components are FLOAT or UNSIGNED_INT, starts
//   aligned to its component size (vertex attributes: to 4 bytes), lies in
//   a buffer view that lies in its buffer, with a byteStride (if any) no
//   shorter than an element and a multiple of the component size;
//   indices are SCALAR, tightly packed (no byteStride) and never the
//   largest value of their type (which restarts a strip elsewhere);
// - in a GLB, only the first buffer may have no URI (the BIN chunk).
//
// The GLB container is checked before (glb_chunks.hpp). Rules about what
// the loader does not read (materials, textures, animations, skins,
// POSITION's min and max) are left to scripts/validate-gltf.
#pragma once

#include <string>

#include <tiny_gltf.h>

namespace vern {

// Throws vern::Error (Input) naming `source` and what breaks a rule above
// that concerns the whole file (asset, extensions, scenes, nodes, meshes,
// buffers); accessors and primitives are checked as they are read.
void check_gltf_file_rules(const tinygltf::Model& model, const std::string& source);

// What an accessor read as `use` breaks, said after "its POSITION
// accessor " ("(accessor 3) has byteStride 4, ..."), or "".
enum class AccessorUse { VertexAttribute, Indices, Other };
std::string accessor_problem(const tinygltf::Model& model, int index, AccessorUse use);

// What a primitive with a POSITION attribute breaks, said after "mesh 0
// primitive 1 " ("has mode -1, ..."), or "". Its accessors are checked
// with accessor_problem as they are read, and the number of vertex indices
// it draws, once read, with index_count_problem.
std::string primitive_problem(const tinygltf::Model& model, const tinygltf::Primitive& primitive);
std::string index_count_problem(int mode, std::size_t indices);

// An index a primitive may not hold: the largest value of its component
// type (255, 65535 or 4294967295), which some APIs read as a restart.
bool is_restart_index(int component_type, std::uint32_t index);

}  // namespace vern
