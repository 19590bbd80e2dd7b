#include "io/palette.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>

#include "base/error.hpp"
#include "base/hashing.hpp"
#include "graph/label.hpp"

namespace vern {

namespace {

constexpr Rgb rgb(int r, int g, int b) {
  return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f};
}

// The built-in primitives in the colours of the parts they usually are.
struct Named {
  std::string_view label;
  Rgb colour;
};
constexpr Named kBuiltin[] = {
    {"rect", rgb(222, 206, 180)},                  // plaster
    {"window", rgb(120, 160, 190)},                // glass
    {"door", rgb(130, 88, 60)},                    // wood
    {"roof", rgb(178, 86, 62)},                    // clay tiles
    {"triangle", rgb(178, 86, 62)},
    {"right_angle_triangle", rgb(166, 80, 58)},
    {"hip", rgb(160, 78, 60)},
    {"pyramid", rgb(150, 74, 58)},
    {"corner", rgb(170, 92, 70)},
    {"trough", rgb(140, 70, 56)},
};

// Muted, distinct colours for every other label.
constexpr Rgb kPalette[] = {
    rgb(141, 160, 203), rgb(102, 194, 165), rgb(252, 141, 98), rgb(231, 138, 195),
    rgb(166, 216, 84),  rgb(255, 217, 47),  rgb(229, 196, 148), rgb(179, 179, 179),
    rgb(128, 177, 211), rgb(190, 186, 218), rgb(251, 128, 114), rgb(253, 180, 98),
};

constexpr std::uint32_t kUnused = 0xffffffffu;


int to_byte(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<int>(std::lround(c * 255.0f));
}

std::uint32_t colour_key(const Rgb& c) {
  return static_cast<std::uint32_t>(to_byte(c.red) << 16 | to_byte(c.green) << 8 | to_byte(c.blue));
}

void append_hex(std::string& out, int byte) {
  static constexpr char kDigits[] = "0123456789abcdef";
  out += kDigits[byte >> 4];
  out += kDigits[byte & 15];
}

}  // namespace

Rgb label_colour(std::string_view label) {
  for (const Named& n : kBuiltin) {
    if (n.label == label) return n.colour;
  }
  return kPalette[fnv1a(label) % std::size(kPalette)];
}

Material terminal_material(const Terminal& t, std::string_view label) {
  Material m;
  if (t.coloured) {
    const int r = to_byte(t.colour.red), g = to_byte(t.colour.green), b = to_byte(t.colour.blue);
    m.name = "colour_";
    append_hex(m.name, r);
    append_hex(m.name, g);
    append_hex(m.name, b);
    m.colour = rgb(r, g, b);
    return m;
  }
  // One word per label, and different labels never share one (graph/label.hpp).
  m.name = label_as_word(label);
  m.colour = label_colour(m.name);
  // Kept apart from the colour materials: "colour_..." and every
  // "label_..._colour_..." gain one more "label_", the other names none.
  std::string_view rest = m.name;
  while (rest.starts_with("label_")) rest.remove_prefix(6);
  if (rest.starts_with("colour_")) m.name = "label_" + m.name;
  return m;
}

std::array<double, 3> colour_components(Rgb colour) {
  std::array<double, 3> out{};
  const float in[3] = {colour.red, colour.green, colour.blue};
  for (std::size_t i = 0; i < 3; ++i) {
    char buf[32];
    const auto printed = std::to_chars(buf, buf + sizeof buf, in[i]);
    std::from_chars(buf, printed.ptr, out[i]);
  }
  return out;
}

MaterialTable::MaterialTable(const Scene& scene) : MaterialTable(scene.labels.size()) {
  for (const Variant& v : scene.variants)
    for (const Terminal& t : v.terminals) intern(t, scene.labels);
}

MaterialTable::MaterialTable(std::size_t labels) : by_label_(labels, kUnused) {}

std::uint32_t MaterialTable::intern(const Terminal& t, const std::vector<std::string>& labels) {
  if (t.label >= labels.size() || t.label >= by_label_.size()) {
    throw Error(ErrorKind::Internal, "error: a terminal's label " + std::to_string(t.label) +
                                         " is outside the scene's label table");
  }
  auto named = [&](Material m) {
    const auto [it, fresh] = by_name_.try_emplace(m.name, static_cast<std::uint32_t>(materials_.size()));
    if (fresh) materials_.push_back(std::move(m));
    return it->second;
  };
  if (t.coloured) {
    const std::uint32_t key = colour_key(t.colour);
    const auto it = by_colour_.find(key);
    if (it != by_colour_.end()) return it->second;
    return by_colour_.emplace(key, named(terminal_material(t, {}))).first->second;
  }
  if (by_label_[t.label] == kUnused) by_label_[t.label] = named(terminal_material(t, labels[t.label]));
  return by_label_[t.label];
}

std::uint32_t MaterialTable::index_of(const Terminal& t) const {
  if (t.coloured) {
    const auto it = by_colour_.find(colour_key(t.colour));
    if (it != by_colour_.end()) return it->second;
  } else if (t.label < by_label_.size() && by_label_[t.label] != kUnused) {
    return by_label_[t.label];
  }
  throw Error(ErrorKind::Internal, "error: a terminal that is not in the scene the material table was made for");
}

}  // namespace vern
