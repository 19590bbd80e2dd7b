// Fuzz bytes as a small folder tree: a main file (a glTF, or a grammar
// with @primitives) and the files, links and folders it may name.
//
// The input is text in sections, each starting on a line of its own:
//
//   header                the bytes before the first section: the word
//                         "grammar" makes the main file a grammar (main.grm),
//                         else it is a glTF example (main.gltf, or main.glb
//                         when it starts with the "glTF" magic); the word
//                         "outside" allows outside files (--allow-outside-files)
//   @@ main               the main file's bytes (the first such section)
//   @@ file NAME          a file holding the section's bytes
//   @@ repeat NAME COUNT  a file of COUNT bytes (at most 1 MiB): the
//                         section's bytes repeated, or zeros
//   @@ link NAME TARGET   a symbolic link to TARGET (the section's bytes are ignored)
//   @@ dir NAME           a folder
//
// A section's bytes run to the line break before the next "@@ " line. NAME
// and TARGET are percent-decoded ("a%20b.bin" is "a b.bin"). Everywhere,
// in bytes too, $ROOT stands for the run's root folder and $IN for the
// folder the main file is in, both absolute.
//
// The tree is placed in a root folder: the main file in <root>/in/, which
// is the folder it may read from unless outside files are allowed; NAME is
// relative to in/ and may lead out of it with "..", to stay in the root.
// Nothing is placed outside the root: a NAME that leads there, a link whose
// target (taken as written) does, a NAME whose folders on the way are links
// or files, a NAME that exists already (the main file's included) are left
// out. Every byte string is some tree; small changes to the bytes make
// small changes to the tree.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "entries.hpp"

namespace vern::fuzz {

struct FolderTree {
  bool grammar = false;        // main is a grammar whose @primitives is followed; else a glTF example
  bool outside_files = false;  // --allow-outside-files
  std::string main;            // the main file's bytes, $ROOT and $IN as written
  struct Entry {
    enum class Kind { File, Link, Folder } kind = Kind::File;
    std::string name;   // relative to in/, decoded
    std::string bytes;  // a file's bytes, or a link's target
  };
  std::vector<Entry> entries;
};

FolderTree decode_folder_tree(Bytes input);

struct PlacedTree {
  std::filesystem::path main;  // <root>/in/main.gltf, main.glb or main.grm
  std::filesystem::path inside;  // <root>/in: the folder the main file may read from
  // The root and every folder below it that is not in/ or below in/ (links
  // not followed): where a file read would be outside.
  std::vector<std::filesystem::path> outside_folders;
};

// Empties `root` (which must exist) and places the tree in it. The harness
// writes only below `root`, and never through a link.
PlacedTree place_folder_tree(const FolderTree& tree, const std::filesystem::path& root);

}  // namespace vern::fuzz
