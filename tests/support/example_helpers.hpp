// Helpers for the inference tests: examples built by hand or from
// derivations, and comparing sets of labelled boxes. (vern::LabelledBox is
// spelled out: derive_helpers.hpp has a vern::test::LabelledBox of its own.)
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "forward/derive.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/load/example.hpp"

namespace vern::test {

// A part as a file would give it: object "label.<index>" on line index + 1.
inline vern::LabelledBox part(const std::string& label, glm::dvec3 min, glm::dvec3 max, std::uint32_t index = 0) {
  vern::LabelledBox b;
  b.label = label;
  b.min = min;
  b.max = max;
  b.object = label + "." + std::to_string(index);
  b.line = index + 1;
  b.mesh = index;
  return b;
}

// Numbers each part's object name and line by its position.
inline std::vector<vern::LabelledBox> numbered(std::vector<vern::LabelledBox> boxes) {
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    boxes[i].object = boxes[i].label + "." + std::to_string(i);
    boxes[i].line = i + 1;
    boxes[i].mesh = i;
  }
  return boxes;
}

// An example of these boxes (without meshes), its bounds computed.
inline Example example_of(std::vector<vern::LabelledBox> boxes, std::string source = "test.obj") {
  Example ex;
  ex.source = std::move(source);
  ex.boxes = std::move(boxes);
  update_bounds(ex);
  return ex;
}

// An example whose cut tree is `slabs` + 1 deep: each part peels a slab
// 1 m thick off the rest, along x, y and z in turn (labels p0 and p1 by
// turns); the core left is the last part.
inline std::vector<vern::LabelledBox> peeled_layout(int slabs) {
  glm::dvec3 lo(0), hi(static_cast<double>((slabs + 2) / 3 + 1));
  std::vector<vern::LabelledBox> boxes;
  for (int i = 0; i < slabs; ++i) {
    const int axis = i % 3;
    glm::dvec3 top = hi;
    top[axis] = lo[axis] + 1;
    boxes.push_back(part(i % 2 ? "p1" : "p0", lo, top));
    lo[axis] += 1;
  }
  boxes.push_back(part("core", lo, hi));
  return numbered(std::move(boxes));
}

// Pinwheels nested `levels` deep in a square `size` across, `height` high:
// four arms (a to d) turn about a centre a third as wide, which is the
// next pinwheel, or at the last level a part e. No straight cut separates
// a pinwheel's arms.
inline std::vector<vern::LabelledBox> nested_pinwheel(int levels, double size, double height) {
  std::vector<vern::LabelledBox> boxes;
  double x = 0, y = 0, s = size;
  for (int level = 0; level < levels; ++level) {
    const double t = s / 3;
    boxes.push_back(part("a", {x, y, 0}, {x + 2 * t, y + t, height}));
    boxes.push_back(part("b", {x + 2 * t, y, 0}, {x + s, y + 2 * t, height}));
    boxes.push_back(part("c", {x + t, y + 2 * t, 0}, {x + s, y + s, height}));
    boxes.push_back(part("d", {x, y + t, 0}, {x + t, y + s, height}));
    x += t, y += t, s = t;
  }
  boxes.push_back(part("e", {x, y, 0}, {x + s, y + s, height}));
  return numbered(std::move(boxes));
}

// Boxes as an OBJ file's text, z up, every coordinate to the last bit:
// one object per box, named by its label; the whole turned by `angle`
// radians about the z axis when it is not 0 (a house standing at an angle).
inline std::string boxes_obj(const std::vector<vern::LabelledBox>& boxes, double angle = 0) {
  std::ostringstream text;
  text.precision(17);
  text << "# up z\n";
  const double c = std::cos(angle), s = std::sin(angle);
  for (const vern::LabelledBox& b : boxes) {
    text << "o " << b.label << "\n";
    for (int i = 0; i < 8; ++i) {
      const double x = (i & 1) ? b.max.x : b.min.x, y = (i & 2) ? b.max.y : b.min.y;
      if (angle == 0) text << "v " << x << " " << y << " ";
      else text << "v " << c * x - s * y << " " << s * x + c * y << " ";
      text << ((i & 4) ? b.max.z : b.min.z) << "\n";
    }
    // Corners -8..-1 are the vertices just written.
    text << "f -8 -6 -5 -7\nf -4 -3 -1 -2\nf -8 -7 -3 -4\nf -6 -2 -1 -5\nf -8 -4 -2 -6\nf -7 -5 -1 -3\n";
  }
  return text.str();
}

// The terminals of a derivation as the parts of an example.
inline std::vector<vern::LabelledBox> derived_parts(const Derivation& d) {
  std::vector<vern::LabelledBox> out;
  out.reserve(d.terminals.size());
  for (std::uint32_t i = 0; i < d.terminals.size(); ++i) {
    const Bounds b = world_bounds(d.terminals[i].scope);
    out.push_back(part(d.labels[d.terminals[i].label], b.min, b.max, i));
  }
  return out;
}

// The parts of the building g derives with this seed (a variant).
inline std::vector<vern::LabelledBox> derived_parts(const Grammar& g, std::uint64_t seed) {
  DeriveOptions o;
  o.seed = seed;
  return derived_parts(derive(g, o));
}

// The examples a grammar derives with seeds 1 to k, as inference's
// round trips take them.
inline std::vector<Example> derived_examples(const Grammar& g, std::uint64_t k) {
  std::vector<Example> out;
  for (std::uint64_t seed = 1; seed <= k; ++seed) out.push_back(example_of(derived_parts(g, seed)));
  return out;
}

// Precision, asserted: every variant the inferred grammar derives with the
// seeds first..last, but at most `misses`, is a building the source
// derives on its extent. Where more are not, the first is named with
// check's reason, and the inferred grammar is shown. (A size drawn from a
// range widens the range its examples show, as an estimate of the
// source's: a variant at its edge may reach past the source's own.)
inline ::testing::AssertionResult source_derives_variants(const Grammar& source, const Grammar& inferred,
                                                          std::uint64_t first, std::uint64_t last,
                                                          std::size_t misses = 0) {
  std::size_t missed = 0;
  std::string first_miss;
  for (std::uint64_t seed = first; seed <= last; ++seed) {
    const Example variant = example_of(derived_parts(inferred, seed));
    const CheckResult r = check_example(source, variant.boxes, example_size(variant));
    if (r.derivable) continue;
    if (missed++ == 0) first_miss = "seed " + std::to_string(seed) + ": " + r.mismatch;
  }
  if (missed <= misses) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << missed << " of " << (last - first + 1)
                                       << " variants are not the source's; " << first_miss << "\n"
                                       << write_grammar(inferred);
}

// Whether g derives every example, on its own extent; else the first it
// does not, with check's reason and the grammar.
inline ::testing::AssertionResult derives_every_example(const Grammar& g, const std::vector<Example>& examples) {
  for (const Example& e : examples) {
    const CheckResult r = check_example(g, e.boxes, example_size(e));
    if (!r.derivable) return ::testing::AssertionFailure() << e.source << ": " << r.mismatch << "\n" << write_grammar(g);
  }
  return ::testing::AssertionSuccess();
}

inline std::vector<vern::LabelledBox> translated(std::vector<vern::LabelledBox> boxes, glm::dvec3 by) {
  for (vern::LabelledBox& b : boxes) {
    b.min += by;
    b.max += by;
  }
  return boxes;
}

inline std::string describe(const vern::LabelledBox& b) {
  std::ostringstream s;
  s.precision(17);
  s << b.label << " [" << b.min.x << ", " << b.min.y << ", " << b.min.z << "] - [" << b.max.x << ", " << b.max.y
    << ", " << b.max.z << "]";
  return s.str();
}

// The two multisets of labelled boxes are equal, coordinates within eps.
// Matching rather than sorting: float noise must not reorder equal keys.
inline ::testing::AssertionResult same_boxes(const std::vector<vern::LabelledBox>& expected,
                                             const std::vector<vern::LabelledBox>& actual, double eps) {
  if (expected.size() != actual.size()) {
    return ::testing::AssertionFailure() << "expected " << expected.size() << " boxes, got " << actual.size();
  }
  std::map<std::string, std::vector<const vern::LabelledBox*>> by_label;
  for (const vern::LabelledBox& b : actual) by_label[b.label].push_back(&b);
  for (auto& [label, list] : by_label) {
    std::sort(list.begin(), list.end(), [](const vern::LabelledBox* p, const vern::LabelledBox* q) { return p->min.x < q->min.x; });
  }
  std::map<const vern::LabelledBox*, bool> used;
  for (const vern::LabelledBox& e : expected) {
    const auto found = by_label.find(e.label);
    if (found == by_label.end()) return ::testing::AssertionFailure() << "no box labelled " << e.label;
    const auto& list = found->second;
    auto it = std::lower_bound(list.begin(), list.end(), e.min.x - eps,
                               [](const vern::LabelledBox* p, double x) { return p->min.x < x; });
    bool matched = false;
    for (; it != list.end() && (*it)->min.x <= e.min.x + eps; ++it) {
      const vern::LabelledBox& a = **it;
      if (used[&a]) continue;
      bool close = true;
      for (int i = 0; i < 3; ++i) {
        close = close && std::abs(a.min[i] - e.min[i]) <= eps && std::abs(a.max[i] - e.max[i]) <= eps;
      }
      if (close) {
        used[&a] = true;
        matched = true;
        break;
      }
    }
    if (!matched) return ::testing::AssertionFailure() << "no match within " << eps << " for " << describe(e);
  }
  return ::testing::AssertionSuccess();
}

}  // namespace vern::test
