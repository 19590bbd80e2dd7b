#include "inverse/load/example.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <unordered_set>
#include <utility>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "base/out_of_memory.hpp"
#include "inverse/load/gltf_example.hpp"
#include "inverse/load/obj_example.hpp"

namespace vern {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

enum class Format { Obj, Glb, Gltf, Other };

Format format_of(const fs::path& path) {
  const std::string ext = lower(path.extension().string());
  if (ext == ".obj") return Format::Obj;
  if (ext == ".glb") return Format::Glb;
  if (ext == ".gltf") return Format::Gltf;
  return Format::Other;
}

[[noreturn]] void not_an_example(const fs::path& path) {
  fail(ErrorKind::Usage, path.string(), {},
       "is not an example file: examples are labelled .obj, .glb or .gltf files",
       "export the building as OBJ (one object per part) or glTF (one named node per part)");
}

}  // namespace

void update_bounds(Example& example) {
  if (example.boxes.empty()) {
    example.min = example.max = glm::dvec3(0.0);
    return;
  }
  example.min = example.boxes.front().min;
  example.max = example.boxes.front().max;
  for (const LabelledBox& b : example.boxes) {
    example.min = glm::min(example.min, b.min);
    example.max = glm::max(example.max, b.max);
  }
}

glm::dvec3 example_size(const Example& example) { return example.max - example.min; }

double default_tolerance(const Example& example) {
  return std::max(default_tolerance(example.min, example.max), example.file_tolerance);
}

double default_tolerance(glm::dvec3 min, glm::dvec3 max) {
  const glm::dvec3 size = max - min;
  const glm::dvec3 far = glm::max(glm::abs(min), glm::abs(max));
  return 1e-6 * std::max({size.x, size.y, size.z, far.x, far.y, far.z});
}

double example_tolerance(const Example& example, double given) {
  return given > 0 ? given : default_tolerance(example);
}

std::string describe_object(const LabelledBox& box) {
  std::string text = "'" + box.object + "'";
  if (box.line != 0) text += " (line " + std::to_string(box.line) + ")";
  return text;
}

namespace {

// A size as messages state it: four digits ("0.002001", "2001").
std::string approx(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// The example's default tolerance is a millionth of its span or of its
// farthest coordinate from the origin (default_tolerance): the part that
// sets it, said as "its span, 2001 m from 'wall' (line 2) to 'post' (line 32)".
std::string what_sets_the_tolerance(const Example& ex) {
  const glm::dvec3 extent = example_size(ex);
  const glm::dvec3 far = glm::max(glm::abs(ex.min), glm::abs(ex.max));
  const int span_axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const int far_axis = far.x >= far.y && far.x >= far.z ? 0 : far.y >= far.z ? 1 : 2;
  auto reaching = [&](int axis, bool low) {
    for (const LabelledBox& b : ex.boxes)
      if ((low ? b.min[axis] : b.max[axis]) == (low ? ex.min[axis] : ex.max[axis])) return describe_object(b);
    return std::string();
  };
  if (far[far_axis] > extent[span_axis]) {
    const bool low = std::abs(ex.min[far_axis]) > std::abs(ex.max[far_axis]);
    return "its farthest coordinate from the origin, " + approx(far[far_axis]) + " m, in " + reaching(far_axis, low);
  }
  return "its span, " + approx(extent[span_axis]) + " m from " + reaching(span_axis, true) + " to " +
         reaching(span_axis, false);
}

// Coordinates are metres. Below a micron across, an example is no building
// but a unit mistake, and its tolerance (a millionth of that) nears the
// end of what doubles hold: ratios and sums of its sizes would be noise.
constexpr double kSmallestExample = 1e-6;

}  // namespace

void refuse_points(const Example& ex, double given_tolerance) {
  const double tolerance = example_tolerance(ex, given_tolerance);
  for (const LabelledBox& b : ex.boxes) {
    const glm::dvec3 size = b.max - b.min;
    const double largest = std::max({size.x, size.y, size.z});
    if (largest > tolerance) continue;
    const SourceLoc where{b.line, b.line != 0 ? 1u : 0u};
    if (largest == 0)
      fail(ErrorKind::Input, ex.source, where,
           "object " + describe_object(b) + " is a single point: its vertices have no extent on any axis",
           "delete the object or give it its real geometry");
    const std::string small = "object " + describe_object(b) + " is " + approx(largest) + " m across at most, ";
    if (given_tolerance > 0)
      fail(ErrorKind::Input, ex.source, where,
           small + "no larger than --tolerance " + approx(tolerance) + ": too small to tell from a point",
           "give the part its real size, or a smaller --tolerance");
    // A part far away (another building, a stray vertex) makes a small part
    // too small to tell: say which part sets the tolerance.
    fail(ErrorKind::Input, ex.source, where,
         small + "no larger than the example's tolerance, " + approx(tolerance) + " m: too small to tell from a " +
             "point (the tolerance is a millionth of " + what_sets_the_tolerance(ex) + ")",
         "check that the far part belongs to this building and the model sits near the origin; else give the part "
         "its real size, or a smaller --tolerance");
  }
  const glm::dvec3 extent = example_size(ex);
  const double across = std::max({extent.x, extent.y, extent.z});
  if (!ex.boxes.empty() && across < kSmallestExample)
    fail(ErrorKind::Input, ex.source, {},
         "the example is " + approx(across) + " m across: too small for a building in metres",
         "scale the model to metres (coordinates are read as metres)");
}

Example load_example(const fs::path& path, const ExampleLimits& limits, unsigned threads) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {  // or it cannot be told: a link that leads to itself
    fail(ErrorKind::Io, path.string(), {}, ec ? "cannot read: " + ec.message() : "no such file",
         "check the path of the example");
  }
  if (fs::is_directory(path, ec)) {
    fail(ErrorKind::Io, path.string(), {}, "is a folder, not an example file",
         "name an .obj, .glb or .gltf file (the command line accepts folders)");
  }
  require_regular_file(path);
  Example ex = naming_out_of_memory(
      path.string(), "while reading this example",
      "read fewer or smaller examples at once (one example's parts: --max-parts), or free memory", [&] {
        switch (format_of(path)) {
          case Format::Obj: return load_obj_example(path, limits, threads != 1);
          case Format::Glb: return load_gltf_example(path, true, limits);
          case Format::Gltf: return load_gltf_example(path, false, limits);
          case Format::Other: break;
        }
        not_an_example(path);
      });
  update_bounds(ex);

  refuse_points(ex, limits.tolerance);
  return ex;
}

std::vector<fs::path> example_files(const std::vector<std::string>& args) {
  std::vector<fs::path> files;
  for (const std::string& arg : args) {
    const fs::path path(arg);
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      fail(ErrorKind::Io, arg, {}, ec ? "cannot read: " + ec.message() : "no such file or folder",
           "name example files (.obj, .glb, .gltf) or folders of them");
    }
    if (!fs::is_directory(path, ec)) {
      if (format_of(path) == Format::Other) not_an_example(path);
      files.push_back(path);
      continue;
    }
    const std::vector<fs::path> inside = regular_files_in(
        path, [](const fs::path& p) { return format_of(p) != Format::Other; }, "an example file");
    if (inside.empty()) {
      fail(ErrorKind::Io, arg, {}, "the folder holds no example files (.obj, .glb or .gltf)",
           "put the labelled examples there, or name the files themselves");
    }
    files.insert(files.end(), inside.begin(), inside.end());
  }
  return files;
}

}  // namespace vern
