// Files a run reads because another file names them: a glTF example's
// buffers and images, a grammar's @primitives file or folder. The input is
// a small folder tree (folder_tree.hpp) that the main file is placed in;
// it is read as infer and check read an example (load_example) or as
// generate reads a grammar and its primitives (read_grammar_file,
// primitives_for), with the real limits and --allow-outside-files off or on.
//
// Allowed outcomes: success, or a vern::Error of kind Input, Io or Limit
// that names a file. Beyond that, whatever the outcome:
//   - without outside files, nothing outside the main file's folder was
//     opened (the kernel's record of opens in every other folder of the
//     tree: folder_opens.hpp);
//   - nothing in the tree was written, made, removed or replaced;
// and on success the example keeps the example's promises (labels that are
// labels included), or every primitive is a label with a mesh that fills
// the unit box.
#include "entries.hpp"
#include "example_invariants.hpp"
#include "folder_opens.hpp"
#include "folder_snapshot.hpp"
#include "folder_tree.hpp"
#include "forward/primitive_sources.hpp"
#include "graph/parser.hpp"
#include "scratch_file.hpp"
#include "verdict.hpp"

namespace vern::fuzz {

namespace {

std::string load(const FolderTree& tree, const PlacedTree& placed) {
  if (tree.grammar) {
    const Grammar grammar = read_grammar_file(placed.main);
    return library_invariants(primitives_for(grammar, placed.main, std::nullopt, tree.outside_files));
  }
  ExampleLimits limits;
  limits.gltf.outside_folder = tree.outside_files;
  return example_invariants(load_example(placed.main, limits));
}

}  // namespace

std::string indirect_inputs(Bytes input) {
  static const std::filesystem::path root = scratch_folder("indirect");
  static FolderOpens opens;
  const FolderTree tree = decode_folder_tree(input);
  const PlacedTree placed = place_folder_tree(tree, root);
  const FolderSnapshot before = snapshot_folder(root);

  opens.watch(placed.outside_folders);
  // Errors name the main file or a file it names: below the root, unless
  // outside files may be named by absolute paths.
  std::string finding = judged([&] { return load(tree, placed); }, {ErrorKind::Input, ErrorKind::Io, ErrorKind::Limit},
                               tree.outside_files ? "/" : root.string());
  const std::vector<std::string> opened = opens.opened();

  if (finding.empty() && !tree.outside_files) {
    for (const std::string& path : opened) {
      // The root's watch sees in/ itself opened, which is inside.
      if (path == placed.inside.string()) continue;
      finding = "a file outside the folder of " + placed.main.filename().string() + " was opened: " + path;
      break;
    }
  }
  if (finding.empty()) {
    if (std::string changed = snapshot_difference(before, snapshot_folder(root)); !changed.empty())
      finding = "the run wrote in the folder tree: " + changed;
  }
  if (!finding.empty()) {
    finding += "\n--- folder tree (" + std::string(tree.outside_files ? "outside files allowed" : "no outside files") +
               ") in " + root.string() + ":\n" + excerpt(std::string(reinterpret_cast<const char*>(input.data()), input.size()));
  }
  return finding;
}

}  // namespace vern::fuzz
