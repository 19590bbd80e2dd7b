// Materials for written meshes: the colour each terminal shows.
//
// Both writers (OBJ/MTL and glTF) name and colour materials here, so the
// same scene looks the same in either format. A coloured terminal gets a
// material per distinct colour; an uncoloured one a material per label, with
// a fixed colour for the built-in primitives and a palette colour picked by
// the label's name otherwise, so parts are told apart in any viewer and keep
// their colour from run to run.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "forward/terminal.hpp"

namespace vern {

struct Material {
  std::string name;  // one word, safe in MTL and glTF (graph/label.hpp's label_as_word)
  Rgb colour;        // components in [0, 1], quantised to 8 bits
  friend bool operator==(const Material&, const Material&) = default;
};

// The colour an uncoloured terminal with this label shows.
Rgb label_colour(std::string_view label);

// The material of a terminal: "colour_ff8000" for a coloured one, the
// label as one word for an uncoloured one: a material per label, different
// labels different materials.
Material terminal_material(const Terminal& t, std::string_view label);

// A colour's components as doubles that print as short decimals: each is
// the shortest decimal that reads back to the float (0.8705882f -> 0.8705882,
// not 0.87058824300765991). What both writers put in their files.
std::array<double, 3> colour_components(Rgb colour);

// The materials a scene uses, in order of first use, and which one each
// terminal uses. Built once per write (or as a streaming writer meets the
// terminals); lookups allocate nothing.
class MaterialTable {
 public:
  explicit MaterialTable(const Scene& scene);
  // Empty, for scenes of this many labels, filled by intern().
  explicit MaterialTable(std::size_t labels);

  // Index into materials() of the terminal's material, added when new.
  // Throws vern::Error (Internal) for a label outside `labels`.
  std::uint32_t intern(const Terminal& t, const std::vector<std::string>& labels);

  const std::vector<Material>& materials() const { return materials_; }

  // Index into materials() of a terminal of the scene given to the constructor.
  std::uint32_t index_of(const Terminal& t) const;

 private:
  std::vector<Material> materials_;
  std::map<std::string, std::uint32_t, std::less<>> by_name_;  // each name once
  std::vector<std::uint32_t> by_label_;                         // uncoloured terminals
  std::unordered_map<std::uint32_t, std::uint32_t> by_colour_;  // 0xrrggbb -> index
};

}  // namespace vern
