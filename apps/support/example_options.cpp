#include "support/example_options.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "base/error.hpp"

namespace vern {

void add_example_options(CommandLine& cl) {
  cl.add({"--max-parts", "", 1, "N", "limit on labelled parts per example (default 10000)"});
  cl.add({"--max-faces", "", 1, "N", "limit on faces per labelled part (default 1000000)"});
  cl.add({"--max-total-faces", "", 1, "N",
          "limit on faces (and vertices) a glTF example's parts place in all, a mesh counting\n"
          "once for each node that places it (default 10000000)"});
  cl.add({"--max-gltf-mib", "", 1, "N",
          "limit on a glTF or GLB file and each file it names, read whole, and on the memory\n"
          "its JSON takes once read (default 256)"});
  cl.add({"--allow-outside-files", "", 0, "",
          "a glTF's URIs may name files outside its folder ('..', absolute paths, links out);\n"
          "without it they are refused: a glTF from elsewhere chooses them"});
  cl.add({"--up", "", 1, "y|z",
          "the up axis of OBJ examples that do not declare one with a `# up` line\n"
          "(default y, as Blender exports OBJ; glTF is always y-up)"});
  cl.add({"--stack", "", 1, "LABEL,LABEL,...",
          "the order overlapping parts are painted in, bottom to top: each keeps what is visible of\n"
          "it (annotations: --stack facade,window,sill). A part inside another needs no order"});
  cl.add({"--buildings", "", 1, "apart|parts|groups|file",
          "how a file of several buildings becomes examples: apart (default), each\n"
          "building standing apart from the others, never dividing a top-level glTF\n"
          "node or OBJ `g` group; parts, the same, dividing groups too; groups, each\n"
          "group; file, the whole file one example"});
}

ExampleLimits example_limits(const ParsedCommandLine& args) {
  ExampleLimits limits;
  if (args.has("--max-parts"))
    limits.max_parts = static_cast<std::size_t>(CommandLine::integer(args, "--max-parts", 1, 100'000'000));
  if (args.has("--max-faces"))
    limits.max_faces = static_cast<std::size_t>(CommandLine::integer(args, "--max-faces", 1, 1'000'000'000));
  if (args.has("--max-total-faces")) {
    limits.max_total_faces =
        static_cast<std::size_t>(CommandLine::integer(args, "--max-total-faces", 1, 1'000'000'000'000));
  }
  // tinygltf reads lengths as 32-bit numbers: below 4 GiB.
  if (args.has("--max-gltf-mib"))
    limits.gltf.max_bytes = static_cast<std::uint64_t>(CommandLine::integer(args, "--max-gltf-mib", 1, 4095)) << 20;
  limits.gltf.outside_folder = args.has("--allow-outside-files");
  if (args.has("--up")) limits.obj_up = *parse_up_axis(CommandLine::one_of(args, "--up", {"y", "z"}));
  return limits;
}

vernacular::ReadOptions read_options(const ParsedCommandLine& args) {
  const ExampleLimits limits = example_limits(args);
  vernacular::ReadOptions o;
  o.max_parts = limits.max_parts;
  o.max_faces = limits.max_faces;
  o.max_total_faces = limits.max_total_faces;
  o.max_file_bytes = limits.gltf.max_bytes;
  o.outside_files = limits.gltf.outside_folder;
  o.obj_up = limits.obj_up == UpAxis::Z ? vernacular::UpAxis::Z : vernacular::UpAxis::Y;
  switch (buildings_mode(args)) {
    case BuildingsMode::Apart: o.buildings = vernacular::Buildings::Apart; break;
    case BuildingsMode::Parts: o.buildings = vernacular::Buildings::Parts; break;
    case BuildingsMode::Groups: o.buildings = vernacular::Buildings::Groups; break;
    case BuildingsMode::File: o.buildings = vernacular::Buildings::File; break;
  }
  return o;
}

std::vector<std::string> stack_order(const ParsedCommandLine& args) {
  std::vector<std::string> labels;
  if (!args.has("--stack")) return labels;
  const std::string text = args.value("--stack");
  std::size_t from = 0;
  while (true) {
    const std::size_t comma = text.find(',', from);
    std::string label = text.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    if (label.empty() || std::find(labels.begin(), labels.end(), label) != labels.end())
      throw Error(ErrorKind::Usage, args.program + ": error: --stack '" + text + "' " +
                                        (label.empty() ? "has an empty label" : "lists '" + label + "' twice") +
                                        "\n  hint: labels bottom to top, separated by commas: --stack wall,window,sill");
    labels.push_back(std::move(label));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return labels;
}

BuildingsMode buildings_mode(const ParsedCommandLine& args) {
  if (!args.has("--buildings")) return BuildingsMode::Apart;
  const std::string mode = CommandLine::one_of(args, "--buildings", {"apart", "parts", "groups", "file"});
  return mode == "parts"    ? BuildingsMode::Parts
         : mode == "groups" ? BuildingsMode::Groups
         : mode == "file"   ? BuildingsMode::File
                            : BuildingsMode::Apart;
}

void print_notes(const std::string& program, const std::vector<std::string>& notes) {
  constexpr std::size_t kShown = 3;
  for (std::size_t k = 0; k < notes.size() && k < kShown; ++k) std::fprintf(stderr, "%s: %s\n", program.c_str(), notes[k].c_str());
  if (notes.size() > kShown)
    std::fprintf(stderr, "%s: note: %zu more files alike\n", program.c_str(), notes.size() - kShown);
}

}  // namespace vern
