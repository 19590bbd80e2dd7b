// glTF in (JSON, or binary GLB when it starts with the "glTF" magic): the
// example loader takes it, or says what is wrong with the file or which
// limit it reaches (a small file may place one mesh many times over:
// --max-faces, --max-total-faces); what it takes must keep the example's
// promises. A GLB the plain reader reads (io/plain_glb.hpp) must read
// the same through tinygltf.
#include <cstring>

#include "entries.hpp"
#include "example_invariants.hpp"
#include "io/plain_glb.hpp"
#include "scratch_file.hpp"
#include "verdict.hpp"

namespace vern::fuzz {

std::string gltf_loader(Bytes input) {
  const bool binary = input.size() >= 4 && std::memcmp(input.data(), "glTF", 4) == 0;
  if (binary) {
    if (std::string d = plain_glb_disagreement(input); !d.empty()) return d;
  }
  const std::string path = scratch_file(binary ? "fuzz.glb" : "fuzz.gltf", input).string();
  return judged([&] { return example_invariants(load_example(path)); }, {ErrorKind::Input, ErrorKind::Limit}, path);
}

}  // namespace vern::fuzz
