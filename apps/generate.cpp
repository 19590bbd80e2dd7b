// generate: a grammar in, buildings out (OBJ, glTF or GLB).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

#include "base/atomic_file.hpp"
#include "base/files_read.hpp"
#include "base/number_format.hpp"
#include "base/out_of_memory.hpp"
#include "base/suggest.hpp"
#include "forward/primitive_check.hpp"
#include "forward/primitive_sources.hpp"
#include "forward/shards.hpp"
#include "forward/variants.hpp"
#include "graph/parser.hpp"
#include "io/gltf_writer.hpp"
#include "io/obj_writer.hpp"
#include "support/command_line.hpp"
#include "support/guarded_main.hpp"
#include "support/output_paths.hpp"

namespace fs = std::filesystem;
using namespace vern;

namespace {

CommandLine make_command_line() {
  CommandLine cl("generate", "generate GRAMMAR.grm [-n COUNT] [--seed S] [-o OUT] [options]",
                 "Derives COUNT buildings from a grammar and writes them as OBJ, glTF or GLB.\n"
                 "OUT is a folder (one file per variant: OUT/variant_000.obj, ...) or one file\n"
                 "ending in .obj, .gltf or .glb that holds all variants side by side.");
  cl.add({"--count", "-n", 1, "COUNT", "how many buildings (default 1)"});
  cl.add({"--seed", "-s", 1, "S", "seed of the first building; building i uses S + i (default 1)"});
  cl.add({"--output", "-o", 1, "OUT", "folder or .obj/.gltf/.glb file (default: variants/)"});
  cl.add({"--format", "", 1, "FORMAT", "obj, gltf or glb: the file type in a folder (default obj)"});
  cl.add({"--scope", "", 3, "X Y Z", "start-scope size in metres (default: the grammar's @scope, else 10 10 10)"});
  cl.add({"--start", "", 1, "LABEL", "start rule (default: @start, else the first rule)"});
  cl.add({"--spacing", "", 1, "METRES", "gap between buildings in a one-file layout (default 5)"});
  cl.add({"--primitives", "", 1, "PATH", "primitive meshes: a folder of .obj files or one .obj of named objects"});
  cl.add({"--allow-outside-files", "", 0, "",
          "the grammar's @primitives may name files outside its folder ('..', absolute paths,\n"
          "links out); without it they are refused: a grammar from elsewhere chooses them"});
  cl.add({"--instancing", "", 0, "",
          "glTF/GLB: each part's copies as GPU instances (EXT_mesh_gpu_instancing):\n"
          "smaller, faster files for large scenes. The extension is required (it has no\n"
          "fallback): three.js and Babylon.js read it; Blender 3.4 refuses the file, so\n"
          "leave --instancing out for Blender (docs/clients.md)"});
  cl.add({"--up", "", 1, "y|z",
          "OBJ: the up axis written, declared by a `# up` line (default y, as Blender\n"
          "imports OBJ; glTF is y-up by its specification). The grammar's z is up"});
  cl.add({"--shard", "", 1, "K/N",
          "derive and write only the K-th of N slices of the run's buildings (K = 1..N), each\n"
          "under its own index and at its place in a one-file layout: N shards, run anywhere,\n"
          "write together what the whole run writes"});
  cl.add({"--strict", "", 0, "", "treat warnings (no rule applies, unknown primitive) as errors"});
  cl.add({"--threads", "-j", 1, "N", "derive with N threads (default: all cores; output is the same)"});
  cl.add({"--max-depth", "", 1, "N", "limit on nested rule calls (default 1000)"});
  cl.add({"--max-terminals", "", 1, "N", "limit on terminals per building (default 1000000: a building\nthat large takes ~300 MB while derived, per thread)"});
  cl.add({"--max-operations", "", 1, "N", "limit on operations per building (default 200000000)"});
  cl.add_standard_options();
  cl.set_epilog(
      "examples:\n"
      "  generate data/grammars/garage.grm -n 10 -o garages/        # garages/variant_000.obj ...\n"
      "  generate data/grammars/garage.grm -n 10 -o garages.glb     # all ten in one GLB\n"
      "  generate style.grm --seed 14 -n 1 -o one.obj               # variant 7 of --seed 7\n"
      "  generate city.grm -n 1000 --shard 3/8 -o city/             # city/variant_250 ... variant_374\n"
      "\n"
      "exit codes: 0 success, 2 usage error, 3 bad input (grammar or mesh file),\n"
      "            4 a limit was reached, 5 a file could not be read or written, 70 internal error\n");
  return cl;
}

enum class Format { Obj, Gltf, Glb };

std::optional<Format> format_of_extension(const fs::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".obj") return Format::Obj;
  if (ext == ".gltf") return Format::Gltf;
  if (ext == ".glb") return Format::Glb;
  return std::nullopt;
}

const char* extension(Format f) { return f == Format::Obj ? ".obj" : f == Format::Gltf ? ".gltf" : ".glb"; }

// Stages the scene among the run's outputs, committed together at the end.
void write_scene(const Scene& scene, const PrimitiveLibrary& library, const fs::path& path, Format format,
                 GltfOptions gltf, UpAxis obj_up, OutputFiles& outputs) {
  naming_out_of_memory(path.string(), "while writing the buildings",
                       "write fewer buildings into one file, or a folder of one file per building", [&] {
                         if (format == Format::Obj)
                           write_obj(scene, library, path, outputs, obj_up);
                         else
                           write_gltf(scene, library, path, gltf, outputs);
                       });
}

// One output file of all variants, written as they come: OBJ text goes
// straight to its staged file, glTF waits for its head (GltfStream).
class SceneFileWriter {
 public:
  SceneFileWriter(const fs::path& path, Format format, std::vector<std::string> labels, const PrimitiveLibrary& library,
                  GltfOptions gltf, UpAxis obj_up, OutputFiles& outputs)
      : path_(path), outputs_(outputs) {
    if (format == Format::Obj) {
      check_obj_path(path);
      file_.emplace(outputs.open(path));
      obj_.emplace(std::move(labels), library, mtl_path_for(path).filename().string(),
                   [this](std::string_view piece) { file_->write(piece); }, obj_up);
    } else {
      check_gltf_path(path);
      gltf_.emplace(std::move(labels), library, gltf, path.parent_path(), path.string());
    }
  }

  void add(const Variant& variant) {
    if (obj_) obj_->add(variant);
    else gltf_->add(variant);
  }

  void finish() {
    if (obj_) {
      obj_->flush();
      file_->close();
      outputs_.stage(mtl_path_for(path_), obj_->mtl_text());
    } else {
      write_gltf(*gltf_, path_, outputs_);
    }
  }

 private:
  fs::path path_;
  OutputFiles& outputs_;
  std::optional<OutputFile> file_;
  std::optional<ObjStream> obj_;
  std::optional<GltfStream> gltf_;
};

// The files a run writes for one output file: an OBJ brings its MTL.
std::vector<fs::path> files_written(const fs::path& output, Format format) {
  if (format == Format::Obj) return {output, mtl_path_for(output)};
  return {output};
}

// Whether `name` is a file this run writes into its folder: variant_NNN
// with the format's extension (or an OBJ's .mtl), NNN in the run's slice.
bool is_variant_output(const std::string& name, Slice slice, Format format) {
  const std::string prefix = "variant_";
  const std::size_t dot = name.rfind('.');
  if (!name.starts_with(prefix) || dot == std::string::npos || dot - prefix.size() > 9) return false;
  const std::string ext = name.substr(dot);
  if (ext != extension(format) && !(format == Format::Obj && ext == ".mtl")) return false;
  std::uint32_t index = 0;
  for (std::size_t i = prefix.size(); i < dot; ++i) {
    if (name[i] < '0' || name[i] > '9') return false;
    index = index * 10 + static_cast<std::uint32_t>(name[i] - '0');
  }
  return index >= slice.first && index - slice.first < slice.count && variant_name(index) + ext == name;
}

// A folder this run made for its outputs goes again when the run fails
// (once the outputs' temporary files are gone: declare it before them).
struct MadeFolder {
  fs::path path;
  bool made = false;
  bool done = false;
  ~MadeFolder() {
    std::error_code ec;
    if (made && !done) fs::remove(path, ec);  // only when empty
  }
};

[[noreturn]] void usage(const std::string& message, const std::string& hint = {}) {
  throw Error(ErrorKind::Usage, "generate: error: " + message + (hint.empty() ? "" : "\n  hint: " + hint));
}

int run(int argc, char** argv) {
  const CommandLine cl = make_command_line();
  const std::optional<ParsedCommandLine> parsed = cl.parse_or_answer(argc, argv);
  if (!parsed) return 0;
  const ParsedCommandLine& args = *parsed;
  if (args.positional.size() != 1)
    usage(args.positional.empty() ? "no grammar file given" : "give one grammar file, got " + std::to_string(args.positional.size()),
          "usage: generate GRAMMAR.grm [-n COUNT] [-o OUT]  (generate --help for more)");
  const bool quiet = args.has("--quiet");
  const fs::path grammar_path = args.positional[0];

  VariantOptions options;
  options.count = args.has("--count") ? static_cast<std::uint32_t>(CommandLine::integer(args, "--count", 1, 10'000'000)) : 1;
  options.derive.seed = args.has("--seed") ? static_cast<std::uint64_t>(CommandLine::integer(args, "--seed", 0, (1LL << 53))) : 1;
  // The run's buildings, and of them this shard's (all without --shard).
  const std::uint32_t run_count = options.count;
  Slice slice{0, run_count};
  if (args.has("--shard")) {
    const std::optional<Shard> shard = parse_shard(args.value("--shard"));
    if (!shard)
      usage("--shard '" + args.value("--shard") + "' is not K/N with K from 1 to N",
            "for example --shard 3/8: the third of eight slices of the run's buildings");
    slice = shard_slice(run_count, *shard);
    if (slice.count == 0)
      usage("--shard " + args.value("--shard") + " of " + std::to_string(run_count) + " building" +
                (run_count == 1 ? "" : "s") + " is empty",
            "use at most as many shards as buildings (-n)");
  }
  options.threads = args.has("--threads") ? static_cast<unsigned>(CommandLine::integer(args, "--threads", 1, 256)) : 0;
  options.derive.strict = args.has("--strict");
  if (args.has("--max-depth"))
    options.derive.limits.max_depth = static_cast<std::uint32_t>(CommandLine::integer(args, "--max-depth", 1, 1'000'000));
  if (args.has("--max-terminals"))
    options.derive.limits.max_terminals = static_cast<std::uint64_t>(CommandLine::integer(args, "--max-terminals", 1, 1LL << 40));
  if (args.has("--max-operations"))
    options.derive.limits.max_operations = static_cast<std::uint64_t>(CommandLine::integer(args, "--max-operations", 1, 1LL << 50));
  if (args.has("--scope")) {
    glm::dvec3 size;
    for (int i = 0; i < 3; ++i) {
      size[i] = CommandLine::number(args, "--scope", static_cast<std::size_t>(i));
      if (size[i] < 0) usage("--scope sizes must be >= 0, got " + args.value("--scope", static_cast<std::size_t>(i)),
                             "for example --scope 12 8 9 (metres along x, y, z)");
      // Beyond it the outputs could not hold the coordinates (forward/scope.hpp).
      if (size[i] > kMaxDerivedCoordinate)
        usage("--scope sizes must be at most " + format_number(kMaxDerivedCoordinate) + ", got " +
                  args.value("--scope", static_cast<std::size_t>(i)),
              "for example --scope 12 8 9 (metres along x, y, z)");
    }
    options.derive.size = size;
  }
  const double spacing = args.has("--spacing") ? CommandLine::number(args, "--spacing") : 5.0;
  if (std::abs(spacing) > kMaxDerivedCoordinate)
    usage("--spacing must be between -" + format_number(kMaxDerivedCoordinate) + " and " +
              format_number(kMaxDerivedCoordinate) + ", got " + args.value("--spacing"),
          "the gap between buildings in metres, for example --spacing 5");

  const fs::path output = args.has("--output") ? fs::path(args.value("--output")) : fs::path("variants/");
  std::optional<Format> folder_format;
  if (args.has("--format")) {
    const std::string f = args.value("--format");
    if (f == "obj") folder_format = Format::Obj;
    else if (f == "gltf") folder_format = Format::Gltf;
    else if (f == "glb") folder_format = Format::Glb;
    else usage("unknown --format '" + f + "'", "formats are obj, gltf and glb");
  }
  std::error_code ec;
  if (fs::exists(output, ec) && fs::equivalent(output, grammar_path, ec))
    usage("the output " + output.string() + " is the grammar file itself", "choose another output path");
  const std::optional<Format> file_format = format_of_extension(output);
  const bool one_file = file_format.has_value();
  if (one_file && folder_format && *folder_format != *file_format)
    usage("--format " + args.value("--format") + " contradicts the output file " + output.string(),
          "leave out --format when writing one file: its extension says the format");
  GltfOptions gltf;
  gltf.instancing = args.has("--instancing");
  if (gltf.instancing && (one_file ? *file_format : folder_format.value_or(Format::Obj)) == Format::Obj)
    usage("--instancing applies to glTF output only", "write a .glb or .gltf file, or add --format glb");
  UpAxis obj_up = UpAxis::Y;
  if (args.has("--up")) {
    obj_up = *parse_up_axis(CommandLine::one_of(args, "--up", {"y", "z"}));
    if ((one_file ? *file_format : folder_format.value_or(Format::Obj)) != Format::Obj)
      usage("--up applies to OBJ output only", "glTF is y-up by its specification: leave --up out");
  }
  if (!one_file && output.has_extension() && !fs::is_directory(output, ec))
    usage("cannot tell what to write to '" + output.string() + "'",
          "name a folder (ending in /) or a file ending in .obj, .gltf or .glb");
  // Say so now, naming the path as given, rather than after deriving.
  if (one_file)
    for (const fs::path& file : files_written(output, *file_format))
      check_output_file("generate", file, {grammar_path}, "the grammar file");
  if (!one_file && fs::exists(output, ec) && !fs::is_directory(output, ec))
    throw Error(ErrorKind::Io, output.string() + ": error: cannot write the buildings into this folder: it is a file" +
                                   "\n  hint: name a folder (ending in /) or a file ending in .obj, .gltf or .glb");

  Grammar grammar = read_grammar_file(grammar_path);
  if (args.has("--start")) {
    const std::string label = args.value("--start");
    const auto rule = grammar.find_rule(label);
    if (!rule) {
      std::vector<std::string> names;
      for (const auto& r : grammar.rules) names.push_back(r.label);
      usage("--start names '" + label + "', which is not a rule of " + grammar_path.string(),
            suggest(label, names, "the rules"));
    }
    if (!grammar.rules[*rule].params.empty())
      usage("--start '" + label + "' takes parameters; the start rule takes none",
            "start from a rule without parameters, or add one such as 'plot --> " + label + "(...)'");
    grammar.start_rule = *rule;
  }
  const std::optional<fs::path> primitives_path =
      args.has("--primitives") ? std::optional<fs::path>(args.value("--primitives")) : std::nullopt;
  // The primitive meshes are inputs too: never written over.
  std::vector<fs::path> primitive_inputs;
  if (!grammar.primitives.empty()) primitive_inputs.push_back(grammar_path.parent_path() / grammar.primitives);
  if (primitives_path) primitive_inputs.push_back(*primitives_path);
  if (one_file) {
    for (const fs::path& file : files_written(output, *file_format))
      check_output_file("generate", file, primitive_inputs, "a primitives file");
  } else if (fs::is_directory(output, ec)) {
    // Of what the folder holds, only this run's variant files are written:
    // none may be an input, or a folder.
    const Format format = folder_format.value_or(Format::Obj);
    for (fs::directory_iterator it(output, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (!is_variant_output(name, slice, format)) continue;
      check_output_file("generate", output / name, {grammar_path}, "the grammar file");
      check_output_file("generate", output / name, primitive_inputs, "a primitives file");
    }
    if (ec)
      throw Error(ErrorKind::Io, output.string() + ": error: cannot list the folder: " + ec.message() +
                                     "\n  hint: check the folder's permissions, or choose another output");
  }
  const PrimitiveLibrary library =
      primitives_for(grammar, grammar_path, primitives_path, args.has("--allow-outside-files"));
  // A mesh of a primitives folder is an input too: said before deriving.
  if (one_file)
    for (const fs::path& file : files_written(output, *file_format)) refuse_file_read(file);
  for (const auto& w : unknown_primitive_warnings(grammar, library)) {
    if (options.derive.strict) {
      // The warning's text, reported as the error --strict makes it.
      std::string message = w;
      if (const auto at = message.find(": warning: "); at != std::string::npos) message.replace(at, 11, ": error: ");
      throw Error(ErrorKind::Input, message + "\n  hint: --strict turns this warning into an error; add the primitive "
                                              "with --primitives or @primitives, or run without --strict");
    }
    if (!quiet) std::cerr << w << "\n";
  }

  const auto started = std::chrono::steady_clock::now();
  // This run's buildings: the shard's slice, building i of it derived with
  // the run's seed + slice.first + i and written as building slice.first + i.
  VariantOptions mine = options;
  mine.derive.seed += slice.first;
  mine.count = slice.count;
  const bool show_progress = !quiet && mine.count >= 50 && isatty(STDERR_FILENO);
  if (show_progress) {
    mine.progress = [](std::uint32_t done, std::uint32_t total) {
      if (done % 10 == 0 || done == total) std::fprintf(stderr, "\rderiving %u/%u buildings", done, total);
    };
  }
  // Buildings go to the writer as they are derived, a batch at a time:
  // memory stays flat however many there are (a one-file layout needs
  // only every variant's start size first).
  std::size_t terminals = 0;
  std::vector<std::string> warnings;
  auto note = [&](Derivation& d) {
    terminals += d.terminals.size();
    for (auto& w : d.warnings)
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(std::move(w));
  };
  const std::uint32_t batch = 16 * std::max(1u, options.threads == 0 ? std::thread::hardware_concurrency() : options.threads);
  const std::string deriving = "deriving " + std::to_string(mine.count) + " building" + (mine.count == 1 ? "" : "s");
  const char* deriving_hint = "derive fewer buildings at once (-n), lower --max-terminals, or use fewer threads (-j)";

  // Every file is written before any replaces what was there: a run that
  // fails half way through a folder leaves the earlier run's variants.
  std::string where;
  MadeFolder made{output};
  OutputFiles outputs;
  if (one_file) {
    // Laid out as the whole run is: a shard's buildings stand where they
    // stand in the one run's file.
    const std::vector<glm::dvec3> offsets = layout_offsets(
        naming_out_of_memory(grammar_path.string(), deriving, deriving_hint, [&] { return start_sizes(grammar, options); }),
        spacing);
    std::optional<SceneFileWriter> writer;
    naming_out_of_memory(grammar_path.string(), deriving, deriving_hint, [&] {
      derive_variants_in_order(grammar, mine, batch, [&](std::uint32_t i, Derivation&& d) {
        note(d);
        if (!writer) writer.emplace(output, *file_format, std::move(d.labels), library, gltf, obj_up, outputs);
        writer->add(Variant{variant_name(slice.first + i), offsets[slice.first + i], std::move(d.terminals)});
      });
    });
    naming_out_of_memory(output.string(), "while writing the buildings",
                         "write fewer buildings into one file, or a folder of one file per building",
                         [&] { writer->finish(); });
    where = output.string();
  } else {
    const Format format = folder_format.value_or(Format::Obj);
    made.made = fs::create_directories(output, ec);
    if (ec)
      throw Error(ErrorKind::Io, output.string() + ": error: cannot create the folder: " + ec.message() +
                                     "\n  hint: check that its parent folder exists and is writable, or choose another path");
    naming_out_of_memory(grammar_path.string(), deriving, deriving_hint, [&] {
      derive_variants_in_order(grammar, mine, batch, [&](std::uint32_t i, Derivation&& d) {
        note(d);
        const std::uint32_t index = slice.first + i;
        write_scene(single(std::move(d), index), library, output / (variant_name(index) + extension(format)), format,
                    gltf, obj_up, outputs);
      });
    });
    where = (output / (variant_name(slice.first) + extension(format))).string();
    if (mine.count > 1) where += " ... " + variant_name(slice.first + mine.count - 1) + extension(format);
  }
  if (show_progress) std::fprintf(stderr, "\n");
  if (!quiet)
    for (const auto& w : warnings) std::cerr << w << "\n";
  outputs.commit();
  made.done = true;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!quiet)
    std::fprintf(stderr, "generate: %u building%s, %zu terminals -> %s (%.2f s)\n", mine.count,
                 mine.count == 1 ? "" : "s", terminals, where.c_str(), seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("generate", run, argc, argv); }
