#include "inverse/write/inferred_files.hpp"

#include "base/atomic_file.hpp"
#include "forward/terminal.hpp"
#include "io/obj_writer.hpp"

namespace fs = std::filesystem;

namespace vern {

fs::path meshes_path_for(const fs::path& grammar) { return fs::path(grammar).replace_extension(".prims.obj"); }

std::string path_from(const fs::path& grammar, const fs::path& file) {
  std::error_code ec;
  const fs::path base = fs::absolute(grammar, ec).parent_path();
  const fs::path rel = fs::relative(fs::absolute(file, ec), base, ec);
  return (ec || rel.empty()) ? fs::absolute(file, ec).string() : rel.generic_string();
}

std::string inferred_header(std::size_t examples, double tolerance, const fs::path& grammar) {
  return "# Inferred by Vernacular's infer from " + std::to_string(examples) + " example" +
         (examples == 1 ? "" : "s") + " (tolerance " + std::to_string(tolerance) +
         " m).\n# Regenerate buildings with: generate " + grammar.filename().string() + " -n 10 -o out/\n";
}

void write_inferred(const PrimitiveLibrary& primitives, std::string_view header, std::string_view text,
                    const fs::path& grammar, const fs::path& meshes, std::span<const AlsoWritten> also) {
  // The parts' meshes: one object per label, each filling the unit box.
  Scene scene;
  Variant all;
  all.name = "primitives";
  for (const auto& name : primitives.names()) {
    Terminal t;
    t.label = static_cast<LabelId>(scene.labels.size());
    scene.labels.push_back(name);
    all.terminals.push_back(t);
  }
  scene.variants.push_back(std::move(all));
  OutputFiles outputs;
  write_obj(scene, primitives, meshes, outputs);
  // Two pieces: the grammar's text (124 MB at a million parts) is not copied.
  const std::string_view pieces[] = {header, text};
  outputs.stage(grammar, pieces);
  for (const AlsoWritten& file : also) outputs.stage(file.path, file.content);
  outputs.commit();
}

}  // namespace vern
