// read_examples and write_buildings: the example loader and the scene
// writers behind the public API.
#include "vernacular/io.hpp"

#include <cmath>

#include "api/api_data.hpp"
#include "api/buildings.hpp"
#include "base/error.hpp"
#include "base/parallel_for.hpp"
#include "graph/label.hpp"
#include "forward/primitive_sources.hpp"
#include "forward/variants.hpp"
#include "inverse/load/examples_of_files.hpp"
#include "io/gltf_writer.hpp"
#include "io/obj_writer.hpp"

namespace fs = std::filesystem;

namespace vernacular {

const std::string& Example::source() const { return data_->example.source; }
const std::vector<ExamplePart>& Example::parts() const { return data_->parts; }
const std::vector<std::string>& Example::notes() const { return data_->notes; }
Example::Example(std::shared_ptr<const detail::ExampleData> data) : data_(std::move(data)) {}

Example Example::from_parts(std::vector<ExamplePart> parts, std::string source) {
  return detail::guarded([&] {
    if (parts.empty())
      vern::fail(vern::ErrorKind::Input, source, {}, "has no parts", "give the example at least one labelled box");
    vern::Example e;
    e.source = source;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      ExamplePart& p = parts[i];
      const std::string name = p.object.empty() ? p.label + "." + std::to_string(i) : p.object;
      vern::LabelledBox b;
      b.label = vern::read_label(p.label, vern::NameOf::Part, source, {}, "part " + std::to_string(i) + "'s label");
      for (int a = 0; a < 3; ++a) {
        const auto k = static_cast<std::size_t>(a);
        if (!std::isfinite(p.min[k]) || !std::isfinite(p.max[k]) || p.min[k] > p.max[k])
          vern::fail(vern::ErrorKind::Input, source, {},
                     "part " + std::to_string(i) + " ('" + name + "') is no box: min must be <= max on every axis, finite",
                     "give each part its lowest and highest corner");
        b.min[a] = p.min[k];
        b.max[a] = p.max[k];
      }
      b.object = name;
      p.object = name;
      b.group = static_cast<std::uint32_t>(i);
      e.boxes.push_back(std::move(b));
    }
    vern::update_bounds(e);
    vern::refuse_points(e, 0);
    auto data = std::make_shared<detail::ExampleData>();
    data->example = std::move(e);
    data->parts = std::move(parts);
    return Example(std::move(data));
  });
}

namespace {

vern::BuildingsMode mode_of(Buildings b) {
  switch (b) {
    case Buildings::Apart: return vern::BuildingsMode::Apart;
    case Buildings::Parts: return vern::BuildingsMode::Parts;
    case Buildings::Groups: return vern::BuildingsMode::Groups;
    case Buildings::File: return vern::BuildingsMode::File;
  }
  return vern::BuildingsMode::Apart;
}

Example example_of(vern::Example e, std::vector<std::string> notes) {
  auto data = std::make_shared<detail::ExampleData>();
  data->parts.reserve(e.boxes.size());
  for (const vern::LabelledBox& b : e.boxes)
    data->parts.push_back({b.label, b.object, {b.min.x, b.min.y, b.min.z}, {b.max.x, b.max.y, b.max.z}});
  data->example = std::move(e);
  data->notes = std::move(notes);
  return Example(std::move(data));
}

}  // namespace

std::vector<Example> read_examples(const std::vector<fs::path>& paths, const ReadOptions& options) {
  return detail::guarded([&] {
    if (paths.empty()) vern::fail(vern::ErrorKind::Usage, "", {}, "no examples given", "name .obj, .gltf or .glb files, or folders of them");
    if (!(options.tolerance >= 0)) vern::fail(vern::ErrorKind::Usage, "", {}, "the tolerance must be >= 0", "0 takes each file's own precision");
    const std::vector<fs::path> files = example_files(paths);
    vern::ExampleLimits limits;
    limits.max_parts = options.max_parts;
    limits.max_faces = options.max_faces;
    limits.max_total_faces = options.max_total_faces;
    limits.gltf.max_bytes = options.max_file_bytes;
    limits.gltf.outside_folder = options.outside_files;
    limits.obj_up = options.obj_up == UpAxis::Z ? vern::UpAxis::Z : vern::UpAxis::Y;
    limits.tolerance = options.tolerance;
    // Read in parallel; the first unreadable file (in the order given) is
    // the one reported (parallel_for), whatever the thread count.
    std::vector<vern::Example> loaded(files.size());
    vern::parallel_for(files.size(), 0, [&](std::size_t i) { loaded[i] = vern::load_example(files[i], limits); });
    std::vector<Example> out;
    for (vern::Example& file : loaded) {
      std::vector<vern::Example> one;
      one.push_back(std::move(file));
      std::vector<std::string> notes;
      std::vector<vern::Example> buildings =
          vern::examples_of_files(std::move(one), mode_of(options.buildings), options.tolerance, notes);
      for (vern::Example& b : buildings) out.push_back(example_of(std::move(b), notes));
    }
    return out;
  });
}

std::vector<fs::path> example_files(const std::vector<fs::path>& paths) {
  return detail::guarded([&] {
    std::vector<std::string> named;
    for (const fs::path& p : paths) named.push_back(p.string());
    return vern::example_files(named);
  });
}

void write_buildings(const std::vector<Building>& buildings, const Grammar& grammar, const fs::path& file,
                     double spacing) {
  detail::guarded([&] {
    const std::string ext = file.extension().string();
    if (ext != ".obj" && ext != ".glb" && ext != ".gltf")
      vern::fail(vern::ErrorKind::Usage, file.string(), {}, "cannot write buildings as '" + ext + "'",
                 "name a .obj, .glb or .gltf file");
    const detail::GrammarData& g = grammar.data();
    // An inferred grammar's own meshes; a read one's @primitives, only
    // from its own folder or below it.
    const vern::PrimitiveLibrary library =
        g.meshes ? *g.meshes
                 : vern::primitives_for(g.grammar, g.file.empty() ? g.folder / "grammar" : g.file, std::nullopt, false);
    const vern::Scene scene = vern::lay_out(detail::derivations_of(buildings), spacing);
    if (ext == ".obj")
      vern::write_obj(scene, library, file);
    else
      vern::write_gltf(scene, library, file);
  });
}

}  // namespace vernacular
