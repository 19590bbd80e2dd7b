// OBJ text in: the reader streams it into objects or says which line is
// wrong; what it reads must be well-formed meshes, and an example loaded
// from it must keep the example's promises.
#include <sstream>

#include "entries.hpp"
#include "example_invariants.hpp"
#include "io/obj_reader.hpp"
#include "scratch_file.hpp"
#include "verdict.hpp"

namespace vern::fuzz {

namespace {

std::string run(Bytes input) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(input.data()), input.size()));
  const std::vector<ObjObject> objects = read_obj(in, "fuzz.obj");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const ObjObject& o = objects[i];
    if (o.mesh.face_sizes.empty()) return "object " + std::to_string(i) + " has no faces but was kept";
    if (std::string broken = mesh_invariants(o.mesh); !broken.empty())
      return "object " + std::to_string(i) + " '" + o.name + "': " + broken;
    if (o.line == 0) return "object " + std::to_string(i) + " has no line";
  }
  if (objects.empty()) return "";

  // The same text as an example file: names become labels, points are
  // refused. The scratch path is what error messages must name.
  const std::string path = scratch_file("fuzz.obj", input).string();
  return judged([&] { return example_invariants(load_example(path)); }, {ErrorKind::Input}, path);
}

}  // namespace

std::string obj_loader(Bytes input) {
  return judged([&] { return run(input); }, {ErrorKind::Input}, "fuzz.obj");
}

}  // namespace vern::fuzz
