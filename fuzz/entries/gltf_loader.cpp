// glTF in (JSON, or binary GLB when it starts with the "glTF" magic): the
// example loader takes it or says what is wrong with the file; what it
// takes must keep the example's promises.
#include <cstring>

#include "entries.hpp"
#include "example_invariants.hpp"
#include "scratch_file.hpp"
#include "verdict.hpp"

namespace vern::fuzz {

std::string gltf_loader(Bytes input) {
  const bool binary = input.size() >= 4 && std::memcmp(input.data(), "glTF", 4) == 0;
  const std::string path = scratch_file(binary ? "fuzz.glb" : "fuzz.gltf", input).string();
  return judged([&] { return example_invariants(load_example(path)); }, {ErrorKind::Input}, path);
}

}  // namespace vern::fuzz
