#include "inverse/load/examples_of_files.hpp"

#include <cstdio>
#include <numbers>
#include <optional>

#include "inverse/load/building_angle.hpp"

namespace vern {

std::vector<Example> examples_of_files(std::vector<Example> files, BuildingsMode mode, double tolerance,
                                       std::vector<std::string>& notes) {
  std::vector<Example> out;
  out.reserve(files.size());
  for (Example& file : files) {
    const double own = example_tolerance(file, tolerance);
    SceneBuildings scene = scene_buildings(std::move(file), mode, own);
    if (!scene.note.empty()) notes.push_back(std::move(scene.note));
    for (Example& b : scene.buildings) {
      // A building standing at an angle is read in its own frame.
      if (const std::optional<double> angle = building_angle(b, example_tolerance(b, tolerance))) {
        char degrees[32];
        std::snprintf(degrees, sizeof degrees, "%.4g", *angle * 180 / std::numbers::pi);
        notes.push_back("note: " + b.source + " stands turned " + degrees +
                        " degrees about z: read turned back, its parts along x and y\n  hint: the grammar describes "
                        "the building in its own frame; where it stands, and at what angle, is the scene's");
        b = turned_back(b, *angle);
      }
      out.push_back(std::move(b));
    }
  }
  return out;
}

}  // namespace vern
